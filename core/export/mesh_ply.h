#pragma once
// Writes a TriangleMesh as binary little-endian PLY: vertex x y z nx ny nz (float) red green
// blue (uchar), face vertex_indices (list uchar int). Header comments carry the tool version
// and one "param <key> <value>" per entry of `params_json`. Atomic; InputError on failure.
#include <nlohmann/json.hpp>
#include <string>

#include "core/fusion/triangle_mesh.h"

namespace tunnelmap {

void write_mesh_ply(const std::string& path, const TriangleMesh& mesh,
                    const nlohmann::json& params_json = nlohmann::json::object());

}  // namespace tunnelmap
