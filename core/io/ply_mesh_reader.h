#pragma once
// Strict reader for the PLY files our exporters write (core/export/*_ply.*): ascii or
// binary_little_endian, a vertex element with x y z (optional nx ny nz, red green blue, an
// integer "plane" or "label"), an optional face element with a vertex_indices list (optional
// uchar-like "label" and "wall"). Written because VTK's reader crashes on hostile input: every
// count is checked against the file size before anything is allocated.
#include <Eigen/Core>
#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace tunnelmap {

// Largest PLY file accepted (read into memory whole).
constexpr std::size_t kMaxPlyFileBytes = std::size_t(1) << 30;
// Longest polygon accepted in a face list (faces are fan-triangulated).
constexpr int kMaxPlyPolygonVertices = 64;

struct PlyMesh {
  std::vector<Eigen::Vector3f> vertices;
  std::vector<Eigen::Vector3f> normals;                 // empty, or one per vertex
  std::vector<std::array<std::uint8_t, 3>> colors;      // empty, or one per vertex
  std::vector<std::int32_t> vertex_labels;              // "plane"/"label" per vertex, or empty
  std::vector<std::array<std::int32_t, 3>> triangles;   // indices into vertices
  std::vector<std::int32_t> face_labels, face_walls;    // per triangle, or empty
  std::vector<std::string> comments;                    // header comment lines, as written
};

// Throws InputError(path, problem) for a missing/unreadable file or any violation.
PlyMesh read_ply_mesh(const std::string& path);

// Same, from memory; `name` is the file named in errors.
PlyMesh parse_ply_mesh(const std::uint8_t* data, std::size_t size, const std::string& name);

}  // namespace tunnelmap
