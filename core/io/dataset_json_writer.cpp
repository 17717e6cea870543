#include "core/io/dataset_json_writer.h"

#include <cstdio>
#include <utility>

#include "core/io/dataset.h"
#include "core/util/atomic_file.h"

namespace tunnelmap {

using nlohmann::json;

json dataset_pose_json(const Eigen::Isometry3d& pose) {
  json a = json::array();
  const Eigen::Matrix4d m = pose.matrix();
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 4; ++c) a.push_back(m(r, c));
  for (const double bottom : {0.0, 0.0, 0.0, 1.0}) a.push_back(bottom);  // exact, whatever was stored
  return a;
}

json dataset_vector_json(const Eigen::Vector3d& v) { return json::array({v.x(), v.y(), v.z()}); }

std::string dataset_frame_file(std::size_t index, const std::string& extension) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%06zu", index);
  return buf + extension;
}

json dataset_document(const Intrinsics& K, double depth_scale, const Eigen::Vector3d& up, json frames) {
  return {{"format", kDatasetFormat},
          {"intrinsics",
           {{"fx", K.fx}, {"fy", K.fy}, {"cx", K.cx}, {"cy", K.cy}, {"width", K.width}, {"height", K.height}}},
          {"depth_scale", depth_scale},
          {"up", dataset_vector_json(up)},
          {"frames", std::move(frames)}};
}

void write_dataset_json(const std::filesystem::path& folder, const json& document) {
  write_file_atomically((folder / "dataset.json").string(),
                        [&](std::ostream& out) { out << document.dump(2) << "\n"; });
}

}  // namespace tunnelmap
