#include "core/recordings/recording_frames.h"

#include <cmath>
#include <cstdio>
#include <deque>
#include <opencv2/calib3d.hpp>
#include <opencv2/imgproc.hpp>

#include "core/recordings/byte_cursor.h"
#include "core/recordings/depth_image_decode.h"
#include "core/util/error.h"

namespace tunnelmap::recordings {
namespace {

// PoseStamped carries no child frame: its pose is the camera's own, under this name.
constexpr const char* kPoseTopicFrame = "tunnelmap/pose_topic";

std::string time_text(std::int64_t ns) {
  char buf[48];
  std::snprintf(buf, sizeof buf, "t=%.6f s", 1e-9 * static_cast<double>(ns));
  return buf;
}

bool has_distortion(const RosCameraInfo& info) {
  for (double d : info.d)
    if (d != 0.0) return true;
  return false;
}

struct ColorImage {
  std::int64_t stamp_ns = 0;
  int width = 0, height = 0;
  std::vector<std::uint8_t> rgb;
};

struct PendingFrame {
  std::int64_t stamp_ns = 0;
  DepthFrame frame;
};

}  // namespace

// OpenCV's undistortion maps for the camera info's size, applied to every frame.
struct RecordingFrames::Undistortion {
  cv::Mat map_x, map_y;
  void apply(std::vector<float>& values, int w, int h) const {
    const cv::Mat src(h, w, CV_32FC1, values.data());
    cv::Mat dst;
    cv::remap(src, dst, map_x, map_y, cv::INTER_NEAREST, cv::BORDER_CONSTANT, 0);  // no invented depth
    std::copy(dst.ptr<float>(), dst.ptr<float>() + values.size(), values.begin());
  }
  void apply(std::vector<std::uint8_t>& rgb, int w, int h) const {
    const cv::Mat src(h, w, CV_8UC3, rgb.data());
    cv::Mat dst;
    cv::remap(src, dst, map_x, map_y, cv::INTER_LINEAR, cv::BORDER_CONSTANT, cv::Scalar());
    std::copy(dst.ptr<std::uint8_t>(), dst.ptr<std::uint8_t>() + rgb.size(), rgb.begin());
  }
};

RecordingFrames::RecordingFrames(const Recording& rec, const RecordingOptions& opt, const ReadOptions& read)
    : rec_(rec), opt_(opt), read_(read) {
  if (opt_.every < 1) throw ParameterError("--every must be at least 1");
  if (opt_.start_s && !(*opt_.start_s >= 0)) throw ParameterError("--start must be >= 0 seconds");
  if (opt_.duration_s && !(*opt_.duration_s > 0)) throw ParameterError("--duration must be > 0 seconds");
  choice_ = choose_topics(rec, classify_topics(rec), opt_);
  bool first = true;
  for (const TopicInfo& t : rec.summary().topics)
    if (t.first_time_ns) {
      recording_start_ns_ = first ? *t.first_time_ns : std::min(recording_start_ns_, *t.first_time_ns);
      first = false;
    }
  read_static_topics(rec);
  const std::string path = rec.summary().files.front();
  if (!read_.intrinsics && !camera_info_)
    throw InputError(path, "depth topic " + choice_.depth +
                               " has no camera info (give --camera-info-topic or --intrinsics FX,FY,CX,CY)");
  if (!read_.intrinsics && camera_info_ && has_distortion(*camera_info_)) {
    const RosCameraInfo& ci = *camera_info_;
    if (ci.distortion_model != "plumb_bob" && ci.distortion_model != "rational_polynomial")
      throw InputError(path, "camera info " + choice_.camera_info + ": distortion model '" + ci.distortion_model +
                                 "' is not supported (plumb_bob, rational_polynomial)");
    const cv::Mat K(3, 3, CV_64F, const_cast<double*>(ci.k.data()));
    const cv::Mat D(1, static_cast<int>(ci.d.size()), CV_64F, const_cast<double*>(ci.d.data()));
    undistort_ = std::make_unique<Undistortion>();
    // Same K out as in: the undistorted image keeps the camera's focal length and centre.
    cv::initUndistortRectifyMap(K, D, cv::Mat(), K, cv::Size(static_cast<int>(ci.width), static_cast<int>(ci.height)),
                                CV_32FC1, undistort_->map_x, undistort_->map_y);
  }
  world_frame_ = opt_.world_frame.empty() ? default_world_frame() : opt_.world_frame;
  if (!opt_.world_frame.empty() && !tf_.has_frame(opt_.world_frame))
    throw InputError(path, "world frame '" + opt_.world_frame + "' is not in the TF tree (--world-frame)");
}

RecordingFrames::~RecordingFrames() = default;

void RecordingFrames::read_static_topics(const Recording& rec) {
  std::set<std::string> topics(choice_.tf_static_topics.begin(), choice_.tf_static_topics.end());
  if (!choice_.camera_info.empty()) topics.insert(choice_.camera_info);
  if (choice_.use_tf) topics.insert(choice_.tf_topics.begin(), choice_.tf_topics.end());
  if (!choice_.pose.empty()) topics.insert(choice_.pose);
  if (!choice_.imu.empty()) topics.insert(choice_.imu);
  if (topics.empty()) return;
  std::map<std::string, RosType> types;
  for (const TopicInfo& t : rec.summary().topics) types[t.name] = ros_type(t.type);
  const MessageEncoding enc = rec.summary().encoding;
  const std::set<std::string> statics(choice_.tf_static_topics.begin(), choice_.tf_static_topics.end());
  rec.read_messages(topics, [&](const MessageView& m) {
    try {
      const RosType type = types.at(m.topic);
      if (type == RosType::CameraInfo && !camera_info_) camera_info_ = decode_camera_info(m, enc);
      if (type == RosType::TfMessage)
        for (const RosTransform& t : decode_tf_message(m, enc)) tf_.add(t, statics.count(m.topic) > 0);
      if (type == RosType::PoseStamped || type == RosType::Odometry) {
        RosTransform t = type == RosType::Odometry ? decode_odometry(m, enc) : decode_pose_stamped(m, enc);
        if (t.child_frame_id.empty()) t.child_frame_id = kPoseTopicFrame;
        if (pose_child_frame_.empty()) pose_child_frame_ = t.child_frame_id;
        if (t.header.stamp_ns == 0) t.header.stamp_ns = m.log_time_ns;
        tf_.add(t, false);
        if (world_frame_.empty()) world_frame_ = t.header.frame_id;
      }
      if (type == RosType::Imu && m.topic == choice_.imu) add_imu_sample(decode_imu(m, enc), m.log_time_ns);
    } catch (const TruncatedData& e) {
      throw InputError(rec.summary().files.front(), "topic " + m.topic + " at " + time_text(m.log_time_ns) + ": " + e.what());
    }
    return true;
  });
}

// The pose topic's own frame; with TF, odom (then map) when present; else decided per frame
// (the root above the camera's frame).
std::string RecordingFrames::default_world_frame() const {
  if (!choice_.pose.empty()) return world_frame_;
  if (!choice_.use_tf) return "";
  for (const char* f : {"odom", "map"})
    if (tf_.has_frame(f)) return f;
  return "";
}

// world <- camera at the stamp. A pose topic whose frames do not reach the camera's frame
// through TF is taken as the camera's own pose.
std::optional<Eigen::Isometry3d> RecordingFrames::pose_at(const std::string& camera_frame, std::int64_t stamp_ns,
                                                          std::int64_t tolerance_ns) const {
  if (!choice_.use_tf && choice_.pose.empty()) return std::nullopt;
  const std::string world = world_frame_.empty() ? tf_.root_of(camera_frame) : world_frame_;
  if (auto pose = tf_.lookup(world, camera_frame, stamp_ns, tolerance_ns)) return pose;
  if (!choice_.pose.empty() && !tf_.has_frame(camera_frame))
    return tf_.lookup(world, pose_child_frame_, stamp_ns, tolerance_ns);
  return std::nullopt;
}

void RecordingFrames::add_imu_sample(const RosImu& imu, std::int64_t log_time_ns) {
  if (!imu.linear_acceleration) return;
  if (imu_frame_.empty()) imu_frame_ = imu.header.frame_id;
  imu_.add(imu.header.stamp_ns != 0 ? imu.header.stamp_ns : log_time_ns, *imu.linear_acceleration);
}

// The IMU's gravity turned into the camera's frame at the stamp: on an arm the mounting between
// them moves, and the TF tree knows how.
std::optional<Eigen::Vector3d> RecordingFrames::gravity_at(const std::string& camera_frame, std::int64_t stamp_ns,
                                                           std::int64_t tolerance_ns) const {
  const std::optional<Eigen::Vector3d> falling = imu_.falling_at(stamp_ns);
  if (!falling) return std::nullopt;
  if (imu_frame_ == camera_frame) return falling;
  const auto camera_from_imu = tf_.lookup(camera_frame, imu_frame_, stamp_ns, tolerance_ns);
  if (!camera_from_imu) return std::nullopt;
  return (camera_from_imu->linear() * *falling).normalized();
}

void RecordingFrames::for_each_frame(const std::function<bool(DepthFrame&)>& visit) const {
  const std::string path = rec_.summary().files.front();
  std::map<std::string, RosType> types;
  for (const TopicInfo& t : rec_.summary().topics) types[t.name] = ros_type(t.type);
  const MessageEncoding enc = rec_.summary().encoding;
  const std::int64_t window_start = recording_start_ns_ + static_cast<std::int64_t>(std::llround(opt_.start_s.value_or(0) * 1e9));
  const std::optional<std::int64_t> window_end =
      opt_.duration_s ? std::optional<std::int64_t>(window_start + std::llround(*opt_.duration_s * 1e9)) : std::nullopt;
  const auto max_dt_ns = static_cast<std::int64_t>(std::llround(read_.max_time_diff_s * 1e9));

  std::optional<ColorImage> previous_color;
  std::deque<PendingFrame> pending;
  std::size_t in_window = 0;
  bool stopped = false;

  // The nearer of the colour images before and after the depth frame, within the time limit.
  auto emit = [&](PendingFrame& p, const ColorImage* next) {
    const ColorImage* best = nullptr;
    const ColorImage* before = previous_color ? &*previous_color : nullptr;
    for (const ColorImage* c : {before, next}) {
      if (!c || std::llabs(c->stamp_ns - p.stamp_ns) > max_dt_ns) continue;
      if (!best || std::llabs(c->stamp_ns - p.stamp_ns) < std::llabs(best->stamp_ns - p.stamp_ns)) best = c;
    }
    if (best && best->width == p.frame.width && best->height == p.frame.height) {
      p.frame.rgb = best->rgb;
      if (undistort_) undistort_->apply(p.frame.rgb, p.frame.width, p.frame.height);
    }
    stopped = stopped || !visit(p.frame);
  };

  auto depth_frame = [&](const MessageView& m) {
    DecodedDepth d;
    RosHeader header;
    if (types.at(m.topic) == RosType::CompressedImage) {
      const RosCompressedImage img = decode_compressed_image(m, enc);
      header = img.header;
      d = decode_compressed_depth(img, read_.max_image_pixels);
    } else {
      const RosImage img = decode_image(m, enc);
      header = img.header;
      d = decode_depth_image(img);
    }
    PendingFrame p;
    p.stamp_ns = header.stamp_ns != 0 ? header.stamp_ns : m.log_time_ns;
    DepthFrame& f = p.frame;
    f.width = d.width;
    f.height = d.height;
    f.depth = std::move(d.depth);
    f.depth_units_per_m = d.depth_units_per_m;
    f.timestamp_s = 1e-9 * static_cast<double>(p.stamp_ns);
    f.source = m.topic + " " + time_text(p.stamp_ns);
    if (read_.intrinsics) {
      f.intrinsics = intrinsics_for_image(read_, f.width, f.height);
    } else {
      const RosCameraInfo& ci = *camera_info_;
      if (static_cast<int>(ci.width) != f.width || static_cast<int>(ci.height) != f.height)
        throw TruncatedData("image is " + std::to_string(f.width) + "x" + std::to_string(f.height) + " but " +
                            choice_.camera_info + " is " + std::to_string(ci.width) + "x" + std::to_string(ci.height));
      f.intrinsics = Intrinsics{ci.k[0], ci.k[4], ci.k[2], ci.k[5], f.width, f.height};
      if (undistort_) undistort_->apply(f.depth, f.width, f.height);
    }
    f.pose = pose_at(header.frame_id, p.stamp_ns, max_dt_ns);
    f.gravity = gravity_at(header.frame_id, p.stamp_ns, max_dt_ns);
    return p;
  };

  std::set<std::string> topics{choice_.depth};
  if (!choice_.color.empty()) topics.insert(choice_.color);
  rec_.read_messages(topics, [&](const MessageView& m) {
    try {
      if (m.topic == choice_.depth) {
        if (m.log_time_ns < window_start || (window_end && m.log_time_ns > *window_end)) return true;
        if (in_window++ % static_cast<std::size_t>(opt_.every) != 0) return true;
        PendingFrame p = depth_frame(m);
        if (choice_.color.empty() || (previous_color && previous_color->stamp_ns >= p.stamp_ns)) {
          emit(p, nullptr);  // no later colour image can be nearer
        } else {
          pending.push_back(std::move(p));
          // Bounded memory: a colour stream that stalls does not hold depth frames back.
          if (pending.size() > 8) {
            emit(pending.front(), nullptr);
            pending.pop_front();
          }
        }
        return !stopped;
      }
      ColorImage c;
      if (types.at(m.topic) == RosType::CompressedImage) {
        const RosCompressedImage img = decode_compressed_image(m, enc);
        c.stamp_ns = img.header.stamp_ns;
        c.rgb = decode_compressed_color(img, read_.max_image_pixels, c.width, c.height);
      } else {
        const RosImage img = decode_image(m, enc);
        c.stamp_ns = img.header.stamp_ns;
        c.rgb = decode_color_image(img, c.width, c.height);
      }
      if (c.stamp_ns == 0) c.stamp_ns = m.log_time_ns;
      while (!pending.empty() && pending.front().stamp_ns <= c.stamp_ns && !stopped) {
        emit(pending.front(), &c);
        pending.pop_front();
      }
      previous_color = std::move(c);
    } catch (const TruncatedData& e) {
      throw InputError(path, "topic " + m.topic + " at " + time_text(m.log_time_ns) + ": " + e.what());
    }
    return !stopped;
  });
  while (!pending.empty() && !stopped) {
    emit(pending.front(), nullptr);
    pending.pop_front();
  }
}

}  // namespace tunnelmap::recordings
