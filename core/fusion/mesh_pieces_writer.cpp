#include "core/fusion/mesh_pieces_writer.h"

#include <cstdio>
#include <filesystem>

#include "core/export/mesh_ply.h"
#include "core/io/output_folder.h"
#include "core/util/atomic_file.h"
#include "core/util/error.h"

namespace tunnelmap {

namespace fs = std::filesystem;

namespace {

nlohmann::json vec(const Eigen::Vector3d& v) { return {v.x(), v.y(), v.z()}; }

std::string piece_file(std::size_t i) {
  char name[32];
  std::snprintf(name, sizeof name, "piece_%03zu.ply", i);
  return name;
}

nlohmann::json index_json(const std::vector<MeshPiece>& pieces, const PieceIndexInfo& info) {
  nlohmann::json list = nlohmann::json::array();
  for (std::size_t i = 0; i < pieces.size(); ++i) {
    const MeshPiece& p = pieces[i];
    list.push_back({{"file", piece_file(i)},
                    {"from_m", p.from_m},
                    {"to_m", p.to_m},
                    {"bounds", {{"min", vec(p.bounds.min())}, {"max", vec(p.bounds.max())}}},
                    {"vertices", p.mesh.vertices.size()},
                    {"triangles", p.mesh.triangles.size()}});
  }
  nlohmann::json doc = info.header.is_object() ? info.header : nlohmann::json::object();
  doc["axis"] = {{"point", vec(info.axis.point)}, {"direction", vec(info.axis.direction)}};
  doc["cut_by"] = info.cut_by;
  doc["piece_length_m"] = info.piece_length_m;
  doc["cuts_m"] = info.cuts_m;
  doc["pieces"] = list;
  return doc;
}

}  // namespace

void write_mesh_pieces(const std::string& dir, const std::vector<MeshPiece>& pieces,
                       const PieceIndexInfo& info, const nlohmann::json& params_json) {
  StagedFolder out(dir);  // whole or nothing, beside the target
  for (std::size_t i = 0; i < pieces.size(); ++i)
    write_mesh_ply((out.path() / piece_file(i)).string(), pieces[i].mesh, params_json);
  write_file_atomically((out.path() / "pieces.json").string(),
                        [&](std::ostream& index) { index << index_json(pieces, info).dump(2) << "\n"; });
  out.commit();
}

}  // namespace tunnelmap
