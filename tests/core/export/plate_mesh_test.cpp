// The plates of the map mesh: the cross-section rectangle with the manhole cut out covers the
// plate's area less the opening's, lies in the plate's plane, and leaves the opening empty.
#include <gtest/gtest.h>

#include <cmath>

#include "core/export/plate_mesh.h"

namespace tunnelmap {
namespace {

PlateOutline plate_with(const std::string& shape, double radius) {
  PlateOutline p;
  p.centre = Eigen::Vector3d(12.0, 0.3, 0.6);
  p.left = Eigen::Vector3d::UnitY();
  p.up = Eigen::Vector3d::UnitZ();
  p.width_m = 0.90;
  p.height_m = 1.20;
  PlateOpening o;
  o.lateral_m = 0.05;
  o.vertical_m = -0.08;
  o.width_m = 0.50;
  o.height_m = 0.80;
  o.shape = shape;
  o.corner_radius_m = radius;
  p.opening = o;
  return p;
}

// Area of the mesh's triangles and the largest distance of a vertex from the plate's plane.
double area(const PlateMesh& m) {
  double a = 0.0;
  for (const auto& t : m.triangles)
    a += 0.5 * (m.vertices[t[1]] - m.vertices[t[0]]).cross(m.vertices[t[2]] - m.vertices[t[0]]).norm();
  return a;
}

void expect_plate(const PlateOutline& p, double opening_area) {
  const PlateMesh m = triangulate_plate(p);
  EXPECT_NEAR(area(m), p.width_m * p.height_m - opening_area, 0.002 * p.width_m * p.height_m);
  for (const Eigen::Vector3d& v : m.vertices) {
    EXPECT_NEAR(v.x(), p.centre.x(), 1e-12);  // in the plate's plane (x = 12 m)
    EXPECT_LE(std::abs(v.y() - p.centre.y()), 0.5 * p.width_m + 1e-9);
    EXPECT_LE(std::abs(v.z() - p.centre.z()), 0.5 * p.height_m + 1e-9);
  }
  // No triangle covers the opening's centre.
  const Eigen::Vector3d c = p.centre + p.left * p.opening->lateral_m + p.up * p.opening->vertical_m;
  for (const auto& t : m.triangles) {
    const Eigen::Vector3d g = (m.vertices[t[0]] + m.vertices[t[1]] + m.vertices[t[2]]) / 3.0;
    EXPECT_GT((g - c).norm(), 0.2) << "a triangle inside the opening";
  }
}

TEST(PlateMesh, AnEllipticOpeningIsCutOutOfTheCrossSection) {
  expect_plate(plate_with("ellipse", 0.0), M_PI * 0.25 * 0.40);
}

TEST(PlateMesh, ARoundedRectangleIsCutOutWithItsCorners) {
  const double r = 0.12;
  expect_plate(plate_with("rounded_rectangle", r), 0.50 * 0.80 - (4.0 - M_PI) * r * r);
}

TEST(PlateMesh, APlateWithoutAMeasuredOpeningIsWhole) {
  PlateOutline p = plate_with("ellipse", 0.0);
  p.opening.reset();
  const PlateMesh m = triangulate_plate(p);
  EXPECT_EQ(m.triangles.size(), 2u);
  EXPECT_NEAR(area(m), 0.90 * 1.20, 1e-12);
}

TEST(PlateMesh, OnlyPlatesWhoseCrossSectionWasMeasuredAreDrawn) {
  StationMap map;
  Diaphragm d;
  d.station_m = 4.0;
  d.point = Eigen::Vector3d(4.0, 0.0, 0.6);
  map.girder.diaphragms = {d, d};
  map.girder.diaphragms[1].station_m = 8.0;
  map.girder.diaphragms[1].point.x() = 8.0;
  Compartment before;  // measured, ends at the first plate
  before.from_m = 0.5;
  before.to_m = 4.0;
  before.width_m = 0.84;
  before.height_m = 1.20;
  Compartment between;  // not measured: the second plate has no size
  between.from_m = 4.0;
  between.to_m = 8.0;
  between.width_m = NAN;
  between.height_m = NAN;
  map.girder.compartments = {before, between};
  const std::vector<PlateOutline> plates = plate_outlines(map);
  ASSERT_EQ(plates.size(), 1u);
  EXPECT_DOUBLE_EQ(plates[0].width_m, 0.84);
  EXPECT_DOUBLE_EQ(plates[0].centre.x(), 4.0);
  EXPECT_FALSE(plates[0].opening.has_value());
  EXPECT_NEAR(plates[0].left.dot(Eigen::Vector3d::UnitY()), 1.0, 1e-12);  // left of +x, up +z
}

}  // namespace
}  // namespace tunnelmap
