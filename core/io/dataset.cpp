#include "core/io/dataset.h"
#include "core/io/path_inside.h"

#include <cmath>
#include <filesystem>

#include "core/io/depth_png.h"
#include "core/io/json_file.h"
#include "core/io/input_limits.h"
#include "core/io/read_options.h"
#include "core/io/tum_sequence.h"
#include "core/util/error.h"

namespace tunnelmap {
namespace fs = std::filesystem;
using nlohmann::json;

namespace {

// Every validation message names dataset.json (as the InputError file) and the JSON key.
class Checker {
 public:
  explicit Checker(std::string json_path) : path_(std::move(json_path)) {}

  [[noreturn]] void fail(const std::string& key, const std::string& problem) const {
    throw InputError(path_, "key '" + key + "': " + problem);
  }

  const json& member(const json& obj, const std::string& name, const std::string& key) const {
    auto it = obj.find(name);
    if (it == obj.end()) fail(key, "missing");
    return *it;
  }

  double number(const json& j, const std::string& key) const {
    if (!j.is_number()) fail(key, "must be a number, got " + std::string(j.type_name()));
    const double x = j.get<double>();
    if (!std::isfinite(x)) fail(key, "must be finite");
    return x;
  }

  int integer(const json& j, const std::string& key) const {
    const double x = number(j, key);
    if (x != std::floor(x) || std::abs(x) > 1e9) fail(key, "must be an integer");
    return static_cast<int>(x);
  }

  std::string string(const json& j, const std::string& key) const {
    if (!j.is_string()) fail(key, "must be a string, got " + std::string(j.type_name()));
    return j.get<std::string>();
  }

  std::vector<double> numbers(const json& j, const std::string& key) const {
    if (!j.is_array()) fail(key, "must be an array of numbers, got " + std::string(j.type_name()));
    std::vector<double> out;
    for (std::size_t i = 0; i < j.size(); ++i)
      out.push_back(number(j[i], key + "[" + std::to_string(i) + "]"));
    return out;
  }

  const std::string& path() const { return path_; }

