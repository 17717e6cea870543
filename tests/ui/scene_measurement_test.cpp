// Picking and measuring in the 3D scene (OSMesa, no DISPLAY): a pick at a cloud point's screen
// position returns that point, two picks across the tunnel measure its width, the measurement
// is drawn in its own colour, and a third pick starts another measurement beside the first.
#include <gtest/gtest.h>

#include <cmath>
#include <vtkCoordinate.h>

#include "app/render/osmesa_window.h"
#include "tests/ui/synthetic_tunnel.h"
#include "ui/scene/image_checks.h"
#include "ui/scene/tunnel_scene.h"

namespace tunnelmap {
namespace {

// The valid cloud point nearest to `target` (camera frame).
Eigen::Vector3d nearest_cloud_point(const OrganizedCloud& cloud, const Eigen::Vector3d& target) {
  Eigen::Vector3d best = Eigen::Vector3d::Constant(1e9);
  for (const auto& p : cloud.points)
    if (OrganizedCloud::valid(p) && (p.cast<double>() - target).norm() < (best - target).norm()) best = p.cast<double>();
  return best;
}

Eigen::Vector2d display_of(vtkRenderer* r, const Eigen::Vector3d& p) {
  auto c = vtkSmartPointer<vtkCoordinate>::New();
  c->SetCoordinateSystemToWorld();
  c->SetValue(p.x(), p.y(), p.z());
  const double* d = c->GetComputedDoubleDisplayValue(r);
  return {d[0], d[1]};
}

int white_pixels(const scene::RgbImage& img) {
  int n = 0;
  for (int y = 0; y < img.height; ++y)
    for (int x = 0; x < img.width; ++x) {
      const auto* p = img.at(x, y);
      n += p[0] > 250 && p[1] > 250 && p[2] > 250;
    }
  return n;
}

TEST(SceneMeasurement, TwoPicksAcrossTheTunnelMeasureItsWidth) {
  const auto pf = test::make_synthetic_tunnel(1.0, 0.8, 3.0);
  render::OsMesaWindow window(640, 400);
  scene::TunnelScene sc;
  sc.update(pf.scene_data());
  sc.show_only({scene::Layer::Cloud});
  window.add_renderer(sc.renderer());
  sc.apply_view(scene::ViewPreset::Along);
  const scene::RgbImage before = window.render();
  EXPECT_EQ(white_pixels(before), 0);

  const Eigen::Vector3d left = nearest_cloud_point(pf.result.cloud, {-0.5, 0.0, 1.5});
  const Eigen::Vector3d right = nearest_cloud_point(pf.result.cloud, {0.5, 0.0, 1.5});
  ASSERT_NEAR(left.x(), -0.5, 0.01);
  ASSERT_NEAR(right.x(), 0.5, 0.01);
  const Eigen::Vector2d dl = display_of(sc.renderer(), left), dr = display_of(sc.renderer(), right);
  const auto a = sc.pick_at(dl.x(), dl.y());
  ASSERT_TRUE(a.has_value());
  EXPECT_LT((*a - left).norm(), 0.01);
  EXPECT_FALSE(sc.measurement().distance_m().has_value());
  const auto b = sc.pick_at(dr.x(), dr.y());
  ASSERT_TRUE(b.has_value());
  ASSERT_TRUE(sc.measurement().distance_m().has_value());
  EXPECT_NEAR(*sc.measurement().distance_m(), 1.0, 0.01);
  EXPECT_EQ(sc.measurement().label().substr(sc.measurement().label().size() - 3), " mm");

  const scene::RgbImage after = window.render();
  EXPECT_GT(white_pixels(after), 200);  // the picks, the segment and its label

  // Nothing drawn under the cursor (the measurement cleared too): no pick.
  sc.set_measurements({});
  sc.show_only({});
  window.render();
  EXPECT_FALSE(sc.pick_at(dl.x(), dl.y()).has_value());
  sc.show_only({scene::Layer::Cloud});
  window.render();
  EXPECT_TRUE(sc.pick_at(dl.x(), dl.y()).has_value());
  EXPECT_TRUE(sc.pick_at(dr.x(), dr.y()).has_value());
  const int one_drawn = white_pixels(window.render());
  EXPECT_TRUE(sc.pick_at(dl.x(), dl.y()).has_value());
  EXPECT_EQ(sc.measurement().picks.size(), 1u);  // the third pick started a new measurement
  ASSERT_EQ(sc.measurements().size(), 2u);       // and the first one stays
  EXPECT_NEAR(*sc.measurements().front().distance_m(), 1.0, 0.01);

  // A second distance, lower in the tunnel: both segments and both labels are drawn.
  const Eigen::Vector3d low_left = nearest_cloud_point(pf.result.cloud, {-0.5, 0.2, 1.2});
  const Eigen::Vector3d low_right = nearest_cloud_point(pf.result.cloud, {0.5, 0.2, 1.2});
  sc.set_measurements({sc.measurements().front()});
  const Eigen::Vector2d ll = display_of(sc.renderer(), low_left), lr = display_of(sc.renderer(), low_right);
  ASSERT_TRUE(sc.pick_at(ll.x(), ll.y()).has_value());
  ASSERT_TRUE(sc.pick_at(lr.x(), lr.y()).has_value());
  ASSERT_EQ(sc.measurements().size(), 2u);
  EXPECT_NEAR(*sc.measurements().back().distance_m(), (low_right - low_left).norm(), 0.01);
  const int two_drawn = white_pixels(window.render());
  EXPECT_GT(two_drawn, one_drawn + 100) << one_drawn << " white pixels with one measurement";
  const auto labels = scene::measurement_label(sc.measurements());
  EXPECT_EQ(labels->GetNumberOfPoints(), 2);
}

}  // namespace
}  // namespace tunnelmap
