#pragma once
// Writes a TunnelMap as a coloured triangle mesh (binary little-endian PLY) for MeshLab, VTK, PCL.
#include <Eigen/Geometry>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "core/export/plate_mesh.h"
#include "core/tunnel/tunnel_map.h"

namespace tunnelmap {

// Face labels of the map mesh (uchar `label` face property).
// Plate: a plate across the tunnel (a diaphragm with its manhole cut out; wall 4).
enum class MapFaceLabel : unsigned char { Boundary = 0, Traversable = 1, Forbidden = 2, Plate = 3 };

// Width of the blue border band drawn inside each wall's boundary rectangle.
constexpr double kMapBorderBandM = 0.01;

// For each found wall: its zone rectangles (forbidden orange, traversable red, two triangles
// each) and its boundary as a thin blue band of 4 quads just inside Wall::boundary.
// Vertex: x y z (float), red green blue (uchar). Face: vertex_indices (list uchar int),
// label (uchar, MapFaceLabel), wall (uchar, WallClass). Header comments carry the tool version,
// the tunnel size and one "param <key> <value>" per entry of `params_json` (an object).
// Points are mapped through `to_world`. Written atomically; InputError on failure.
void write_map_ply(const std::string& path, const TunnelMap& map, const nlohmann::json& params_json,
                   const Eigen::Isometry3d& to_world = Eigen::Isometry3d::Identity());

// The map of a tunnel whose cross-section changes: one swept rectangle per section (each map's
// walls and zones, already in the world frame), in one mesh, and the plates across it with their
// openings (grey, label Plate). The header gives the section count and each section's width and
// height ("comment section <i> <width_m> <height_m>") and the plate count ("comment plates <n>").
void write_sectioned_map_ply(const std::string& path, const std::vector<TunnelMap>& sections,
                             const nlohmann::json& params_json, const std::vector<PlateOutline>& plates = {});

}  // namespace tunnelmap
