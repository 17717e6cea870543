// The PLY mesh reader: round trips with our map, mesh and planes exporters, ascii polygons,
// hostile and truncated files.
#include <gtest/gtest.h>

#include <array>
#include <cstdint>
#include <nlohmann/json.hpp>
#include <random>
#include <string>
#include <vector>

#include "core/export/map_ply.h"
#include "core/export/mesh_ply.h"
#include "core/export/planes_ply.h"
#include "core/io/ply_mesh_reader.h"
#include "core/util/error.h"
#include "tests/support/expect_input_error.h"
#include "tests/support/io_temp_dir.h"

namespace tunnelmap {
namespace {

using testing::IoTempDir;
using testing::expect_input_error;
using nlohmann::json;

TunnelMap one_wall_map() {
  TunnelMap m;
  m.detected = true;
  m.status = TunnelStatus::Ok;
  m.width_m = 0.8;
  m.height_m = 1.3;
  Wall& w = m.wall(WallClass::Top);
  w.found = true;
  w.boundary = {Eigen::Vector3d(0, 0, 1), Eigen::Vector3d(0.8, 0, 1), Eigen::Vector3d(0.8, 0, 3),
                Eigen::Vector3d(0, 0, 3)};
  w.zones.push_back({ZoneKind::Forbidden, {Eigen::Vector3d(0, 0, 1), Eigen::Vector3d(0.2, 0, 1),
                                           Eigen::Vector3d(0.2, 0, 3), Eigen::Vector3d(0, 0, 3)}});
  w.zones.push_back({ZoneKind::Traversable, {Eigen::Vector3d(0.2, 0, 1), Eigen::Vector3d(0.8, 0, 1),
                                             Eigen::Vector3d(0.8, 0, 3), Eigen::Vector3d(0.2, 0, 3)}});
  return m;
}

TEST(PlyMeshReader, ReadsOurMapPlyBack) {
  IoTempDir tmp;
  const std::string path = tmp.file("map.ply");
  write_map_ply(path, one_wall_map(), json{{"grow.angle_deg", 4.0}});
  const PlyMesh m = read_ply_mesh(path);
  // 2 zones + 4 border quads, 4 vertices and 2 triangles each.
  ASSERT_EQ(m.vertices.size(), 24u);
  ASSERT_EQ(m.triangles.size(), 12u);
  ASSERT_EQ(m.colors.size(), 24u);
  ASSERT_EQ(m.face_labels.size(), 12u);
  ASSERT_EQ(m.face_walls.size(), 12u);
  EXPECT_TRUE(m.normals.empty());
  EXPECT_TRUE((m.vertices[0] - Eigen::Vector3f(0, 0, 1)).norm() < 1e-6f);
  EXPECT_TRUE((m.vertices[5] - Eigen::Vector3f(0.8f, 0, 1)).norm() < 1e-6f);
  EXPECT_EQ(m.colors[0], (std::array<std::uint8_t, 3>{255, 140, 0}));   // forbidden orange
  EXPECT_EQ(m.colors[4], (std::array<std::uint8_t, 3>{220, 30, 30}));   // traversable red
  EXPECT_EQ(m.face_labels[0], int(MapFaceLabel::Forbidden));
  EXPECT_EQ(m.face_labels[2], int(MapFaceLabel::Traversable));
  EXPECT_EQ(m.face_labels[4], int(MapFaceLabel::Boundary));
  for (int w : m.face_walls) EXPECT_EQ(w, int(WallClass::Top));
  EXPECT_EQ(m.triangles[3], (std::array<std::int32_t, 3>{4, 6, 7}));
  bool has_param = false;
  for (const auto& c : m.comments) has_param |= c == "param grow.angle_deg 4";
  EXPECT_TRUE(has_param);
}

TEST(PlyMeshReader, ReadsOurFusedMeshAndPlanesPlyBack) {
  IoTempDir tmp;
  TriangleMesh mesh;
  for (int i = 0; i < 5; ++i) {
    mesh.vertices.emplace_back(0.5f * i, -1.25f * i, 3.f + i);
    mesh.normals.emplace_back(0, 0, 1);
    mesh.colors.push_back({std::uint8_t(10 * i), 20, std::uint8_t(250 - i)});
  }
  mesh.triangles = {{0, 1, 2}, {2, 3, 4}, {4, 0, 1}};
  write_mesh_ply(tmp.file("mesh.ply"), mesh);
  const PlyMesh m = read_ply_mesh(tmp.file("mesh.ply"));
  ASSERT_EQ(m.vertices.size(), 5u);
  for (int i = 0; i < 5; ++i) {
    EXPECT_EQ(m.vertices[i], mesh.vertices[i]);
    EXPECT_EQ(m.normals[i], mesh.normals[i]);
    EXPECT_EQ(m.colors[i], mesh.colors[i]);
  }
  EXPECT_EQ(m.triangles, mesh.triangles);

  OrganizedCloud cloud;
  cloud.width = 3;
  cloud.height = 1;
  cloud.points = {{0.1f, 0.2f, 1.f}, {0.3f, 0.4f, 2.f}, {0.5f, 0.6f, 3.f}};
  PlaneSegments planes;
  planes.width = 3;
  planes.height = 1;
  planes.planes.resize(1);
  planes.planes[0].id = 7;
  planes.labels = {7, 0, 7};
  write_planes_ply(tmp.file("planes.ply"), cloud, planes, {WallClass::Left});
  const PlyMesh p = read_ply_mesh(tmp.file("planes.ply"));
  ASSERT_EQ(p.vertices.size(), 2u);
  EXPECT_EQ(p.vertices[1], cloud.points[2]);
  EXPECT_EQ(p.vertex_labels, (std::vector<std::int32_t>{7, 7}));
  EXPECT_TRUE(p.triangles.empty());
}

const char* kAsciiQuad =
    "ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\nproperty float z\n"
    "element face 1\nproperty list uchar int vertex_indices\nend_header\n"
    "0 0 0\n1 0 0\n1 1 0\n0 1 -2.5e-1\n4 0 1 2 3\n";

TEST(PlyMeshReader, ReadsAsciiAndTriangulatesPolygons) {
  const std::string text = kAsciiQuad;
  const PlyMesh m = parse_ply_mesh(reinterpret_cast<const std::uint8_t*>(text.data()), text.size(), "q.ply");
  ASSERT_EQ(m.vertices.size(), 4u);
  EXPECT_FLOAT_EQ(m.vertices[3].z(), -0.25f);
  ASSERT_EQ(m.triangles.size(), 2u);
  EXPECT_EQ(m.triangles[1], (std::array<std::int32_t, 3>{0, 2, 3}));
}

TEST(PlyMeshReader, RefusesHostileFilesWithOneLine) {
  const auto parse = [](const std::string& text) {
    return parse_ply_mesh(reinterpret_cast<const std::uint8_t*>(text.data()), text.size(), "h.ply");
  };
  const auto expect = [&](const std::string& text, const std::string& part) {
    expect_input_error([&] { parse(text); }, {"h.ply", part});
  };
  const std::string head = "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n";
  const std::string face = "element face 1\nproperty list uchar int vertex_indices\nend_header\n";
  expect("hello", "not a PLY");
  expect("ply\nformat binary_big_endian 1.0\nend_header\n", "binary_big_endian");
  expect("ply\nformat ascii 1.0\nelement vertex 2000000000\nproperty float x\nproperty float y\nproperty float z\nend_header\n0 0 0\n",
         "truncated PLY: header promises");
  expect("ply\nformat ascii 1.0\nelement vertex 99999999999\nproperty float x\nend_header\n", "absurd element count");
  expect(head + face + "0 0 0\n1 0 0\n0 1 0\n3 0 1 7\n", "refers to vertex 7 of 3");
  expect(head + face + "0 0 0\n1 0 0\n0 1 0\n200 0 1 2\n", "length");
  expect(head + face + "0 0 0\n1 0 0\n0 1 0\n3 0 1 -1\n", "vertex index");
  expect(head + face + "0 0 0\nnan 0 0\n0 1 0\n3 0 1 2\n", "PLY vertex 1 position is not finite");
  expect(head + face + "0 0 0\n1 0 zero\n0 1 0\n3 0 1 2\n", "bad number 'zero'");
  expect(head + "property float x\n" + face, "declared twice");
  expect(head + "element face 1\nproperty list float int vertex_indices\nend_header\n", "list types must be integers");
  expect(head + "property uchar red\nproperty uchar green\nproperty uchar blue\n" + face + "0 0 0 1 2 3\n1 0 0 4 5 300\n0 1 0 1 1 1\n3 0 1 2\n",
         "bad value '300' for a uchar");
  expect("ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\n", "no end_header");
  expect("ply\nformat ascii 1.0\nelement face 0\nproperty list uchar int vertex_indices\nend_header\n", "no vertex element");

  // Every truncation of a binary map PLY and of an ascii one: an InputError, never a crash.
  IoTempDir tmp;
  write_map_ply(tmp.file("map.ply"), one_wall_map(), json::object());
  const auto map = testing::read_binary_file(tmp.file("map.ply"));
  for (const std::string& full : {std::string(map.begin(), map.end()), std::string(kAsciiQuad)}) {
    for (std::size_t n = 0; n + 1 < full.size(); ++n) {
      const std::string cut = full.substr(0, n);
      if (n + 2 >= full.size() && full == kAsciiQuad) continue;  // "4 0 1 2 3" minus its newline is whole
      expect_input_error([&] { parse(cut); }, {"h.ply"});
    }
  }
}

TEST(PlyMeshReader, RandomByteFlipsNeverEscapeAsAnythingButInputError) {
  IoTempDir tmp;
  write_map_ply(tmp.file("map.ply"), one_wall_map(), json::object());
  const auto map = testing::read_binary_file(tmp.file("map.ply"));
  std::mt19937 rng(8);
  int refused = 0, read = 0;
  for (int trial = 0; trial < 3000; ++trial) {
    std::vector<std::uint8_t> bytes(map.begin(), map.end());
    for (int k = 0; k < 3; ++k) bytes[rng() % bytes.size()] = static_cast<std::uint8_t>(rng());
    try {
      const PlyMesh m = parse_ply_mesh(bytes.data(), bytes.size(), "flip.ply");
      for (const auto& t : m.triangles)
        for (int v : t) ASSERT_LT(static_cast<std::size_t>(v), m.vertices.size());
      ++read;
    } catch (const InputError& e) {
      ++refused;
      ASSERT_EQ(std::string(e.what()).find('\n'), std::string::npos);
    }
  }
  EXPECT_GT(refused, 100);
  EXPECT_GT(read, 100);
}

TEST(PlyMeshReader, MissingFileAndFolder) {
  IoTempDir tmp;
  expect_input_error([&] { read_ply_mesh(tmp.file("none.ply")); }, {"none.ply", "not found"});
  expect_input_error([&] { read_ply_mesh(tmp.path().string()); }, {"folder"});
}

}  // namespace
}  // namespace tunnelmap
