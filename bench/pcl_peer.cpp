#include "bench/pcl_peer.h"

#include <pcl/ModelCoefficients.h>
#include <pcl/PointIndices.h>
#include <pcl/features/integral_image_normal.h>
#include <pcl/point_cloud.h>
#include <pcl/point_types.h>
#include <pcl/segmentation/organized_multi_plane_segmentation.h>

#include <cmath>

namespace tunnelmap::bench {

// Why these values (fair to PCL on 640x480 PrimeSense-class frames at 0.5-3 m; chosen by a
// sweep on the two simulated frames, best recall at full precision, see docs/performance.md):
// - Normals: AVERAGE_3D_GRADIENT, the fastest IINE method, with the window of our own normals
//   (10 px) and depth-change factor 0.02 (PCL's tutorial value). COVARIANCE_MATRIX, factor
//   0.05 and window 20 were slower and did not raise recall.
// - Angular threshold 8 deg, not PG&C's lambda = 4 deg: PCL compares the normals of
//   neighbouring pixels (PG&C compares a pixel with the region's mean normal), and IINE's
//   normals are noisier on these frames (median error 6-10 deg on the simulated ones, window
//   shrunk next to holes), so at 4 deg planes shatter below the inlier minimum: recall on
//   sim_lab 0.45 at 4 deg, 0.55 at 8 deg, 0.55 at 12 deg, precision 1.0 throughout.
// - Distance threshold 20 mm: PCL compares the plane offsets (p.n) of neighbouring pixels and
//   multiplies the threshold by z^2, so 20 mm at 1 m (80 mm at 2 m) covers PG&C's epsilon =
//   15 mm plus the sensor's depth-squared noise growth; 30-50 mm merged walls (lower recall).
// - Min inliers 300: PG&C's min area 0.004 m^2 seen at ~2 m by a 575 px lens
//   (0.004 * (575 / 2)^2 ~ 330 px; at 1 m it is ~1300 px, so this is lenient for PCL).
// - Max curvature 0.01 instead of PCL's 0.001: with 0.001 OMPS drops true tunnel plates
//   (lambda_min / trace of a noisy plate at 2-3 m is ~1e-3): sim_lab recall 0.27 -> 0.45.
PclPeerSettings tuned_pcl_settings() {
  PclPeerSettings s;
  s.covariance_normals = false;
  s.max_depth_change = 0.02f;
  s.smoothing_px = 10.0f;
  s.angle_deg = 8.0;
  s.distance_m = 0.02;
  s.min_inliers = 300;
  s.max_curvature = 0.01;
  return s;
}

struct PclPeer::Impl {
  PclPeerSettings settings;
  pcl::PointCloud<pcl::PointXYZ>::Ptr cloud{new pcl::PointCloud<pcl::PointXYZ>};
  pcl::PointCloud<pcl::Normal>::Ptr normals{new pcl::PointCloud<pcl::Normal>};
  pcl::IntegralImageNormalEstimation<pcl::PointXYZ, pcl::Normal> ne;
  pcl::OrganizedMultiPlaneSegmentation<pcl::PointXYZ, pcl::Normal, pcl::Label> mps;
  // segment() outputs, reused between frames.
  std::vector<pcl::ModelCoefficients> coefficients;
  std::vector<pcl::PointIndices> inliers;
  std::vector<Eigen::Vector4f, Eigen::aligned_allocator<Eigen::Vector4f>> centroids;
  std::vector<Eigen::Matrix3f, Eigen::aligned_allocator<Eigen::Matrix3f>> covariances;
  pcl::PointCloud<pcl::Label> labels;
  std::vector<pcl::PointIndices> label_indices;
};

PclPeer::PclPeer(const PclPeerSettings& s) : impl_(new Impl) {
  impl_->settings = s;
  impl_->ne.setNormalEstimationMethod(s.covariance_normals ? impl_->ne.COVARIANCE_MATRIX
                                                           : impl_->ne.AVERAGE_3D_GRADIENT);
  impl_->ne.setMaxDepthChangeFactor(s.max_depth_change);
  impl_->ne.setNormalSmoothingSize(s.smoothing_px);
  impl_->mps.setAngularThreshold(s.angle_deg * M_PI / 180.0);
  impl_->mps.setDistanceThreshold(s.distance_m);
  impl_->mps.setMinInliers(s.min_inliers);
  impl_->mps.setMaximumCurvature(s.max_curvature);
}

PclPeer::~PclPeer() = default;

void PclPeer::set_cloud(const OrganizedCloud& cloud) {
  auto& c = *impl_->cloud;
  c.resize(cloud.width, cloud.height);  // organised: width x height
  for (std::size_t i = 0; i < cloud.points.size(); ++i) c[i].getVector3fMap() = cloud.points[i];
  c.is_dense = false;
}

void PclPeer::estimate_normals() {
  impl_->ne.setInputCloud(impl_->cloud);
  impl_->ne.compute(*impl_->normals);
}

void PclPeer::segment() {
  Impl& m = *impl_;
  m.coefficients.clear();
  m.inliers.clear();
  m.centroids.clear();
  m.covariances.clear();
  m.label_indices.clear();
  // OrganizedConnectedComponentSegmentation only resizes `labels`, so labels left from the
  // previous frame on invalid pixels index past its run table (segfault): start empty.
  m.labels.clear();
  m.mps.setInputCloud(m.cloud);
  m.mps.setInputNormals(m.normals);
  m.mps.segment(m.coefficients, m.inliers, m.centroids, m.covariances, m.labels, m.label_indices);
}

int PclPeer::plane_count() const { return static_cast<int>(impl_->inliers.size()); }

std::vector<Eigen::Vector3f> PclPeer::normals() const {
  std::vector<Eigen::Vector3f> n(impl_->normals->size());
  for (std::size_t i = 0; i < n.size(); ++i) n[i] = (*impl_->normals)[i].getNormalVector3fMap();
  return n;
}

PlaneSegments PclPeer::segments() const {
  PlaneSegments s;
  s.width = static_cast<int>(impl_->cloud->width);
  s.height = static_cast<int>(impl_->cloud->height);
  s.labels.assign(impl_->cloud->size(), 0);
  for (std::size_t p = 0; p < impl_->inliers.size(); ++p) {
    PlaneSegment seg;
    seg.id = static_cast<int>(p) + 1;
    for (const auto i : impl_->inliers[p].indices) s.labels[i] = seg.id;
    seg.points = static_cast<int>(impl_->inliers[p].indices.size());
    s.planes.push_back(seg);
  }
  return s;
}

}  // namespace tunnelmap::bench
