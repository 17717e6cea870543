#pragma once
// How a robot recording becomes a depth sequence: which topics, which world frame, which part
// (the CLI's --depth-topic, --color-topic, --camera-info-topic, --pose-topic, --imu-topic,
// --world-frame, --start, --duration and --every). Empty topics are chosen automatically when
// there is one candidate; an IMU topic "none" reads no gravity.
#include <optional>
#include <string>

namespace tunnelmap::recordings {

struct RecordingOptions {
  std::string depth_topic, color_topic, camera_info_topic, pose_topic, imu_topic, world_frame;
  std::optional<double> start_s;     // from the recording's first message
  std::optional<double> duration_s;  // from the start
  int every = 1;                     // keep every N-th depth frame
};

}  // namespace tunnelmap::recordings
