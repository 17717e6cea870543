#include "tests/support/posed_bag.h"

#include <cmath>
#include <cstring>

#include "tests/support/cdr_writer.h"
#include "tests/support/imu_at_rest.h"

namespace tunnelmap::testing {

std::int64_t bag_stamp_ns(const Dataset& ds, std::size_t i) {
  return 1700000000LL * 1000000000LL + std::llround(ds.frames[i].timestamp_s * 1e9);
}

namespace {

// The IMU's readings before (or from) the stamp: in time order around the frame's messages.
void write_imu(const DepthFrame& f, std::int64_t t, bool before, const BagMessageSink& write) {
  if (!f.gravity) return;
  for (const ImuReading& r : imu_at_rest(t, *f.gravity))
    if ((r.stamp_ns < t) == before)
      write(kBagImuTopic, "sensor_msgs/msg/Imu", r.stamp_ns, cdr_imu(r.stamp_ns, kBagCameraFrame, r.specific_force));
}

}  // namespace

void write_posed_bag(const Dataset& ds, const BagMessageSink& write, bool with_imu) {
  for (std::size_t i = 0; i < ds.frames.size(); ++i) {
    const DepthFrame f = ds.load_frame(i);
    const std::int64_t t = bag_stamp_ns(ds, i);
    if (with_imu) write_imu(f, t, true, write);
    const auto w = static_cast<std::uint32_t>(f.width), h = static_cast<std::uint32_t>(f.height);
    std::vector<std::uint8_t> depth(static_cast<std::size_t>(w) * h * 4);
    for (std::size_t k = 0; k < f.depth.size(); ++k) {
      const float metres = f.depth[k] / static_cast<float>(f.depth_units_per_m);
      std::memcpy(&depth[k * 4], &metres, 4);
    }
    write(kBagInfoTopic, "sensor_msgs/msg/CameraInfo", t,
          cdr_camera_info(t, kBagCameraFrame, w, h, f.intrinsics.fx, f.intrinsics.fy, f.intrinsics.cx, f.intrinsics.cy));
    write(kBagOdomTopic, "nav_msgs/msg/Odometry", t, cdr_odometry(t, "odom", kBagCameraFrame, *f.pose));
    write(kBagDepthTopic, "sensor_msgs/msg/Image", t, cdr_image(t, kBagCameraFrame, w, h, "32FC1", w * 4, depth));
    if (f.has_rgb()) write(kBagColorTopic, "sensor_msgs/msg/Image", t, cdr_image(t, "camera_color_optical_frame", w, h, "rgb8", w * 3, f.rgb));
    if (with_imu) write_imu(f, t, false, write);
  }
}

}  // namespace tunnelmap::testing
