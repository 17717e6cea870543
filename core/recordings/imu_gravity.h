#pragma once
// An IMU topic's accelerometer as gravity at any time. A climbing robot scans standing still,
// and an accelerometer at rest reads the specific force opposite to gravity (REP 145), so the
// mean over the samples near a depth frame, turned round, is where things fall at that frame.
// The window is short because an arm may turn the camera between frames 33 ms apart. The
// samples are kept as 5 ms sums: memory grows with the recording's length, not its rate.
#include <Eigen/Core>
#include <cstdint>
#include <optional>
#include <vector>

namespace tunnelmap::recordings {

class ImuGravityTrack {
 public:
  // Samples within this of a frame's stamp are averaged (either side): 12 samples of a 250 Hz
  // IMU, 3 of a 63 Hz one.
  static constexpr std::int64_t kHalfWindowNs = 25'000'000;
  // A mean whose length differs from standard gravity by more than this is not gravity: the
  // robot was accelerating (or the topic is not in m/s², or carries no accelerometer).
  static constexpr double kStillToleranceMps2 = 0.5;

  void add(std::int64_t stamp_ns, const Eigen::Vector3d& specific_force_mps2);

  // Unit, in the IMU's frame; unknown without a sample within the window or when the mean is
  // not gravity (see above).
  std::optional<Eigen::Vector3d> falling_at(std::int64_t stamp_ns) const;

 private:
  static constexpr std::int64_t kBinNs = 5'000'000;
  struct Bin {
    std::int64_t index = 0;  // stamp / kBinNs
    Eigen::Vector3d sum = Eigen::Vector3d::Zero();
    int count = 0;
  };
  std::vector<Bin> bins_;  // in time order
};

}  // namespace tunnelmap::recordings
