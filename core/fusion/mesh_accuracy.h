#pragma once
// Accuracy of a fused mesh against known planar surfaces (the simulator's ground truth): each
// vertex's distance to the nearest surface plane. Planes are unbounded, so this measures
// surface noise and misregistration, not holes; rivets (<= 6 mm domes) and the plate steps
// are within a few mm of a plane by construction.
#include <Eigen/Geometry>
#include <nlohmann/json.hpp>
#include <vector>

#include "core/fusion/triangle_mesh.h"

namespace tunnelmap {

struct PlaneRef {
  Eigen::Vector3d normal;  // unit
  double offset = 0.0;     // normal.dot(x) + offset = 0
};

struct MeshAccuracy {
  std::size_t vertices = 0;
  double fraction_within = 0.0;  // of vertices within the tolerance
  double median_m = 0.0, p95_m = 0.0, rms_m = 0.0;
};

// `mesh_to_planes` moves the vertices first (without copying a mesh of millions of vertices).
MeshAccuracy mesh_accuracy(const TriangleMesh& mesh, const std::vector<PlaneRef>& planes,
                           double tolerance_m = 0.010,
                           const Eigen::Isometry3d& mesh_to_planes = Eigen::Isometry3d::Identity());

// The rigid motion that best lays the mesh onto the planes (point-to-plane ICP, each vertex
// against its nearest plane within `max_distance_m`): what a fused map is worth up to where the
// whole sequence sits in the world. `mesh_accuracy(transformed mesh, planes)` then measures the
// map's internal consistency.
Eigen::Isometry3d align_mesh_to_planes(const TriangleMesh& mesh, const std::vector<PlaneRef>& planes,
                                       double max_distance_m = 0.05, int iterations = 20);
TriangleMesh transformed(const TriangleMesh& mesh, const Eigen::Isometry3d& T);

// The planes of a dataset's "ground_truth.surfaces" (empty when there are none).
std::vector<PlaneRef> ground_truth_planes(const nlohmann::json& ground_truth);

}  // namespace tunnelmap
