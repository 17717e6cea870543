#include "bench/opencv_peer.h"

#include <opencv2/core.hpp>
#include <opencv2/rgbd.hpp>

#include <cmath>
#include <limits>

namespace tunnelmap::bench {

// Why these values (fair to OpenCV on 640x480 PrimeSense-class frames at 0.5-3 m; chosen by a
// sweep on the two simulated frames, recall / precision per frame sim_lab, sim_field_3m):
// - FALS, window 5 (FALS/SRI accept 1-7). SRI (benchmarked too): recall 0.45 / 0.58 and
//   slower. Window 7: the same recall, lower precision (0.82 / 0.86). LINEMOD crashes in Debian's 4.6 (peer_bench.cpp).
// - RgbdPlane grows planes tile by tile from the flattest tile; `threshold` is both the
//   point-to-plane limit and the RMS a seed tile must beat. 10 mm with the Kinect quadratic
//   error model (a = 0.0075 per m^2, the value OpenCV's header gives, so the band widens with
//   depth like the sensor noise): 0.73 / 0.92 recall, 0.87 / 1.0 precision. 15 mm: 0.73 / 0.92
//   recall, 0.81 / 0.75 precision; 20 mm: worse on both; without the error model (a = 0,
//   10-30 mm) recall falls to 0.45 / 0.42.
// - Tiles of 20 px (divides 640 and 480; the default 40 px loses the narrow edge bands of the
//   tunnel walls: sim_field_3m recall 0.50) and min size 300 px, PG&C's min area 0.004 m^2 at
//   ~2 m (the same as the PCL peer).
OpenCvPeerSettings tuned_opencv_settings(CvNormalsMethod method) {
  OpenCvPeerSettings s;
  s.method = method;
  s.window = 5;
  s.block_size = 20;
  s.min_size = 300;
  s.threshold_m = 0.010;
  s.sensor_error_a = 0.0075;
  return s;
}

const char* method_name(CvNormalsMethod method) {
  switch (method) {
    case CvNormalsMethod::Fals: return "FALS";
    case CvNormalsMethod::Linemod: return "LINEMOD";
    case CvNormalsMethod::Sri: return "SRI";
  }
  return "?";
}

struct OpenCvPeer::Impl {
  cv::Mat depth_m;  // CV_32F metres, NaN = no measurement
  cv::Mat K;
  cv::Mat points, normals, mask, coefficients;
  cv::Ptr<cv::rgbd::RgbdNormals> normal_estimator;
  cv::Ptr<cv::rgbd::RgbdPlane> plane_finder;
};

OpenCvPeer::OpenCvPeer(const DepthFrame& frame, const CloudOptions& range, const OpenCvPeerSettings& s)
    : impl_(new Impl) {
  Impl& m = *impl_;
  m.depth_m.create(frame.height, frame.width, CV_32F);
  const float nan = std::numeric_limits<float>::quiet_NaN();
  for (int v = 0; v < frame.height; ++v)
    for (int u = 0; u < frame.width; ++u) {
      const float z = frame.depth_m(u, v);
      m.depth_m.at<float>(v, u) =
          (std::isfinite(z) && z >= range.min_range_m && z <= range.max_range_m) ? z : nan;
    }
  const Intrinsics& K = frame.intrinsics;
  m.K = (cv::Mat_<float>(3, 3) << K.fx, 0, K.cx, 0, K.fy, K.cy, 0, 0, 1);
  const int method = s.method == CvNormalsMethod::Fals      ? cv::rgbd::RgbdNormals::RGBD_NORMALS_METHOD_FALS
                     : s.method == CvNormalsMethod::Linemod ? cv::rgbd::RgbdNormals::RGBD_NORMALS_METHOD_LINEMOD
                                                            : cv::rgbd::RgbdNormals::RGBD_NORMALS_METHOD_SRI;
  m.normal_estimator = cv::rgbd::RgbdNormals::create(frame.height, frame.width, CV_32F, m.K, s.window, method);
  m.normal_estimator->initialize();
  m.plane_finder = cv::rgbd::RgbdPlane::create(cv::rgbd::RgbdPlane::RGBD_PLANE_METHOD_DEFAULT, s.block_size,
                                               s.min_size, s.threshold_m, s.sensor_error_a);
}

OpenCvPeer::~OpenCvPeer() = default;

void OpenCvPeer::depth_to_3d() { cv::rgbd::depthTo3d(impl_->depth_m, impl_->K, impl_->points); }

void OpenCvPeer::estimate_normals() { (*impl_->normal_estimator)(impl_->points, impl_->normals); }

void OpenCvPeer::find_planes() {
  (*impl_->plane_finder)(impl_->points, impl_->normals, impl_->mask, impl_->coefficients);
}

int OpenCvPeer::plane_count() const { return impl_->coefficients.rows; }

std::vector<Eigen::Vector3f> OpenCvPeer::normals() const {
  const cv::Mat& n = impl_->normals;
  std::vector<Eigen::Vector3f> out(static_cast<std::size_t>(n.rows) * n.cols);
  for (int v = 0; v < n.rows; ++v)
    for (int u = 0; u < n.cols; ++u) {
      const cv::Vec3f& x = n.at<cv::Vec3f>(v, u);
      out[static_cast<std::size_t>(v) * n.cols + u] = Eigen::Vector3f(x[0], x[1], x[2]);
    }
  return out;
}

PlaneSegments OpenCvPeer::segments() const {
  const cv::Mat& mask = impl_->mask;
  PlaneSegments s;
  s.width = mask.cols;
  s.height = mask.rows;
  s.labels.assign(static_cast<std::size_t>(mask.rows) * mask.cols, 0);
  for (int v = 0; v < mask.rows; ++v)
    for (int u = 0; u < mask.cols; ++u) {
      const int m = mask.at<unsigned char>(v, u);
      if (m != 255) s.labels[static_cast<std::size_t>(v) * mask.cols + u] = m + 1;
    }
  for (int p = 0; p < plane_count(); ++p) {
    PlaneSegment seg;
    seg.id = p + 1;
    s.planes.push_back(seg);
  }
  return s;
}

}  // namespace tunnelmap::bench
