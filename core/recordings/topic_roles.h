#pragma once
// What each topic of a recording can be to TunnelMap: depth images (16UC1, 32FC1,
// compressedDepth), colour images, camera info, poses (TF, PoseStamped, Odometry) or an IMU
// (its accelerometer gives each frame's gravity). Image topics are told apart by their first
// message's encoding.
#include <map>
#include <string>
#include <vector>

#include "core/recordings/recording.h"
#include "core/recordings/recording_options.h"

namespace tunnelmap::recordings {

enum class TopicRole { Depth, Color, CameraInfo, Tf, TfStatic, Pose, Imu, None };

// "depth", "color", "camera_info", "tf", "tf_static", "pose", "imu", ""
const char* topic_role_name(TopicRole r);

// One pass over the first message of each image topic; the others by type alone.
std::map<std::string, TopicRole> classify_topics(const Recording& rec);

// The topics a sequence is read from, each chosen by the options or automatically.
struct TopicChoice {
  std::string depth, color, camera_info, pose, imu;  // all but depth may be empty
  // Several IMU topics and none given: gravity is not read (rather than refuse a recording
  // that reads without it), and this says why.
  std::string imu_not_read_because;
  bool use_tf = false;                          // poses from /tf (+ /tf_static)
  std::vector<std::string> tf_static_topics, tf_topics;
};

// ParameterError naming the candidates when a role has several and none was given (camera
// info: the one beside the depth topic wins; IMU: none is read); InputError when a given topic is missing or
// cannot play its role, or the recording has no depth topic.
TopicChoice choose_topics(const Recording& rec, const std::map<std::string, TopicRole>& roles,
                          const RecordingOptions& opt);

// "tunnelmap-cli detect BAG --depth-topic ... [--color-topic ...] ...": what `topics` suggests.
std::string suggested_command(const std::string& path, const TopicChoice& choice);
// The same with the world frame and the time window of `opt` (--world-frame, --start,
// --duration, --every) when they are set, and --imu-topic none when no IMU was wanted.
std::string suggested_command(const std::string& path, const TopicChoice& choice, const RecordingOptions& opt);

}  // namespace tunnelmap::recordings
