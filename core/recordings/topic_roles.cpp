#include "core/recordings/topic_roles.h"

#include <algorithm>
#include <set>
#include <sstream>

#include "core/recordings/byte_cursor.h"
#include "core/recordings/ros_messages.h"
#include "core/util/error.h"

namespace tunnelmap::recordings {
namespace {

bool is_depth_encoding(const std::string& e) { return e == "16UC1" || e == "mono16" || e == "32FC1"; }

TopicRole image_role(RosType type, const MessageView& m, MessageEncoding enc) {
  try {
    if (type == RosType::Image)
      return is_depth_encoding(decode_image(m, enc).encoding) ? TopicRole::Depth : TopicRole::Color;
    const std::string format = decode_compressed_image(m, enc).format;
    return format.find("compressedDepth") != std::string::npos ? TopicRole::Depth : TopicRole::Color;
  } catch (const TruncatedData&) {
    return TopicRole::None;  // an undecodable first message: not offered
  }
}

TopicRole role_by_type(const TopicInfo& t) {
  switch (ros_type(t.type)) {
    case RosType::CameraInfo: return TopicRole::CameraInfo;
    case RosType::TfMessage: return t.name == "/tf_static" || t.name == "tf_static" ? TopicRole::TfStatic : TopicRole::Tf;
    case RosType::PoseStamped:
    case RosType::Odometry: return TopicRole::Pose;
    case RosType::Imu: return TopicRole::Imu;
    default: return TopicRole::None;
  }
}

std::string parent_namespace(const std::string& topic) {
  const auto p = topic.rfind('/');
  return p == std::string::npos ? std::string() : topic.substr(0, p);
}

std::vector<std::string> with_role(const std::map<std::string, TopicRole>& roles, TopicRole r) {
  std::vector<std::string> out;
  for (const auto& [name, role] : roles)
    if (role == r) out.push_back(name);
  return out;
}

std::string join(const std::vector<std::string>& v) {
  std::string s;
  for (const std::string& x : v) s += (s.empty() ? "" : ", ") + x;
  return s;
}

// The given topic (checked), the only candidate, or empty when there is none.
std::string choose(const std::string& given, const std::vector<std::string>& candidates,
                   const std::map<std::string, TopicRole>& roles, const std::string& flag,
                   const std::string& what, const std::string& path) {
  if (!given.empty()) {
    const auto it = roles.find(given);
    if (it == roles.end()) throw InputError(path, "no topic " + given + " (" + flag + ")");
    if (std::find(candidates.begin(), candidates.end(), given) == candidates.end())
      throw InputError(path, "topic " + given + " holds no " + what + " (" + flag + ")");
    return given;
  }
  if (candidates.size() > 1)
    throw ParameterError(path + ": several " + what + " topics (" + join(candidates) + "): choose one with " + flag);
  return candidates.empty() ? std::string() : candidates.front();
}

// The given IMU topic (checked), "none", the only candidate, or none of several (with why).
void choose_imu(const std::string& given, const std::vector<std::string>& candidates,
                const std::map<std::string, TopicRole>& roles, const std::string& path, TopicChoice& c) {
  if (given == "none") return;
  if (given.empty() && candidates.size() > 1) {
    c.imu_not_read_because = "several IMU topics (" + join(candidates) + "): choose one with --imu-topic";
    return;
  }
  c.imu = choose(given, candidates, roles, "--imu-topic", "IMU", path);
}

}  // namespace

const char* topic_role_name(TopicRole r) {
  switch (r) {
    case TopicRole::Depth: return "depth";
    case TopicRole::Color: return "color";
    case TopicRole::CameraInfo: return "camera_info";
    case TopicRole::Tf: return "tf";
    case TopicRole::TfStatic: return "tf_static";
    case TopicRole::Pose: return "pose";
    case TopicRole::Imu: return "imu";
    case TopicRole::None: break;
  }
  return "";
}

std::map<std::string, TopicRole> classify_topics(const Recording& rec) {
  std::map<std::string, TopicRole> roles;
  std::set<std::string> image_topics;
  std::map<std::string, RosType> image_types;
  for (const TopicInfo& t : rec.summary().topics) {
    roles[t.name] = role_by_type(t);
    const RosType type = ros_type(t.type);
    if ((type == RosType::Image || type == RosType::CompressedImage) && t.message_count > 0) {
      image_topics.insert(t.name);
      image_types[t.name] = type;
    }
  }
  if (image_topics.empty()) return roles;
  std::set<std::string> pending = image_topics;
  const MessageEncoding enc = rec.summary().encoding;
  rec.read_messages(image_topics, [&](const MessageView& m) {
    if (!pending.erase(m.topic)) return true;
    roles[m.topic] = image_role(image_types.at(m.topic), m, enc);
    return !pending.empty();
  });
  return roles;
}

TopicChoice choose_topics(const Recording& rec, const std::map<std::string, TopicRole>& roles,
                          const RecordingOptions& opt) {
  const std::string path = rec.summary().files.empty() ? "" : rec.summary().files.front();
  TopicChoice c;
  c.depth = choose(opt.depth_topic, with_role(roles, TopicRole::Depth), roles, "--depth-topic",
                   "depth image", path);
  if (c.depth.empty())
    throw InputError(path, "no depth image topic (sensor_msgs/Image 16UC1 or 32FC1, or compressedDepth)");
  c.color = choose(opt.color_topic, with_role(roles, TopicRole::Color), roles, "--color-topic", "colour image", path);
  std::vector<std::string> infos = with_role(roles, TopicRole::CameraInfo);
  if (opt.camera_info_topic.empty() && infos.size() > 1) {
    // The camera info published beside the depth image (…/depth/camera_info) is its own.
    const std::string ns = parent_namespace(c.depth) + "/";
    std::vector<std::string> beside;
    for (const std::string& t : infos)
      if (t.rfind(ns, 0) == 0) beside.push_back(t);
    if (beside.size() == 1) infos = beside;
  }
  c.camera_info = choose(opt.camera_info_topic, infos, roles, "--camera-info-topic", "camera info", path);
  c.tf_static_topics = with_role(roles, TopicRole::TfStatic);
  c.tf_topics = with_role(roles, TopicRole::Tf);
  if (!opt.pose_topic.empty() || c.tf_topics.empty())
    c.pose = choose(opt.pose_topic, with_role(roles, TopicRole::Pose), roles, "--pose-topic", "pose", path);
  c.use_tf = c.pose.empty() && !c.tf_topics.empty();
  choose_imu(opt.imu_topic, with_role(roles, TopicRole::Imu), roles, path, c);
  return c;
}

std::string suggested_command(const std::string& path, const TopicChoice& c) {
  std::string s = "tunnelmap-cli detect " + path + " --depth-topic " + c.depth;
  if (!c.color.empty()) s += " --color-topic " + c.color;
  if (!c.camera_info.empty()) s += " --camera-info-topic " + c.camera_info;
  if (!c.pose.empty()) s += " --pose-topic " + c.pose;
  if (!c.imu.empty()) s += " --imu-topic " + c.imu;
  return s;
}

std::string suggested_command(const std::string& path, const TopicChoice& choice, const RecordingOptions& opt) {
  std::ostringstream s;
  s << suggested_command(path, choice);
  if (!opt.world_frame.empty()) s << " --world-frame " << opt.world_frame;
  if (opt.start_s) s << " --start " << *opt.start_s;
  if (opt.duration_s) s << " --duration " << *opt.duration_s;
  if (opt.every > 1) s << " --every " << opt.every;
  if (opt.imu_topic == "none") s << " --imu-topic none";
  return s.str();
}

}  // namespace tunnelmap::recordings
