// Output writers: the map mesh PLY and the plane-point PLY, read back with PCL and by hand.
#include <gtest/gtest.h>

#include <pcl/PCLPointCloud2.h>
#include <pcl/PolygonMesh.h>
#include <pcl/conversions.h>
#include <pcl/io/ply_io.h>
#include <pcl/point_cloud.h>
#include <pcl/point_types.h>

#include <cstring>
#include <filesystem>
#include <map>
#include <nlohmann/json.hpp>
#include <sstream>

#include "core/export/map_ply.h"
#include "core/export/planes_ply.h"
#include "core/util/error.h"
#include "tests/support/io_temp_dir.h"

namespace tunnelmap {
namespace {

namespace fs = std::filesystem;
using testing::IoTempDir;

std::array<Eigen::Vector3d, 4> rect(const Eigen::Vector3d& p0, const Eigen::Vector3d& da,
                                    const Eigen::Vector3d& db) {
  return {p0, p0 + da, p0 + da + db, p0 + db};
}

// A 0.82 m x 1.30 m tunnel in the camera frame (x right, y down, z forward), visible from
// z = 0.5 to 2.5 m. Each wall: forbidden 0.15 m bands at both edges and a traversable middle.
// The bottom wall is "not found" but carries zones, which must not be written.
TunnelMap hand_built_map() {
  TunnelMap m;
  m.detected = true;
  m.status = TunnelStatus::Ok;
  m.width_m = 0.82;
  m.height_m = 1.30;
  const double hw = 0.41, hh = 0.65, z0 = 0.5, len = 2.0, band = 0.15;
  const Eigen::Vector3d along(0, 0, len);
  struct Spec {
    WallClass cls;
    Eigen::Vector3d start, across, normal;
  };
  const Spec specs[] = {
      {WallClass::Left, {-hw, -hh, z0}, {0, 2 * hh, 0}, {1, 0, 0}},
      {WallClass::Right, {hw, -hh, z0}, {0, 2 * hh, 0}, {-1, 0, 0}},
      {WallClass::Top, {-hw, -hh, z0}, {2 * hw, 0, 0}, {0, 1, 0}},
      {WallClass::Bottom, {-hw, hh, z0}, {2 * hw, 0, 0}, {0, -1, 0}},
  };
  for (const Spec& s : specs) {
    Wall& w = m.wall(s.cls);
    w.cls = s.cls;
    w.found = s.cls != WallClass::Bottom;
    w.normal = s.normal;
    w.offset_m = -s.normal.dot(s.start);
    w.boundary = rect(s.start, along, s.across);
    const Eigen::Vector3d dir = s.across.normalized();
    const double width = s.across.norm();
    w.zones.push_back({ZoneKind::Forbidden, rect(s.start, along, band * dir)});
    w.zones.push_back({ZoneKind::Traversable, rect(s.start + band * dir, along, (width - 2 * band) * dir)});
    w.zones.push_back({ZoneKind::Forbidden, rect(s.start + (width - band) * dir, along, band * dir)});
  }
  return m;
}

nlohmann::json test_params() {
  return {{"grow.angle_deg", 4.0}, {"tunnel.zone_cluster_m", 0.01}, {"normals.window", 7}};
}

// Minimal reader for the files we write: header lines, then the binary body.
struct PlyFile {
  std::vector<std::string> header;
  std::string body;
};
PlyFile split_ply(const std::string& path) {
  const auto bytes = testing::read_binary_file(path);
  const std::string all(bytes.begin(), bytes.end());
  const std::string marker = "end_header\n";
  const auto end = all.find(marker);
  EXPECT_NE(end, std::string::npos);
  PlyFile f;
  std::istringstream h(all.substr(0, end));
  for (std::string line; std::getline(h, line);) f.header.push_back(line);
  f.body = all.substr(end + marker.size());
  return f;
}
bool has_line(const PlyFile& f, const std::string& line) {
  return std::find(f.header.begin(), f.header.end(), line) != f.header.end();
}
template <typename T>
T get(const std::string& body, std::size_t at) {
  T v;
  std::memcpy(&v, body.data() + at, sizeof(T));  // the test machine is little-endian
  return v;
}

struct MapFace {
  int a, b, c, label, wall;
};
struct MapMesh {
  std::vector<Eigen::Vector3f> points;
  std::vector<std::array<int, 3>> colours;
  std::vector<MapFace> faces;
};
// Vertex: 3 floats + 3 uchar = 15 bytes. Face: uchar count + 3 int + 2 uchar = 15 bytes.
MapMesh parse_map_body(const PlyFile& f, std::size_t nv, std::size_t nf) {
  MapMesh m;
  EXPECT_EQ(f.body.size(), nv * 15 + nf * 15);
  for (std::size_t i = 0; i < nv; ++i) {
    const std::size_t at = i * 15;
    m.points.emplace_back(get<float>(f.body, at), get<float>(f.body, at + 4), get<float>(f.body, at + 8));
    m.colours.push_back({get<std::uint8_t>(f.body, at + 12), get<std::uint8_t>(f.body, at + 13),
                         get<std::uint8_t>(f.body, at + 14)});
  }
  for (std::size_t i = 0; i < nf; ++i) {
    const std::size_t at = nv * 15 + i * 15;
    EXPECT_EQ(get<std::uint8_t>(f.body, at), 3);
    m.faces.push_back({get<std::int32_t>(f.body, at + 1), get<std::int32_t>(f.body, at + 5),
                       get<std::int32_t>(f.body, at + 9), get<std::uint8_t>(f.body, at + 13),
                       get<std::uint8_t>(f.body, at + 14)});
  }
  return m;
}

// 3 found walls x (3 zones x 4 vertices + 4 border quads x 4 vertices).
constexpr std::size_t kMapVertices = 3 * (12 + 16);
constexpr std::size_t kMapFaces = 3 * (6 + 8);

TEST(MapPly, HeaderCarriesVersionSizeAndParameters) {
  IoTempDir tmp;
  const std::string path = tmp.file("map.ply");
  write_map_ply(path, hand_built_map(), test_params());
  const PlyFile f = split_ply(path);
  ASSERT_GE(f.header.size(), 2u);
  EXPECT_EQ(f.header[0], "ply");
  EXPECT_EQ(f.header[1], "format binary_little_endian 1.0");
  EXPECT_TRUE(has_line(f, std::string("comment generated by tunnelmap ") + TUNNELMAP_VERSION));
  EXPECT_TRUE(has_line(f, "comment width_m 0.82 height_m 1.3"));
  EXPECT_TRUE(has_line(f, "comment param grow.angle_deg 4"));
  EXPECT_TRUE(has_line(f, "comment param tunnel.zone_cluster_m 0.01"));
  EXPECT_TRUE(has_line(f, "comment param normals.window 7"));
  EXPECT_TRUE(has_line(f, "element vertex " + std::to_string(kMapVertices)));
  EXPECT_TRUE(has_line(f, "element face " + std::to_string(kMapFaces)));
  EXPECT_TRUE(has_line(f, "property list uchar int vertex_indices"));
  EXPECT_TRUE(has_line(f, "property uchar label"));
  EXPECT_TRUE(has_line(f, "property uchar wall"));
}

TEST(MapPly, BodyHasZonesBordersLabelsAndColours) {
  IoTempDir tmp;
  const std::string path = tmp.file("map.ply");
  write_map_ply(path, hand_built_map(), test_params());
  const MapMesh m = parse_map_body(split_ply(path), kMapVertices, kMapFaces);

  std::map<std::array<int, 3>, int> colour_count;
  for (const auto& c : m.colours) ++colour_count[c];
  EXPECT_EQ(colour_count[(std::array<int, 3>{255, 140, 0})], 3 * 2 * 4);  // forbidden
  EXPECT_EQ(colour_count[(std::array<int, 3>{220, 30, 30})], 3 * 1 * 4);  // traversable
  EXPECT_EQ(colour_count[(std::array<int, 3>{30, 60, 230})], 3 * 16);     // border
  EXPECT_EQ(colour_count.size(), 3u);

  std::map<int, int> label_count, wall_count;
  std::map<int, double> border_area;  // per wall
  for (const MapFace& face : m.faces) {
    for (int idx : {face.a, face.b, face.c}) ASSERT_TRUE(idx >= 0 && idx < int(kMapVertices));
    ++label_count[face.label];
    ++wall_count[face.wall];
    const Eigen::Vector3f e1 = m.points[face.b] - m.points[face.a];
    const Eigen::Vector3f e2 = m.points[face.c] - m.points[face.a];
    if (face.label == 0) border_area[face.wall] += 0.5 * e1.cross(e2).norm();
    // Face colour matches its label.
    const auto colour = m.colours[face.a];
    const std::array<int, 3> expected = face.label == 0   ? std::array<int, 3>{30, 60, 230}
                                        : face.label == 1 ? std::array<int, 3>{220, 30, 30}
                                                          : std::array<int, 3>{255, 140, 0};
    EXPECT_EQ(colour, expected);
  }
  EXPECT_EQ(label_count[0], 24);  // border: 3 walls x 4 quads x 2 triangles
  EXPECT_EQ(label_count[1], 6);
  EXPECT_EQ(label_count[2], 12);
  EXPECT_EQ(wall_count[0], 14);
  EXPECT_EQ(wall_count[1], 14);
  EXPECT_EQ(wall_count[2], 14);
  EXPECT_EQ(wall_count.count(3), 0u);  // bottom wall not found
  // A 1 cm band inside a 2.0 m x 1.30 m (side walls) or 2.0 m x 0.82 m (roof) rectangle:
  // perimeter * w - 4 w^2.
  EXPECT_NEAR(border_area[0], 2 * (2.0 + 1.30) * 0.01 - 4e-4, 1e-5);
  EXPECT_NEAR(border_area[2], 2 * (2.0 + 0.82) * 0.01 - 4e-4, 1e-5);

  // The border lies on the wall plane and inside the boundary rectangle.
  for (std::size_t i = 0; i < m.points.size(); ++i) {
    if (m.colours[i] != std::array<int, 3>{30, 60, 230}) continue;
    const Eigen::Vector3f& p = m.points[i];
    EXPECT_GE(p.z(), 0.5f - 1e-6f);
    EXPECT_LE(p.z(), 2.5f + 1e-6f);
    EXPECT_LE(std::abs(p.x()), 0.41f + 1e-6f);
    EXPECT_LE(std::abs(p.y()), 0.65f + 1e-6f);
  }
}

TEST(MapPly, LoadsInPclWithCountsAndColours) {
  IoTempDir tmp;
  const std::string path = tmp.file("map.ply");
  Eigen::Isometry3d to_world = Eigen::Isometry3d::Identity();
  to_world.translate(Eigen::Vector3d(1, 2, 3));
  write_map_ply(path, hand_built_map(), test_params(), to_world);

  pcl::PolygonMesh mesh;
  ASSERT_EQ(pcl::io::loadPLYFile(path, mesh), 0);
  EXPECT_EQ(mesh.polygons.size(), kMapFaces);
  ASSERT_EQ(std::size_t(mesh.cloud.width) * mesh.cloud.height, kMapVertices);
  for (const auto& poly : mesh.polygons) ASSERT_EQ(poly.vertices.size(), 3u);
  pcl::PointCloud<pcl::PointXYZRGB> cloud;
  pcl::fromPCLPointCloud2(mesh.cloud, cloud);
  int orange = 0, red = 0, blue = 0;
  float min_x = 1e9f, max_z = -1e9f;
  for (const auto& p : cloud) {
    orange += p.r == 255 && p.g == 140 && p.b == 0;
    red += p.r == 220 && p.g == 30 && p.b == 30;
    blue += p.r == 30 && p.g == 60 && p.b == 230;
    min_x = std::min(min_x, p.x);
    max_z = std::max(max_z, p.z);
  }
  EXPECT_EQ(orange, 24);
  EXPECT_EQ(red, 12);
  EXPECT_EQ(blue, 48);
  EXPECT_NEAR(min_x, -0.41f + 1.f, 1e-5);  // to_world applied
  EXPECT_NEAR(max_z, 2.5f + 3.f, 1e-5);
}

TEST(MapPly, EmptyMapStillWritesAValidFile) {
  IoTempDir tmp;
  const std::string path = tmp.file("empty.ply");
  TunnelMap none;
  none.status = TunnelStatus::TooFewPlanes;
  write_map_ply(path, none, nlohmann::json::object());
  const PlyFile f = split_ply(path);
  EXPECT_TRUE(has_line(f, "element vertex 0"));
  EXPECT_TRUE(has_line(f, "element face 0"));
  EXPECT_TRUE(has_line(f, "comment width_m 0 height_m 0"));
  EXPECT_TRUE(f.body.empty());
}

std::vector<std::string> folder_listing(const fs::path& dir) {
  std::vector<std::string> names;
  for (const auto& e : fs::directory_iterator(dir)) names.push_back(e.path().filename().string());
  std::sort(names.begin(), names.end());
  return names;
}

TEST(MapPly, FailedWriteLeavesNoFileAndKeepsTheOldOne) {
  IoTempDir tmp;
  const std::string path = tmp.file("map.ply");
  write_map_ply(path, hand_built_map(), test_params());
  const auto before = testing::read_binary_file(path);

  // The writer throws midway: a parameter whose value is not valid UTF-8 cannot be serialised.
  nlohmann::json bad = test_params();
  bad["label"] = std::string("\xff\xfe broken");
  EXPECT_ANY_THROW(write_map_ply(path, hand_built_map(), bad));
  EXPECT_EQ(testing::read_binary_file(path), before);
  EXPECT_EQ(folder_listing(tmp.path()), std::vector<std::string>{"map.ply"});  // no temporary left

  const std::string in_missing_folder = tmp.file("no/such/folder/map.ply");
  EXPECT_THROW(write_map_ply(in_missing_folder, hand_built_map(), test_params()), InputError);
  EXPECT_FALSE(fs::exists(in_missing_folder));

  // Target is a folder: refused as bad usage, the folder survives, nothing else appears.
  fs::create_directory(tmp.path() / "taken.ply");
  EXPECT_THROW(write_map_ply(tmp.file("taken.ply"), hand_built_map(), test_params()), OutputPathError);
  EXPECT_TRUE(fs::is_directory(tmp.path() / "taken.ply"));
  EXPECT_EQ(folder_listing(tmp.path()), (std::vector<std::string>{"map.ply", "taken.ply"}));
}

// ---------------------------------------------------------------- planes PLY

TEST(PlanesPly, WritesPlanePointsColouredByClass) {
  IoTempDir tmp;
  const std::string path = tmp.file("planes.ply");
  OrganizedCloud cloud;
  cloud.width = 4;
  cloud.height = 3;
  const float nan = std::numeric_limits<float>::quiet_NaN();
  for (int v = 0; v < 3; ++v)
    for (int u = 0; u < 4; ++u) cloud.points.emplace_back(0.1f * u, 0.1f * v, 1.f + u);
  cloud.points[5] = Eigen::Vector3f::Constant(nan);  // labelled but invalid: skipped
  PlaneSegments planes;
  planes.width = 4;
  planes.height = 3;
  planes.planes.resize(3);
  planes.planes[0].id = 1;
  planes.planes[1].id = 2;
  planes.planes[2].id = 5;
  planes.labels = {1, 1, 0, 2,
                   2, 2, 0, 5,
                   5, 0, 0, 1};
  write_planes_ply(path, cloud, planes, {WallClass::Left, WallClass::Top});  // plane 5: unassigned

  pcl::PCLPointCloud2 blob;
  ASSERT_EQ(pcl::io::loadPLYFile(path, blob), 0);
  ASSERT_EQ(std::size_t(blob.width) * blob.height, 7u);
  bool has_plane_field = false;
  for (const auto& field : blob.fields) has_plane_field |= field.name == "plane";
  EXPECT_TRUE(has_plane_field);
  pcl::PointCloud<pcl::PointXYZRGB> pts;
  pcl::fromPCLPointCloud2(blob, pts);
  ASSERT_EQ(pts.size(), 7u);
  EXPECT_EQ(pts[0].r, 60);  // left: blue-ish
  EXPECT_EQ(pts[0].b, 255);
  EXPECT_FLOAT_EQ(pts[0].z, 1.f);
  EXPECT_EQ(pts[2].r, 240);  // pixel 3, plane 2 = top: yellow
  EXPECT_EQ(pts[2].g, 220);
  EXPECT_EQ(pts[4].r, 150);  // pixel 7, plane 5: unassigned grey
  EXPECT_EQ(pts[4].g, 150);

  // The int `plane` property, read by hand: 3 floats + 3 uchar + int = 19 bytes per vertex.
  const PlyFile f = split_ply(path);
  ASSERT_EQ(f.body.size(), 7u * 19);
  std::vector<int> ids;
  for (int i = 0; i < 7; ++i) ids.push_back(get<std::int32_t>(f.body, i * 19 + 15));
  EXPECT_EQ(ids, (std::vector<int>{1, 1, 2, 2, 5, 5, 1}));
}

TEST(PlanesPly, RightAndBottomColours) {
  IoTempDir tmp;
  const std::string path = tmp.file("planes.ply");
  OrganizedCloud cloud;
  cloud.width = 2;
  cloud.height = 1;
  cloud.points = {Eigen::Vector3f(0, 0, 1), Eigen::Vector3f(1, 0, 1)};
  PlaneSegments planes;
  planes.width = 2;
  planes.height = 1;
  planes.planes.resize(2);
  planes.planes[0].id = 1;
  planes.planes[1].id = 2;
  planes.labels = {1, 2};
  write_planes_ply(path, cloud, planes, {WallClass::Right, WallClass::Bottom});
  pcl::PCLPointCloud2 blob;
  ASSERT_EQ(pcl::io::loadPLYFile(path, blob), 0);
  pcl::PointCloud<pcl::PointXYZRGB> pts;
  pcl::fromPCLPointCloud2(blob, pts);
  ASSERT_EQ(pts.size(), 2u);
  EXPECT_EQ(pts[0].g, 200);  // right: green
  EXPECT_EQ(pts[0].r, 40);
  EXPECT_EQ(pts[1].r, 220);  // bottom: magenta
  EXPECT_EQ(pts[1].b, 220);
  EXPECT_EQ(pts[1].g, 40);
}

}  // namespace
}  // namespace tunnelmap
