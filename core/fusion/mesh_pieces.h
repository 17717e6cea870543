#pragma once
// A long fused mesh cut into pieces along the tunnel (at the diaphragms, or every N metres),
// so that a viewer can open one compartment at a time. Each triangle goes to the piece that
// holds its centroid's station; a vertex on a cut is in both pieces, so the pieces together
// hold exactly the vertices and triangles of the whole mesh.
#include <Eigen/Geometry>
#include <vector>

#include "core/fusion/triangle_mesh.h"

namespace tunnelmap {

struct StationAxis {
  Eigen::Vector3d point = Eigen::Vector3d::Zero();      // station 0
  Eigen::Vector3d direction = Eigen::Vector3d::UnitX();  // unit
  double station(const Eigen::Vector3f& p) const { return direction.dot(p.cast<double>() - point); }
};

struct MeshPiece {
  double from_m = 0.0, to_m = 0.0;  // stations of its vertices, lowest and highest
  Eigen::AlignedBox3d bounds;       // world box of its vertices
  TriangleMesh mesh;
};

// Cuts at `cuts` (stations, any order); pieces without triangles are left out, the rest come
// in station order.
std::vector<MeshPiece> split_mesh(const TriangleMesh& mesh, const StationAxis& axis,
                                  std::vector<double> cuts);

// Cuts every `length_m` from the mesh's lowest station.
std::vector<double> regular_cuts(const TriangleMesh& mesh, const StationAxis& axis, double length_m);

// The direction the vertices spread most along (their principal axis), through their mean.
StationAxis principal_axis(const TriangleMesh& mesh);

}  // namespace tunnelmap
