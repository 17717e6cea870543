#pragma once
// Writes a posed dataset (e.g. from the simulator) as a ROS 2 recording, the way a robot's
// camera driver and odometry would publish it: 32FC1 depth in metres on
// /camera/depth/image_raw, its CameraInfo, rgb8 colour on /camera/color/image_raw, and the
// camera pose as nav_msgs/Odometry odom <- camera_depth_optical_frame on /odom; optionally an
// IMU in the camera's frame on /camera/imu, at rest around each frame that has gravity.
#include <functional>
#include <string>

#include "core/io/dataset.h"

namespace tunnelmap::testing {

inline constexpr const char* kBagDepthTopic = "/camera/depth/image_raw";
inline constexpr const char* kBagColorTopic = "/camera/color/image_raw";
inline constexpr const char* kBagInfoTopic = "/camera/depth/camera_info";
inline constexpr const char* kBagOdomTopic = "/odom";
inline constexpr const char* kBagCameraFrame = "camera_depth_optical_frame";
inline constexpr const char* kBagImuTopic = "/camera/imu";

// write(topic, type, time_ns, cdr) for each message, in time order. Frame i is stamped
// 1.7e9 s + its dataset timestamp.
using BagMessageSink =
    std::function<void(const std::string&, const std::string&, std::int64_t, const std::vector<std::uint8_t>&)>;
void write_posed_bag(const Dataset& ds, const BagMessageSink& write, bool with_imu = false);

std::int64_t bag_stamp_ns(const Dataset& ds, std::size_t i);

}  // namespace tunnelmap::testing
