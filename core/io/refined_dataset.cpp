#include "core/io/refined_dataset.h"

#include <filesystem>

#include "core/io/output_folder.h"
#include "core/kinematics/robot_json.h"
#include "core/util/atomic_file.h"
#include "core/util/error.h"

namespace tunnelmap {

namespace fs = std::filesystem;

namespace {

// Hard link, else copy: the images are large and stay unchanged.
void link_or_copy(const fs::path& from, const fs::path& to) {
  std::error_code ec;
  fs::create_directories(to.parent_path(), ec);
  if (ec) throw InputError(to.parent_path().string(), "cannot create folder: " + ec.message());
  fs::create_hard_link(from, to, ec);
  if (!ec) return;
  fs::copy_file(from, to, fs::copy_options::overwrite_existing, ec);
  if (ec) throw InputError(to.string(), "cannot copy " + from.string() + ": " + ec.message());
}

}  // namespace

void write_dataset_with_poses(const Dataset& ds, const std::vector<Eigen::Isometry3d>& poses,
                              const std::string& out_dir) {
  if (poses.size() != ds.frames.size())
    throw InputError(out_dir, "internal: one pose per frame expected");
  std::error_code ec;  // never over a dataset, not even one we wrote: it may be the input
  if (fs::exists(out_dir, ec) && !(fs::is_directory(out_dir, ec) && fs::is_empty(out_dir, ec)))
    throw InputError(out_dir, "the refined dataset's folder must be new or empty");
  StagedFolder staged(out_dir);  // whole or nothing, beside the target
  const fs::path out = staged.path();
  {
    // A dataset.json keeps everything it had (ground truth, robot, simulator); another layout
    // gets the keys every reader needs.
    const bool from_json = ds.raw.is_object() && ds.raw.contains("frames") &&
                           ds.raw["frames"].is_array() && ds.raw["frames"].size() == ds.frames.size();
    nlohmann::json doc = from_json ? ds.raw : nlohmann::json::object();
    if (!from_json) {
      const Intrinsics& K = ds.intrinsics;
      doc["format"] = kDatasetFormat;
      doc["intrinsics"] = {{"fx", K.fx}, {"fy", K.fy}, {"cx", K.cx}, {"cy", K.cy},
                           {"width", K.width}, {"height", K.height}};
      doc["depth_scale"] = ds.depth_scale;
      doc["up"] = {ds.up.x(), ds.up.y(), ds.up.z()};
      doc["frames"] = nlohmann::json::array();
    }
    for (std::size_t i = 0; i < ds.frames.size(); ++i) {
      const DatasetFrameRef& ref = ds.frames[i];
      if (!from_json) doc["frames"].push_back({{"timestamp", ref.timestamp_s}});
      nlohmann::json& f = doc["frames"][i];
      const std::pair<const char*, const std::string*> files[] = {
          {"depth", &ref.depth_path}, {"rgb", &ref.rgb_path}, {"gt_surfaces", &ref.gt_path}};
      for (const auto& [key, path] : files) {
        if (path->empty()) continue;
        const std::string rel = f.contains(key) && f[key].is_string()
                                    ? f[key].get<std::string>()
                                    : std::string(key) + "/" + fs::path(*path).filename().string();
        link_or_copy(*path, out / rel);
        f[key] = rel;
      }
      f["pose"] = isometry_to_json(poses[i]);
    }
    write_file_atomically((out / "dataset.json").string(),
                          [&](std::ostream& o) { o << doc.dump(2) << "\n"; });
  }
  staged.commit();
}

}  // namespace tunnelmap
