#pragma once
// TriangleMesh: an indexed, coloured triangle mesh with per-vertex normals (world frame, metres).
#include <Eigen/Core>
#include <array>
#include <cstdint>
#include <vector>

namespace tunnelmap {

struct TriangleMesh {
  std::vector<Eigen::Vector3f> vertices;
  std::vector<Eigen::Vector3f> normals;               // unit; empty or one per vertex
  std::vector<std::array<std::uint8_t, 3>> colors;    // RGB; empty or one per vertex
  std::vector<std::array<std::int32_t, 3>> triangles;

  bool empty() const { return triangles.empty(); }
};

}  // namespace tunnelmap
