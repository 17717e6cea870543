#pragma once
// Writes mesh pieces as a folder: one binary PLY per piece (piece_000.ply, ...) and an index,
// pieces.json, with each piece's station range and world box. The folder is filled beside its
// final name and renamed into place, so a failed run leaves no partial folder.
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "core/fusion/mesh_pieces.h"

namespace tunnelmap {

struct PieceIndexInfo {
  std::string cut_by;              // "diaphragms" or "length"
  nlohmann::json piece_length_m;   // null when cut at the diaphragms
  std::vector<double> cuts_m;
  StationAxis axis;
  nlohmann::json header;           // merged into the index (tool, input, params)
};

// `dir` must be new or empty (InputError otherwise, or when it cannot be written).
void write_mesh_pieces(const std::string& dir, const std::vector<MeshPiece>& pieces,
                       const PieceIndexInfo& info, const nlohmann::json& params_json);

}  // namespace tunnelmap
