#pragma once
// Step 2 of tunnel detection: per wall class, the Gaussian statistics of the plane normals and
// the rejection of outlier planes by a histogram of their angular deviations from the mean.
#include <Eigen/Core>
#include <vector>

namespace tunnelmap {

struct WeightedNormal {
  Eigen::Vector3d normal;  // unit
  double weight = 1.0;     // point count of the plane (>0)
};

struct NormalClassStats {
  bool valid = false;                // at least one inlier
  Eigen::Vector3d mean = Eigen::Vector3d::Zero();  // unit, weighted mean of the inliers
  double sd_deg = 0.0;               // RMS deviation of the inliers from `mean`
  std::vector<bool> inlier;          // per input normal
};

// Seeds the mean at the densest direction (robust to a large fraction of outliers), then
// iterates: histogram of deviations (bins of `bin_deg`), keep the bins from 0 up to the first
// empty bin after the heaviest one, never beyond `max_deg`; recompute the weighted mean.
NormalClassStats reject_normal_outliers(const std::vector<WeightedNormal>& normals, double bin_deg,
                                        double max_deg);
// The buffers of the histogram test, kept by the caller (TunnelScratch).
struct OutlierScratch {
  std::vector<bool> use, in;  // the seed's neighbours; the current inliers
  std::vector<double> weight;  // per histogram bin
  std::vector<int> bin_of;     // per normal
};
// The same, written into `out`: reuses out.inlier's buffer and those of `scratch`, so a detector
// calling it every frame with the same `out` and `scratch` allocates nothing in the steady state.
void reject_normal_outliers(const std::vector<WeightedNormal>& normals, double bin_deg,
                            double max_deg, NormalClassStats& out, OutlierScratch& scratch);
// The same with scratch of its own: allocates it on every call.
void reject_normal_outliers(const std::vector<WeightedNormal>& normals, double bin_deg,
                            double max_deg, NormalClassStats& out);

double angle_deg(const Eigen::Vector3d& a, const Eigen::Vector3d& b);  // unit vectors

}  // namespace tunnelmap
