#pragma once
// What an IMU at rest reads around a depth frame, for the tests' bag writers: five
// accelerometer samples 10 ms apart centred on the frame's stamp, the opposite of where things
// fall at 9.80665 m/s², with noise in pairs of opposite signs, so their mean is exact.
#include <Eigen/Geometry>
#include <cstdint>
#include <vector>

namespace tunnelmap::testing {

struct ImuReading {
  std::int64_t stamp_ns = 0;
  Eigen::Vector3d specific_force;  // m/s², in the IMU's frame
};

inline std::vector<ImuReading> imu_at_rest(std::int64_t stamp_ns, const Eigen::Vector3d& falling_in_imu) {
  const Eigen::Vector3d at_rest = -9.80665 * falling_in_imu.normalized();
  const Eigen::Vector3d noise = 0.05 * falling_in_imu.unitOrthogonal();
  constexpr std::int64_t ms = 1'000'000;
  return {{stamp_ns - 20 * ms, at_rest + noise},
          {stamp_ns - 10 * ms, at_rest - noise},
          {stamp_ns, at_rest},
          {stamp_ns + 10 * ms, at_rest + noise},
          {stamp_ns + 20 * ms, at_rest - noise}};
}

}  // namespace tunnelmap::testing
