#include "core/fusion/mesh_pieces_writer.h"

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <random>

#include "core/export/mesh_ply.h"
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
  std::error_code ec;
  if (fs::exists(dir, ec) && !(fs::is_directory(dir, ec) && fs::is_empty(dir, ec)))
    throw InputError(dir, "the pieces' folder must be new or empty");
  const fs::path final_dir = fs::absolute(dir).lexically_normal();
  const fs::path tmp = final_dir.parent_path() /
                       (final_dir.filename().string() + ".tmp-" + std::to_string(std::random_device()()));
  if (!fs::create_directory(tmp, ec)) throw InputError(dir, "cannot create the folder: " + ec.message());
  try {
    for (std::size_t i = 0; i < pieces.size(); ++i)
      write_mesh_ply((tmp / piece_file(i)).string(), pieces[i].mesh, params_json);
    std::ofstream out(tmp / "pieces.json");
    out << index_json(pieces, info).dump(2) << "\n";
    if (!out) throw InputError((fs::path(dir) / "pieces.json").string(), "cannot write the index");
    out.close();
    if (fs::exists(final_dir, ec)) fs::remove(final_dir, ec);  // new or empty: checked above
    fs::rename(tmp, final_dir, ec);
    if (ec) throw InputError(dir, "cannot move the pieces into place: " + ec.message());
  } catch (...) {
    fs::remove_all(tmp, ec);
    throw;
  }
}

}  // namespace tunnelmap
