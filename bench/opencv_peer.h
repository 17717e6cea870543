#pragma once
// OpenCV peer: opencv_contrib rgbd depthTo3d + RgbdNormals + RgbdPlane (OpenCV 4.6, Debian's
// libopencv-contrib-dev). OpenCV's rgbd headers stay inside opencv_peer.cpp.
#include <memory>
#include <vector>

#include "core/frame/depth_frame.h"
#include "core/normals/cloud_builder.h"
#include "core/planes/plane_segment.h"

namespace tunnelmap::bench {

enum class CvNormalsMethod { Fals, Linemod, Sri };

struct OpenCvPeerSettings {
  CvNormalsMethod method = CvNormalsMethod::Fals;
  int window = 5;              // RgbdNormals window: 1, 3, 5 or 7
  int block_size = 20;         // RgbdPlane tile side (divides 640 and 480)
  int min_size = 300;          // RgbdPlane minimum plane size, pixels
  double threshold_m = 0.015;  // RgbdPlane point-to-plane distance (and tile RMS) limit
  double sensor_error_a = 0.0; // RgbdPlane quadratic sensor error (0.0075 for a Kinect)
};

OpenCvPeerSettings tuned_opencv_settings(CvNormalsMethod method);
const char* method_name(CvNormalsMethod method);

class OpenCvPeer {
 public:
  // Prepares the depth as CV_32F metres (NaN outside TunnelMap's cloud range, not timed) and the
  // RgbdNormals object with its cached tables (initialize(), not timed).
  OpenCvPeer(const DepthFrame& frame, const CloudOptions& range, const OpenCvPeerSettings& settings);
  ~OpenCvPeer();
  OpenCvPeer(const OpenCvPeer&) = delete;
  OpenCvPeer& operator=(const OpenCvPeer&) = delete;

  void depth_to_3d();       // cv::rgbd::depthTo3d
  void estimate_normals();  // RgbdNormals, needs depth_to_3d()
  void find_planes();       // RgbdPlane with normals, needs estimate_normals()

  int plane_count() const;
  std::vector<Eigen::Vector3f> normals() const;  // NaN where none
  PlaneSegments segments() const;                // mask value m -> id m + 1

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace tunnelmap::bench
