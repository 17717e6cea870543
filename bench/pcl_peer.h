#pragma once
// PCL peer: IntegralImageNormalEstimation + OrganizedMultiPlaneSegmentation (PCL 1.13, Debian).
// PCL types stay inside pcl_peer.cpp (the one translation unit that includes PCL's feature and
// segmentation headers) so the rest of the benchmark compiles quickly.
#include <memory>

#include "core/frame/organized_cloud.h"
#include "core/planes/plane_segment.h"

namespace tunnelmap::bench {

struct PclPeerSettings {
  bool covariance_normals = false;  // COVARIANCE_MATRIX instead of AVERAGE_3D_GRADIENT
  float max_depth_change = 0.02f;   // IINE setMaxDepthChangeFactor
  float smoothing_px = 10.0f;       // IINE setNormalSmoothingSize
  double angle_deg = 4.0;           // OMPS setAngularThreshold
  double distance_m = 0.02;         // OMPS setDistanceThreshold (PCL scales it by z^2)
  unsigned min_inliers = 300;       // OMPS setMinInliers
  double max_curvature = 0.001;     // OMPS setMaximumCurvature
};

// The settings tuned for these frames (see pcl_peer.cpp for why each value).
PclPeerSettings tuned_pcl_settings();

class PclPeer {
 public:
  explicit PclPeer(const PclPeerSettings& settings);
  ~PclPeer();
  PclPeer(const PclPeer&) = delete;
  PclPeer& operator=(const PclPeer&) = delete;

  void set_cloud(const OrganizedCloud& cloud);  // copies the points (not timed)
  void estimate_normals();
  void segment();  // needs estimate_normals() first

  int plane_count() const;
  // Normals of the last estimate_normals() (NaN where none), for normal-quality counters.
  std::vector<Eigen::Vector3f> normals() const;
  // Label image (plane i -> id i+1) and one PlaneSegment per plane, for scoring.
  PlaneSegments segments() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace tunnelmap::bench
