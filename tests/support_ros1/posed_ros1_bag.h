#pragma once
// Writes a posed dataset as a ROS 1 bag with the real writer (rosbag_storage), the way a robot
// records it: 16UC1 or compressedDepth depth on /camera/depth/image_raw, its camera info,
// optionally rgb8 colour, and the camera pose as /tf odom <- base_link over a /tf_static
// base_link <- camera_depth_optical_frame; optionally an IMU on the robot base (/imu/data in
// base_link), at rest around each frame that has gravity.
#include <string>

#include "core/io/dataset.h"

namespace tunnelmap::testing {

struct Ros1PosedBagOptions {
  std::string compression = "lz4";  // "none", "bz2" or "lz4"
  bool compressed_depth = false;    // image_transport's compressedDepth PNG instead of 16UC1
  bool colour = true;
  bool imu = false;
};

void write_posed_ros1_bag(const Dataset& ds, const std::string& path, const Ros1PosedBagOptions& options);

}  // namespace tunnelmap::testing
