#include "core/io/tum_sequence.h"
#include "core/io/path_inside.h"

#include <cmath>
#include <cstdio>
#include <filesystem>

#include "core/io/depth_png.h"
#include "core/io/tum_associate.h"
#include "core/io/tum_camera.h"
#include "core/io/tum_list.h"
#include "core/io/tum_sidecar.h"
#include "core/util/error.h"

namespace tunnelmap {

namespace fs = std::filesystem;

namespace {


// The same path rules as dataset.json: relative, inside the folder after resolving links,
// an existing regular file. Errors name the list and the line.
std::string resolve_listed(const fs::path& root, const std::string& list, const TumFileEntry& e) {
  const auto fail = [&](const std::string& problem) {
    throw InputError(list, "line " + std::to_string(e.line) + ": " + problem);
  };
  const fs::path p(e.path);
  if (p.is_absolute() || p.has_root_name() || p.has_root_directory())
    fail("'" + e.path + "' must be a path relative to the sequence folder");
  std::error_code ec;
  const fs::path resolved = fs::weakly_canonical(root / p, ec);
  if (ec) fail("'" + e.path + "': " + ec.message());
  if (!path_is_inside(root, resolved)) fail("'" + e.path + "' escapes the sequence folder");
  if (!fs::exists(resolved, ec)) fail("file '" + e.path + "' not found");
  if (!fs::is_regular_file(resolved, ec)) fail("'" + e.path + "' is not a regular file");
  return resolved.string();
}

std::vector<double> times_of(const std::vector<TumFileEntry>& list) {
  std::vector<double> t;
  for (const TumFileEntry& e : list) t.push_back(e.timestamp_s);
  return t;
}

Intrinsics choose_intrinsics(const fs::path& root, const std::string& depth_list,
                             const std::string& first_depth, const TumSidecar& sidecar,
                             const ReadOptions& opt) {
  if (opt.intrinsics) {
    // The size comes from the images, as for a single depth PNG.
    const PngHeader h = parse_png_header(read_file_bytes(first_depth, 64u << 20), first_depth, opt.max_image_pixels);
    return intrinsics_for_image(opt, h.width, h.height);
  }
  if (sidecar.intrinsics) return *sidecar.intrinsics;
  if (const auto cam = tum_camera_from_folder_name(root.filename().string())) return cam->intrinsics;
  throw InputError(depth_list, "no camera intrinsics: the folder name '" + root.filename().string() +
                                   "' names no TUM camera (rgbd_dataset_freiburg1/2/3_*) and no "
                                   "--intrinsics FX,FY,CX,CY was given");
}

std::string seconds_text(double s) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%g s", s);
  return buf;
}

// "frames 3, 5, 9 and 4 more"
std::string frame_list(const std::vector<std::size_t>& frames) {
  std::string s = frames.size() == 1 ? "frame " : "frames ";
  for (std::size_t k = 0; k < frames.size() && k < 5; ++k) s += (k ? ", " : "") + std::to_string(frames[k]);
  if (frames.size() > 5) s += " and " + std::to_string(frames.size() - 5) + " more";
  return s;
}

}  // namespace

bool is_tum_sequence(const std::string& path) {
  std::error_code ec;
  const fs::path p(path);
  if (fs::is_directory(p, ec))
    return !fs::exists(p / "dataset.json", ec) && fs::is_regular_file(p / "depth.txt", ec);
  return p.filename() == "depth.txt" && fs::is_regular_file(p, ec);
}

