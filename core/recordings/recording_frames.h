#pragma once
// A robot recording read as a posed depth sequence. The constructor reads what is small
// (camera info, /tf_static, /tf or the pose topic) in one pass; for_each_frame() then streams
// the depth topic with its colour, one message at a time:
//  - depth 16UC1 (mm), 32FC1 (m) or compressedDepth PNG;
//  - intrinsics from CameraInfo (or --intrinsics); a plumb_bob or rational_polynomial
//    distortion is removed with OpenCV (nearest neighbour for depth, so no invented depth);
//  - colour paired with the nearest colour image within ReadOptions::max_time_diff_s;
//  - the pose: world frame <- the depth image's frame at its stamp, through the TF tree (or
//    the pose topic's transforms composed with the static ones), unknown when not connected;
//  - gravity from the IMU topic's accelerometer near the stamp (ImuGravityTrack), turned into
//    the depth image's frame through the TF tree; unknown when the robot was not still or the
//    IMU's frame does not reach the camera's.
#include <functional>
#include <memory>
#include <optional>
#include <string>

#include "core/frame/depth_frame.h"
#include "core/io/read_options.h"
#include "core/recordings/imu_gravity.h"
#include "core/recordings/recording.h"
#include "core/recordings/recording_options.h"
#include "core/recordings/tf_tree.h"
#include "core/recordings/topic_roles.h"

namespace tunnelmap::recordings {

class RecordingFrames {
 public:
  // InputError naming the recording (and the topic) for a missing camera info without
  // --intrinsics, an unsupported distortion model, an undecodable message.
  RecordingFrames(const Recording& rec, const RecordingOptions& opt, const ReadOptions& read);
  ~RecordingFrames();

  const TopicChoice& topics() const { return choice_; }
  const std::string& world_frame() const { return world_frame_; }  // empty without poses
  // Calls `visit` with each kept depth frame, in order; `visit` returns false to stop.
  // A frame with an inconsistent image is refused: InputError naming the topic and time.
  void for_each_frame(const std::function<bool(DepthFrame&)>& visit) const;

 private:
  struct Undistortion;
  void read_static_topics(const Recording& rec);
  std::string default_world_frame() const;
  std::optional<Eigen::Isometry3d> pose_at(const std::string& camera_frame, std::int64_t stamp_ns,
                                           std::int64_t tolerance_ns) const;
  std::optional<Eigen::Vector3d> gravity_at(const std::string& camera_frame, std::int64_t stamp_ns,
                                            std::int64_t tolerance_ns) const;
  void add_imu_sample(const RosImu& imu, std::int64_t log_time_ns);

  const Recording& rec_;
  RecordingOptions opt_;
  ReadOptions read_;
  TopicChoice choice_;
  TfTree tf_;
  std::optional<RosCameraInfo> camera_info_;
  std::string pose_child_frame_;  // PoseStamped: the pose is the camera's own
  std::string world_frame_;
  ImuGravityTrack imu_;
  std::string imu_frame_;
  std::unique_ptr<Undistortion> undistort_;
  std::int64_t recording_start_ns_ = 0;
};

}  // namespace tunnelmap::recordings
