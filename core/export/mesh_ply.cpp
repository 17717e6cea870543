#include "core/export/mesh_ply.h"

#include <sstream>

#include "core/export/ply_binary.h"
#include "core/util/atomic_file.h"

#ifndef TUNNELMAP_VERSION
#define TUNNELMAP_VERSION "unknown"
#endif

namespace tunnelmap {

void write_mesh_ply(const std::string& path, const TriangleMesh& mesh,
                    const nlohmann::json& params_json) {
  const std::size_t n = mesh.vertices.size();
  const bool normals = mesh.normals.size() == n, colors = mesh.colors.size() == n;
  std::ostringstream h;
  h.imbue(std::locale::classic());
  h << "ply\nformat binary_little_endian 1.0\ncomment tunnelmap " << TUNNELMAP_VERSION
    << " fused TSDF mesh (world frame, metres)\n";
  if (params_json.is_object())
    for (auto it = params_json.begin(); it != params_json.end(); ++it)
      h << "comment param " << it.key() << " " << it.value().dump() << "\n";
  h << "element vertex " << n << "\nproperty float x\nproperty float y\nproperty float z\n";
  if (normals) h << "property float nx\nproperty float ny\nproperty float nz\n";
  if (colors) h << "property uchar red\nproperty uchar green\nproperty uchar blue\n";
  h << "element face " << mesh.triangles.size() << "\nproperty list uchar int vertex_indices\n"
    << "end_header\n";
  const std::string header = h.str();
  write_file_atomically(path, [&](std::ostream& out) {
    out.write(header.data(), static_cast<std::streamsize>(header.size()));
    for (std::size_t i = 0; i < n; ++i) {
      for (int k = 0; k < 3; ++k) ply::put_f32(out, mesh.vertices[i][k]);
      if (normals)
        for (int k = 0; k < 3; ++k) ply::put_f32(out, mesh.normals[i][k]);
      if (colors)
        for (int k = 0; k < 3; ++k) ply::put_u8(out, mesh.colors[i][k]);
    }
    for (const auto& t : mesh.triangles) {
      ply::put_u8(out, 3);
      for (int k = 0; k < 3; ++k) ply::put_i32(out, t[k]);
    }
  });
}

}  // namespace tunnelmap