 private:
  std::string path_;
};


// Resolves a frame's relative path inside the dataset folder (symlinks followed) and checks that
// it exists and does not escape the folder.
std::string resolve_frame_path(const Checker& c, const fs::path& root, const json& j,
                               const std::string& key) {
  const std::string rel = c.string(j, key);
  if (rel.empty()) c.fail(key, "empty path");
  // JSON may carry "\u0000"; the file system would see the path cut short there.
  if (rel.find('\0') != std::string::npos) c.fail(key, "path contains a NUL character");
  const fs::path p(rel);
  if (p.is_absolute() || p.has_root_name() || p.has_root_directory())
    c.fail(key, "'" + rel + "' must be a path relative to the dataset folder");
  std::error_code ec;
  const fs::path resolved = fs::weakly_canonical(root / p, ec);
  if (ec) c.fail(key, "'" + rel + "': " + ec.message());
  if (!path_is_inside(root, resolved)) c.fail(key, "'" + rel + "' escapes the dataset folder");
  if (!fs::exists(resolved, ec)) c.fail(key, "file '" + rel + "' not found");
  if (!fs::is_regular_file(resolved, ec)) c.fail(key, "'" + rel + "' is not a regular file");
  return resolved.string();
}

Intrinsics parse_intrinsics(const Checker& c, const json& j) {
  if (!j.is_object()) c.fail("intrinsics", "must be an object with fx, fy, cx, cy, width, height");
  Intrinsics k;
  k.fx = c.number(c.member(j, "fx", "intrinsics.fx"), "intrinsics.fx");
  k.fy = c.number(c.member(j, "fy", "intrinsics.fy"), "intrinsics.fy");
  k.cx = c.number(c.member(j, "cx", "intrinsics.cx"), "intrinsics.cx");
  k.cy = c.number(c.member(j, "cy", "intrinsics.cy"), "intrinsics.cy");
  k.width = c.integer(c.member(j, "width", "intrinsics.width"), "intrinsics.width");
  k.height = c.integer(c.member(j, "height", "intrinsics.height"), "intrinsics.height");
  if (!(k.fx > 0)) c.fail("intrinsics.fx", "must be > 0");
  if (!(k.fy > 0)) c.fail("intrinsics.fy", "must be > 0");
  const std::string range = "must be 1.." + std::to_string(kMaxImageSide);
  if (k.width <= 0 || k.width > kMaxImageSide) c.fail("intrinsics.width", range);
  if (k.height <= 0 || k.height > kMaxImageSide) c.fail("intrinsics.height", range);
  return k;
}

// 16 numbers, row-major camera-to-world; bottom row 0 0 0 1, rotation orthonormal (1e-3).
Eigen::Isometry3d parse_pose(const Checker& c, const json& j, const std::string& key) {
  const std::vector<double> m = c.numbers(j, key);
  if (m.size() != 16)
    c.fail(key, "must have 16 numbers (row-major 4x4), got " + std::to_string(m.size()));
  Eigen::Matrix4d t;
  for (int r = 0; r < 4; ++r)
    for (int col = 0; col < 4; ++col) t(r, col) = m[r * 4 + col];
  if (std::abs(t(3, 0)) > 1e-9 || std::abs(t(3, 1)) > 1e-9 || std::abs(t(3, 2)) > 1e-9 ||
      std::abs(t(3, 3) - 1.0) > 1e-9)
    c.fail(key, "bottom row must be 0 0 0 1");
  const Eigen::Matrix3d r = t.topLeftCorner<3, 3>();
  const double err = (r.transpose() * r - Eigen::Matrix3d::Identity()).cwiseAbs().maxCoeff();
  if (err > 1e-3)
    c.fail(key, "rotation is not orthonormal (max |R'R - I| = " + std::to_string(err) + ")");
  if (r.determinant() < 0) c.fail(key, "rotation is a reflection (determinant -1)");
  if (!(t.topRightCorner<3, 1>().cwiseAbs().maxCoeff() <= kMaxPoseTranslationM))
    c.fail(key, std::string("translation is out of range (|value| <= ") + kMaxPoseTranslationText + ")");
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  pose.linear() = r;
  pose.translation() = t.topRightCorner<3, 1>();
  return pose;
}

// Three numbers, the direction things fall in the camera frame (any length but zero).
Eigen::Vector3d parse_gravity(const Checker& c, const json& j, const std::string& key) {
  const std::vector<double> v = c.numbers(j, key);
  if (v.size() != 3) c.fail(key, "must have 3 numbers (x, y, z in the camera frame), got " + std::to_string(v.size()));
  const Eigen::Vector3d g(v[0], v[1], v[2]);
  if (!(g.norm() > 1e-9) || !std::isfinite(g.norm())) c.fail(key, "must be a non-zero direction");
  return g.normalized();
}

DatasetFrameRef parse_frame(const Checker& c, const fs::path& root, const json& j, std::size_t i) {
  const std::string key = "frames[" + std::to_string(i) + "]";
  if (!j.is_object()) c.fail(key, "must be an object");
  DatasetFrameRef f;
  f.raw = j;
  f.depth_path = resolve_frame_path(c, root, c.member(j, "depth", key + ".depth"), key + ".depth");
  if (j.contains("rgb")) f.rgb_path = resolve_frame_path(c, root, j["rgb"], key + ".rgb");
  if (j.contains("gt_surfaces"))
    f.gt_path = resolve_frame_path(c, root, j["gt_surfaces"], key + ".gt_surfaces");
  if (j.contains("pose")) f.pose = parse_pose(c, j["pose"], key + ".pose");
  if (j.contains("joints")) f.joints = c.numbers(j["joints"], key + ".joints");
  if (j.contains("gravity")) f.gravity = parse_gravity(c, j["gravity"], key + ".gravity");
  if (j.contains("timestamp")) f.timestamp_s = c.number(j["timestamp"], key + ".timestamp");
  return f;
}

Dataset read_dataset_json(const std::string& dir_or_json_path) {
  std::error_code ec;
  const fs::path given(dir_or_json_path);
  // exists() is false with an error for a symlink loop or a folder we may not enter.
  if (!fs::exists(given, ec))
    throw InputError(dir_or_json_path, ec ? "cannot access: " + ec.message() : "not found");
  const fs::path json_path = fs::is_directory(given, ec) ? given / "dataset.json" : given;
  if (!fs::exists(json_path, ec))
    throw InputError(dir_or_json_path, ec ? json_path.string() + ": cannot access: " + ec.message()
                                          : "folder has no dataset.json");

  Dataset d;
  d.json_path = json_path.string();
  const fs::path root = fs::weakly_canonical(fs::absolute(json_path).parent_path(), ec);
  if (ec) throw InputError(json_path.string(), "cannot resolve its folder: " + ec.message());
  d.dir = root.string();
  const Checker c(d.json_path);

  d.raw = read_json_file(d.json_path);
  const json& j = d.raw;
  if (!j.is_object()) c.fail("(top level)", "must be a JSON object");
  const std::string format = c.string(c.member(j, "format", "format"), "format");
  if (format != kDatasetFormat)
    c.fail("format", "is '" + format + "', expected '" + kDatasetFormat + "'");
  d.intrinsics = parse_intrinsics(c, c.member(j, "intrinsics", "intrinsics"));
  d.depth_scale = c.number(c.member(j, "depth_scale", "depth_scale"), "depth_scale");
  if (!(d.depth_scale > 0)) c.fail("depth_scale", "must be > 0 (depth units per metre)");

  if (j.contains("up")) {
    const std::vector<double> up = c.numbers(j["up"], "up");
    if (up.size() != 3) c.fail("up", "must have 3 numbers");
    d.up = Eigen::Vector3d(up[0], up[1], up[2]);
    if (!(d.up.norm() > 1e-9)) c.fail("up", "must not be the zero vector");
    if (!std::isfinite(d.up.norm())) c.fail("up", "is too long (its length overflows a double)");
    d.up.normalize();
  }

  const json& frames = c.member(j, "frames", "frames");
  if (!frames.is_array()) c.fail("frames", "must be an array");
  if (frames.empty()) c.fail("frames", "has no frames");
  if (frames.size() > kMaxDatasetFrames)
    c.fail("frames", "has " + std::to_string(frames.size()) + " frames, more than the " +
                         std::to_string(kMaxDatasetFrames) + " a dataset may hold");
  for (std::size_t i = 0; i < frames.size(); ++i) d.frames.push_back(parse_frame(c, root, frames[i], i));

  if (j.contains("robot")) d.robot = j["robot"];
  if (j.contains("ground_truth")) {
    d.ground_truth = j["ground_truth"];
    if (!d.ground_truth.is_object()) c.fail("ground_truth", "must be an object");
    if (d.ground_truth.contains("width_m"))
      d.gt_width_m = c.number(d.ground_truth["width_m"], "ground_truth.width_m");
    if (d.ground_truth.contains("height_m"))
      d.gt_height_m = c.number(d.ground_truth["height_m"], "ground_truth.height_m");
  }
  return d;
}

}  // namespace

Dataset read_dataset(const std::string& dir_or_json_path) {
  return read_dataset(dir_or_json_path, ReadOptions());
}

Dataset read_dataset(const std::string& dir_or_json_path, const ReadOptions& opt) {
  Dataset d = is_tum_sequence(dir_or_json_path) ? read_tum_sequence(dir_or_json_path, opt)
                                                : read_dataset_json(dir_or_json_path);
  if (opt.world_up) d.up = opt.world_up->normalized();
  d.max_image_pixels = opt.max_image_pixels;
  return d;
}

DepthFrame Dataset::load_frame(std::size_t i) const {
  if (i >= frames.size())
    throw InputError(json_path, "frame index " + std::to_string(i) + " out of range (" +
                                    std::to_string(frames.size()) + " frames)");
  const DatasetFrameRef& ref = frames[i];
  const std::string key = "frames[" + std::to_string(i) + "]";
  const auto size_text = [](int w, int h) { return std::to_string(w) + "x" + std::to_string(h); };
  // dataset.json frames are named by key, TUM frames by their list line.
  const auto fail = [&](const std::optional<ListOrigin>& origin, const std::string& field,
                        const std::string& problem) {
    if (origin)
      throw InputError(origin->file, "line " + std::to_string(origin->line) + ": " + problem);
    throw InputError(json_path, "key '" + key + "." + field + "': " + problem);
  };

  ReadOptions opt;
  opt.depth_units_per_m = depth_scale;
  opt.intrinsics = intrinsics;
  opt.max_image_pixels = max_image_pixels;
  DepthFrame f;
  try {
    f = read_depth_png(ref.depth_path, opt);
  } catch (const InputError& e) {
    fail(ref.depth_origin, "depth", e.what());
  }
  if (f.width != intrinsics.width || f.height != intrinsics.height)
    fail(ref.depth_origin, "depth", "image is " + size_text(f.width, f.height) +
                                        " but intrinsics say " +
                                        size_text(intrinsics.width, intrinsics.height));
  if (!ref.rgb_path.empty()) {
    int w = 0, h = 0;
    try {
      f.rgb = read_rgb_image(ref.rgb_path, w, h, max_image_pixels);
    } catch (const InputError& e) {
      fail(ref.rgb_origin, "rgb", e.what());
    }
    if (w != f.width || h != f.height)
      fail(ref.rgb_origin, "rgb", "image is " + size_text(w, h) + " but the depth image is " +
                                      size_text(f.width, f.height));
  }
  f.intrinsics = intrinsics;
  f.pose = ref.pose;
  f.joints = ref.joints;
  f.gravity = ref.gravity;
  f.timestamp_s = ref.timestamp_s;
  return f;
}

std::vector<std::uint16_t> Dataset::load_gt_surfaces(std::size_t i) const {
  if (i >= frames.size())
    throw InputError(json_path, "frame index " + std::to_string(i) + " out of range (" +
                                    std::to_string(frames.size()) + " frames)");
  const DatasetFrameRef& ref = frames[i];
  if (ref.gt_path.empty()) return {};
  const std::string key = "frames[" + std::to_string(i) + "].gt_surfaces";
  int w = 0, h = 0;
  std::vector<std::uint16_t> labels;
  try {
    labels = read_label_png(ref.gt_path, w, h, max_image_pixels);
  } catch (const InputError& e) {
    throw InputError(json_path, "key '" + key + "': " + e.what());
  }
  if (w != intrinsics.width || h != intrinsics.height)
    throw InputError(json_path, "key '" + key + "': image is " + std::to_string(w) + "x" +
                                    std::to_string(h) + " but intrinsics say " +
                                    std::to_string(intrinsics.width) + "x" +
                                    std::to_string(intrinsics.height));
  return labels;
}

}  // namespace tunnelmap
