// libFuzzer target: the PLY mesh reader, straight from memory.
#include <cstdint>
#include <cstdlib>

#include "core/io/ply_mesh_reader.h"
#include "core/util/error.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace tunnelmap;
  try {
    const PlyMesh m = parse_ply_mesh(data, size, "fuzz.ply");
    // What the GUI relies on when it builds the vtkPolyData.
    for (const auto& t : m.triangles)
      for (std::int32_t v : t)
        if (v < 0 || static_cast<std::size_t>(v) >= m.vertices.size()) std::abort();
    if (!m.normals.empty() && m.normals.size() != m.vertices.size()) std::abort();
    if (!m.colors.empty() && m.colors.size() != m.vertices.size()) std::abort();
    if (!m.face_labels.empty() && m.face_labels.size() != m.triangles.size()) std::abort();
  } catch (const InputError&) {
  }
  return 0;
}