Dataset read_tum_sequence(const std::string& path, const ReadOptions& opt) {
  if (!(opt.max_time_diff_s >= 0) || !std::isfinite(opt.max_time_diff_s))
    throw ParameterError("the maximum time difference must be a number of seconds >= 0");
  std::error_code ec;
  const fs::path given(path);
  if (!fs::exists(given, ec)) throw InputError(path, ec ? "cannot access: " + ec.message() : "not found");
  const fs::path folder = fs::is_directory(given, ec) ? given : given.parent_path();
  const fs::path root = fs::weakly_canonical(fs::absolute(folder), ec);
  if (ec) throw InputError(path, "cannot resolve the folder: " + ec.message());

  Dataset d;
  d.dir = root.string();
  d.json_path = (root / "depth.txt").string();
  const std::string rgb_list = (root / "rgb.txt").string();
  const std::string gt_list = (root / "groundtruth.txt").string();
  const std::string sidecar_path = (root / kTumSidecarName).string();

  const std::vector<TumFileEntry> depth = read_tum_file_list(d.json_path);
  if (depth.empty()) throw InputError(d.json_path, "lists no depth images");
  const bool has_rgb = fs::exists(rgb_list, ec);
  const bool has_gt = fs::exists(gt_list, ec);
  const std::vector<TumFileEntry> rgb = has_rgb ? read_tum_file_list(rgb_list) : std::vector<TumFileEntry>{};
  const std::vector<TumPoseEntry> gt = has_gt ? read_tum_groundtruth(gt_list) : std::vector<TumPoseEntry>{};
  const TumSidecar sidecar = fs::exists(sidecar_path, ec) ? read_tum_sidecar(sidecar_path) : TumSidecar{};

  std::vector<std::string> depth_paths, rgb_paths;
  for (const TumFileEntry& e : depth) depth_paths.push_back(resolve_listed(root, d.json_path, e));
  for (const TumFileEntry& e : rgb) rgb_paths.push_back(resolve_listed(root, rgb_list, e));

  d.intrinsics = choose_intrinsics(root, d.json_path, depth_paths.front(), sidecar, opt);
  d.depth_scale = opt.depth_scale_given ? opt.depth_units_per_m : kTumDepthScale;
  if (!(d.depth_scale > 0)) throw ParameterError("the depth scale must be > 0 units per metre");
  d.up = opt.world_up ? opt.world_up->normalized() : sidecar.up.value_or(Eigen::Vector3d::UnitZ());
  if (sidecar.ground_truth.is_object()) {
    d.ground_truth = sidecar.ground_truth;
    if (d.ground_truth.contains("width_m")) d.gt_width_m = d.ground_truth["width_m"].get<double>();
    if (d.ground_truth.contains("height_m")) d.gt_height_m = d.ground_truth["height_m"].get<double>();
  }

  const double max_dt = opt.max_time_diff_s;
  const std::vector<int> rgb_match = associate_nearest(times_of(depth), times_of(rgb), max_dt);
  std::vector<std::size_t> no_rgb, no_pose;
  for (std::size_t i = 0; i < depth.size(); ++i) {
    DatasetFrameRef f;
    f.depth_path = depth_paths[i];
    f.timestamp_s = depth[i].timestamp_s;
    f.depth_origin = ListOrigin{d.json_path, depth[i].line};
    f.raw = {{"depth", depth[i].path}, {"timestamp", depth[i].timestamp_s}};
    const std::string which = "frame " + std::to_string(i) + " (" + depth[i].path + ", depth.txt line " +
                              std::to_string(depth[i].line) + ")";
    if (rgb_match[i] >= 0) {
      const auto j = static_cast<std::size_t>(rgb_match[i]);
      f.rgb_path = rgb_paths[j];
      f.rgb_origin = ListOrigin{rgb_list, rgb[j].line};
      f.raw["rgb"] = rgb[j].path;
    } else if (has_rgb) {
      no_rgb.push_back(i);
      d.unmatched.notes.push_back(which + ": no colour image within " + seconds_text(max_dt));
    }
    if (const auto g = sidecar.gravity.find(depth[i].path); g != sidecar.gravity.end()) f.gravity = g->second;
    f.pose = interpolate_pose(gt, f.timestamp_s, max_dt);
    if (!f.pose && has_gt) {
      no_pose.push_back(i);
      d.unmatched.notes.push_back(which + ": no ground truth within " + seconds_text(max_dt));
    }
    d.frames.push_back(std::move(f));
  }
  d.unmatched.rgb = no_rgb.size();
  d.unmatched.pose = no_pose.size();

  if (opt.note && (!no_rgb.empty() || !no_pose.empty())) {
    const std::string total = std::to_string(depth.size());
    std::string s = d.json_path + ": ";
    if (!no_rgb.empty())
      s += std::to_string(no_rgb.size()) + " of " + total + " depth frames have no colour image within " +
           seconds_text(max_dt) + " (" + frame_list(no_rgb) + ")";
    if (!no_pose.empty())
      s += std::string(no_rgb.empty() ? "" : "; ") + std::to_string(no_pose.size()) + " of " + total +
           " have no ground-truth pose within " + seconds_text(max_dt) + " (" + frame_list(no_pose) + ")";
    opt.note(s);
  }
  return d;
}

}  // namespace tunnelmap
