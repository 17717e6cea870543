#include "app/cli/input_options.h"

#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <sstream>

#include "core/recordings/recording.h"
#include "core/util/error.h"

namespace tunnelmap::cli {

namespace {
std::vector<double> parse_numbers(const std::string& text, std::size_t count, const std::string& flag) {
  std::vector<double> out;
  std::stringstream ss(text);
  std::string item;
  while (std::getline(ss, item, ',')) {
    std::size_t used = 0;
    double v = 0;
    try {
      v = std::stod(item, &used);
    } catch (...) {
      used = 0;
    }
    if (used == 0 || used != item.size() || !std::isfinite(v))
      throw ParameterError(flag + " expects " + std::to_string(count) + " comma-separated numbers, got '" + text + "'");
    out.push_back(v);
  }
  if (out.size() != count)
    throw ParameterError(flag + " expects " + std::to_string(count) + " comma-separated numbers, got '" + text + "'");
  return out;
}
}  // namespace

namespace {
// Robot recordings (ROS bags): see docs/recordings.md and `tunnelmap-cli topics BAG`.
void add_recording_options(CLI::App* cmd, recordings::RecordingOptions& r) {
  const std::string group = "ROS bags";
  cmd->add_option("--depth-topic", r.depth_topic, "Bag: depth image topic (16UC1, 32FC1 or compressedDepth)")->group(group);
  cmd->add_option("--color-topic", r.color_topic, "Bag: colour image topic, paired by timestamp")->group(group);
  cmd->add_option("--camera-info-topic", r.camera_info_topic, "Bag: CameraInfo topic of the depth camera")->group(group);
  cmd->add_option("--pose-topic", r.pose_topic, "Bag: PoseStamped or Odometry topic (default: the TF tree)")->group(group);
  cmd->add_option("--imu-topic", r.imu_topic,
                  "Bag: sensor_msgs/Imu topic whose accelerometer gives each frame's gravity, or none "
                  "(default: the only one)")
      ->group(group);
  cmd->add_option("--world-frame", r.world_frame, "Bag: TF frame of the poses (default odom, else map, else the root)")
      ->group(group);
  cmd->add_option("--start", r.start_s, "Bag: skip the first S seconds")->group(group);
  cmd->add_option("--duration", r.duration_s, "Bag: read S seconds from the start")->group(group);
  cmd->add_option("--every", r.every, "Bag: keep every N-th depth frame")->group(group);
}
}  // namespace

void add_input_options(CLI::App* cmd, InputOptions& opt, bool input_required) {
  cmd->add_option("INPUT", opt.input, "Depth PNG (16-bit), organised PCD, dataset folder, TUM RGB-D sequence folder, OpenNI2 recording (.oni), or ROS bag (.bag, .mcap, .db3, rosbag2 folder)")
      ->required(input_required);
  cmd->add_option("--params", opt.params_file, "Parameter preset JSON (see resources/presets)");
  cmd->add_option("--set", opt.sets, "Override one parameter: KEY=VALUE (repeatable; see `params`)")
      ->take_all();
  add_read_options(cmd, opt);
  cmd->add_option("--up", opt.up, "Camera-frame vector towards the roof X,Y,Z (default: from the pose, else image-up)");
}

void add_read_options(CLI::App* cmd, InputOptions& opt) {
  cmd->add_option("--intrinsics", opt.intrinsics, "Camera intrinsics FX,FY,CX,CY in pixels");
  cmd->add_option("--depth-scale", opt.depth_scale,
                  "Depth PNG units per metre (default 1000: millimetres; TUM sequences 5000)");
  cmd->add_option("--max-time-diff", opt.max_time_diff,
                  "TUM sequences: pair depth with colour and ground truth at most S seconds apart (default 0.02)");
  cmd->add_option("--world-up", opt.world_up,
                  "World-frame vector towards the roof X,Y,Z for posed frames (default: the dataset's, +Z)");
  add_recording_options(cmd, opt.recording);
}

Parameters InputOptions::parameters() const {
  Parameters p;
  if (!params_file.empty()) p.load_json_file(params_file);
  p.set_from_strings(sets);  // all at once: the rules hold after the whole list
  return p;
}

ReadOptions InputOptions::read_options() const {
  ReadOptions r;
  if (depth_scale) {  // 0 given is refused, not taken as "the default"
    if (!(*depth_scale > 0) || !std::isfinite(*depth_scale) || *depth_scale > 1e7)
      throw ParameterError("--depth-scale must be a positive number of units per metre");
    r.depth_units_per_m = *depth_scale;
    r.depth_scale_given = true;
  }
  if (!intrinsics.empty()) {
    const auto v = parse_numbers(intrinsics, 4, "--intrinsics");
    if (v[0] <= 0 || v[1] <= 0 || v[0] > 1e5 || v[1] > 1e5)
      throw ParameterError("--intrinsics: focal lengths must be positive pixels");
    Intrinsics K;
    K.fx = v[0], K.fy = v[1], K.cx = v[2], K.cy = v[3];
    r.intrinsics = K;
  }
  if (max_time_diff) {
    if (!(*max_time_diff >= 0 && *max_time_diff <= 10))
      throw ParameterError("--max-time-diff must be 0..10 seconds");
    r.max_time_diff_s = *max_time_diff;
  }
  if (!world_up.empty()) {
    const auto v = parse_numbers(world_up, 3, "--world-up");
    const Eigen::Vector3d u(v[0], v[1], v[2]);
    if (u.norm() < 1e-9) throw ParameterError("--world-up must not be the zero vector");
    if (!std::isfinite(u.norm())) throw ParameterError("--world-up is too long (its length overflows a double)");
    r.world_up = u.normalized();
  }
  r.note = [](const std::string& line) { std::fprintf(stderr, "tunnelmap-cli: note: %s\n", line.c_str()); };
  r.recording = recording;
  r.max_image_pixels = input_limit_options(parameters()).max_image_pixels;
  return r;
}

DatasetInput::DatasetInput(const InputOptions& in) {
  if (recordings::is_recording_path(in.input))
    recording_ = open_input(in.input, in.read_options());
  else
    dataset_ = read_dataset(in.input, in.read_options());
}

std::optional<Eigen::Vector3d> InputOptions::camera_up() const {
  if (up.empty()) return std::nullopt;
  const auto v = parse_numbers(up, 3, "--up");
  const Eigen::Vector3d u(v[0], v[1], v[2]);
  if (u.norm() < 1e-9) throw ParameterError("--up must not be the zero vector");
  if (!std::isfinite(u.norm())) throw ParameterError("--up is too long (its length overflows a double)");
  return u.normalized();
}

Pipeline InputOptions::pipeline() const {
  Pipeline p(parameters());
  p.set_camera_up(camera_up());
  return p;
}

Progress::Progress(std::size_t total) : total_(total), enabled_(total > 1 && isatty(STDERR_FILENO)) {}

void Progress::step(std::size_t done) {
  if (!enabled_) return;
  const int width = 30;
  const int filled = static_cast<int>(width * done / std::max<std::size_t>(1, total_));
  std::fprintf(stderr, "\r[%.*s%*s] %zu/%zu", filled, "##############################", width - filled, "",
               done, total_);
  std::fflush(stderr);
}

Progress::~Progress() {
  if (enabled_) std::fprintf(stderr, "\r%*s\r", 50, "");
}

}  // namespace tunnelmap::cli
