#include "core/io/dataset_writer.h"

#include <algorithm>
#include <cctype>

#include "core/io/dataset_json_writer.h"
#include "core/io/output_folder.h"
#include "core/util/error.h"

namespace tunnelmap {

namespace fs = std::filesystem;
using nlohmann::json;

namespace {

std::string lower_extension(const std::string& path, const char* fallback) {
  std::string e = fs::path(path).extension().string();
  std::transform(e.begin(), e.end(), e.begin(), [](unsigned char c) { return std::tolower(c); });
  return e.empty() ? fallback : e;
}

}  // namespace

void write_dataset_folder(const Dataset& ds, const std::string& out_dir, const SequenceExport& ex) {
  const std::size_t n = ds.frames.size();
  if (n == 0) throw InputError(ds.json_path, "the dataset has no frames");
  StagedFolder out(out_dir);
  make_folder(out.path() / "depth");
  json frames = json::array();
  bool joints_dropped = false;
  for (std::size_t i = 0; i < n; ++i) {
    const DatasetFrameRef& ref = ds.frames[i];
    ds.load_frame(i);  // validates depth and colour
    const std::string stem = dataset_frame_file(i, "");
    json f = {{"depth", "depth/" + stem + ".png"}};
    copy_file_to(ref.depth_path, out.path() / f["depth"].get<std::string>());
    if (!ref.rgb_path.empty()) {
      make_folder(out.path() / "rgb");
      f["rgb"] = "rgb/" + stem + lower_extension(ref.rgb_path, ".png");
      copy_file_to(ref.rgb_path, out.path() / f["rgb"].get<std::string>());
    }
    if (!ref.gt_path.empty()) {
      ds.load_gt_surfaces(i);
      make_folder(out.path() / "gt");
      f["gt_surfaces"] = "gt/" + stem + ".png";
      copy_file_to(ref.gt_path, out.path() / f["gt_surfaces"].get<std::string>());
    }
    const std::optional<Eigen::Isometry3d>& pose = ex.poses.empty() ? ref.pose : ex.poses[i];
    if (pose) f["pose"] = dataset_pose_json(*pose);
    joints_dropped = joints_dropped || !ref.joints.empty();
    if (ref.gravity) f["gravity"] = dataset_vector_json(*ref.gravity);
    f["timestamp"] = ref.timestamp_s;
    frames.push_back(f);
    if (ex.progress) ex.progress(i, n, (out.target() / f["depth"].get<std::string>()).string());
  }
  json doc = dataset_document(ds.intrinsics, ds.depth_scale, ds.up, std::move(frames));
  if (ds.ground_truth.is_object()) doc["ground_truth"] = ds.ground_truth;
  write_dataset_json(out.path(), doc);
  out.commit();
  if (ex.note && joints_dropped)
    ex.note(out.target().string() + ": arm joints are not kept; frames carry their poses instead");
}

}  // namespace tunnelmap
