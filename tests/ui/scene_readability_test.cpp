// The 3D scene is readable by default: zones are translucent with opaque outlines (the walls'
// points show through), the frustum and axes leave the along view, the legend lists only what
// is shown in text no smaller than 16 px rows, a distance grid lies on the floor, and every
// pair of colours stays apart for colour-blind viewers (Machado et al. 2009 simulation).
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <vector>

#include "app/render/osmesa_window.h"
#include "tests/ui/synthetic_tunnel.h"
#include <vtkMapper2D.h>
#include <vtkPointData.h>
#include <vtkStringArray.h>

#include "ui/scene/dimension_labels.h"
#include "ui/scene/image_checks.h"
#include "ui/scene/scene_colors.h"
#include "ui/scene/scene_legend.h"
#include "ui/scene/tunnel_scene.h"

namespace tunnelmap {
namespace {

using scene::Layer;
using scene::Rgb;

// --- colour-vision deficiency: Machado, Oliveira & Fernandes 2009, severity 1, linear RGB ---
using Matrix = std::array<std::array<double, 3>, 3>;
constexpr Matrix kDeuteranopia{{{0.367322, 0.860646, -0.227968},
                                {0.280085, 0.672501, 0.047413},
                                {-0.011820, 0.042940, 0.968881}}};
constexpr Matrix kProtanopia{{{0.152286, 1.052583, -0.204868},
                              {0.114503, 0.786281, 0.099216},
                              {-0.003882, -0.048116, 1.051998}}};

double to_linear(double c) { return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4); }
double to_srgb(double c) { return c <= 0.0031308 ? 12.92 * c : 1.055 * std::pow(c, 1 / 2.4) - 0.055; }

Rgb simulate(const Rgb& c, const Matrix& m) {
  const Rgb lin{to_linear(c[0]), to_linear(c[1]), to_linear(c[2])};
  Rgb out;
  for (int i = 0; i < 3; ++i) {
    const double v = m[i][0] * lin[0] + m[i][1] * lin[1] + m[i][2] * lin[2];
    out[i] = to_srgb(std::clamp(v, 0.0, 1.0));
  }
  return out;
}

// CIE L*a*b* (D65) of an sRGB colour; distances are CIE76 delta E.
std::array<double, 3> lab(const Rgb& c) {
  const double r = to_linear(c[0]), g = to_linear(c[1]), b = to_linear(c[2]);
  const double x = (0.4124 * r + 0.3576 * g + 0.1805 * b) / 0.95047;
  const double y = 0.2126 * r + 0.7152 * g + 0.0722 * b;
  const double z = (0.0193 * r + 0.1192 * g + 0.9505 * b) / 1.08883;
  auto f = [](double t) { return t > 0.008856 ? std::cbrt(t) : 7.787 * t + 16.0 / 116.0; };
  return {116 * f(y) - 16, 500 * (f(x) - f(y)), 200 * (f(y) - f(z))};
}

double delta_e(const Rgb& a, const Rgb& b) {
  const auto la = lab(a), lb = lab(b);
  return std::sqrt((la[0] - lb[0]) * (la[0] - lb[0]) + (la[1] - lb[1]) * (la[1] - lb[1]) +
                   (la[2] - lb[2]) * (la[2] - lb[2]));
}

std::vector<std::pair<const char*, Rgb>> legend_colours() {
  std::vector<std::pair<const char*, Rgb>> out;
  for (WallClass c : {WallClass::Left, WallClass::Right, WallClass::Top, WallClass::Bottom, WallClass::Unassigned})
    out.push_back({scene::wall_class_label(c), scene::wall_class_color(c)});
  out.push_back({"boundary", scene::kBoundaryBlue});
  out.push_back({"traversable", scene::kTraversableRed});
  out.push_back({"forbidden", scene::kForbiddenAmber});
  return out;
}

TEST(SceneColours, EveryPairStaysApartForDeuteranopesAndProtanopes) {
  const auto colours = legend_colours();
  for (const Matrix* m : {&kDeuteranopia, &kProtanopia})
    for (std::size_t i = 0; i < colours.size(); ++i)
      for (std::size_t j = i + 1; j < colours.size(); ++j) {
        const double d = delta_e(simulate(colours[i].second, *m), simulate(colours[j].second, *m));
        EXPECT_GE(d, 15.0) << colours[i].first << " vs " << colours[j].first
                           << (m == &kDeuteranopia ? " (deuteranopia)" : " (protanopia)");
      }
}

TEST(SceneColours, TheSimulationMergesRedAndGreenAsItShould) {
  // The filter itself: pure red and a green of equal lightness collapse for a deuteranope.
  const Rgb red{0.8, 0.2, 0.1}, green{0.45, 0.55, 0.1};
  EXPECT_GT(delta_e(red, green), 40.0);
  EXPECT_LT(delta_e(simulate(red, kDeuteranopia), simulate(green, kDeuteranopia)), 12.0);
}

struct Shot {
  scene::RgbImage image;
  int legend_entries = 0, legend_h = 0;
};

Shot shoot(const scene::ProcessedFrame& pf, scene::ViewPreset view, const std::vector<Layer>& layers,
           int w = 640, int h = 400) {
  render::OsMesaWindow window(w, h);
  scene::TunnelScene sc;
  sc.update(pf.scene_data());
  sc.show_only(layers);
  window.add_renderer(sc.renderer());
  sc.apply_view(view);
  Shot s;
  s.image = window.render();
  s.legend_entries = sc.legend().entries();
  s.legend_h = sc.legend().box_height();
  return s;
}

TEST(SceneReadability, ZonesAreTranslucentSoTheWallPointsShowThrough) {
  const auto pf = test::make_synthetic_tunnel(1.0, 0.8, 3.0);
  const auto planes_only = shoot(pf, scene::ViewPreset::Along, {Layer::Planes});
  const auto with_zones = shoot(pf, scene::ViewPreset::Along, {Layer::Planes, Layer::Traversable});
  // Pixels of a wall-class colour in the planes-only image that keep some of it under the zones.
  int wall_pixels = 0, still_seen = 0;
  for (int y = 0; y < planes_only.image.height; ++y)
    for (int x = 0; x < planes_only.image.width; ++x) {
      const auto* p = planes_only.image.at(x, y);
      const auto* q = with_zones.image.at(x, y);
      if (p[0] + p[1] + p[2] < 200) continue;  // background
      ++wall_pixels;
      // Fully covered by an opaque red zone the green and blue channels would read < 30.
      if (q[1] > 40 || q[2] > 40) ++still_seen;
    }
  ASSERT_GT(wall_pixels, 5000);
  EXPECT_GT(static_cast<double>(still_seen) / wall_pixels, 0.9);
  EXPECT_GT(scene::find_traversable_red(with_zones.image).count, 2000);  // and the zones are there
}

TEST(SceneReadability, TheAlongViewHidesTheFrustumAndAxesTheSideViewShowsThem) {
  const auto pf = test::make_synthetic_tunnel();
  scene::TunnelScene sc;
  sc.update(pf.scene_data());
  sc.apply_view(scene::ViewPreset::Along);
  EXPECT_TRUE(sc.layer_visible(Layer::Frustum));
  EXPECT_FALSE(sc.layer_shown(Layer::Frustum));
  EXPECT_FALSE(sc.layer_shown(Layer::Axes));
  sc.apply_view(scene::ViewPreset::Side);
  EXPECT_TRUE(sc.layer_shown(Layer::Frustum));
  // In pictures: the frustum alone draws nothing along, something from the side.
  const int along = scene::distinct_colors(shoot(pf, scene::ViewPreset::Along, {Layer::Frustum}).image);
  const int side = scene::distinct_colors(shoot(pf, scene::ViewPreset::Side, {Layer::Frustum}).image);
  EXPECT_EQ(along, 1);
  EXPECT_GT(side, 1);
}

TEST(SceneReadability, TheLegendListsOnlyTheShownLayersInRowsOfAtLeast16Pixels) {
  const auto pf = test::make_synthetic_tunnel();
  const auto all = shoot(pf, scene::ViewPreset::Along,
                         {Layer::Planes, Layer::Boundary, Layer::Traversable, Layer::Forbidden, Layer::Legend},
                         480, 300);
  EXPECT_EQ(all.legend_entries, 8);  // five wall classes, boundary, two zone kinds
  EXPECT_GE(all.legend_h, 8 * 16);
  const auto some = shoot(pf, scene::ViewPreset::Along, {Layer::Cloud, Layer::Boundary, Layer::Legend});
  EXPECT_EQ(some.legend_entries, 1);
  const auto none = shoot(pf, scene::ViewPreset::Along, {Layer::Cloud, Layer::Legend});
  EXPECT_EQ(none.legend_entries, 0);
  EXPECT_EQ(scene::distinct_colors(shoot(pf, scene::ViewPreset::Along, {Layer::Legend}).image), 1);
  // A large view gets larger rows (up to 20 px).
  EXPECT_EQ(scene::legend_row_px(300), 16);
  EXPECT_EQ(scene::legend_row_px(1000), 20);
}

TEST(SceneReadability, InANarrowViewTheLegendMovesUpAndLeavesTheWidthLabelClear) {
  // A 3D dock 320 px wide (the GUI at 1200 px): the legend goes to the upper-right corner, so
  // the lower half of the picture, with the width label, is the same with or without it.
  const auto pf = test::make_synthetic_tunnel();
  const std::vector<Layer> map = {Layer::Planes, Layer::Boundary, Layer::Traversable, Layer::Forbidden};
  std::vector<Layer> with_legend = map;
  with_legend.push_back(Layer::Legend);
  const auto without = shoot(pf, scene::ViewPreset::Along, map, 320, 475).image;
  const auto with = shoot(pf, scene::ViewPreset::Along, with_legend, 320, 475).image;
  int lower = 0, upper_right = 0;
  for (int y = 0; y < with.height; ++y)
    for (int x = 0; x < with.width; ++x) {
      const std::uint8_t *a = with.at(x, y), *b = without.at(x, y);
      const bool differs = std::abs(a[0] - b[0]) + std::abs(a[1] - b[1]) + std::abs(a[2] - b[2]) > 30;
      if (!differs) continue;
      if (y >= with.height / 2) ++lower;
      else if (x >= with.width / 2) ++upper_right;
    }
  EXPECT_EQ(lower, 0);
  EXPECT_GT(upper_right, 1000);  // the legend's text and swatches
  // Wide views keep it in the lower-right corner.
  scene::SceneLegend legend(vtkSmartPointer<vtkRenderer>::New());
  legend.fit(320, 475);
  EXPECT_TRUE(legend.at_top());
  legend.fit(1280, 720);
  EXPECT_FALSE(legend.at_top());
}

// Whatever the view's shape, the legend takes the corner where it covers no distance, width or
// height label (in the GUI's 3D view at 1600 x 1000 it covered the "3 m" of the grid).
TEST(SceneReadability, TheLegendNeverCoversALabel) {
  const auto pf = test::make_synthetic_tunnel(1.0, 0.8, 3.0);
  for (const auto& size : std::vector<std::array<int, 2>>{{520, 620}, {640, 400}, {320, 475}, {1280, 720}}) {
    render::OsMesaWindow window(size[0], size[1]);
    scene::TunnelScene sc;
    sc.update(pf.scene_data());
    window.add_renderer(sc.renderer());
    sc.apply_view(scene::ViewPreset::Along);
    window.render();
    const std::vector<scene::ScreenBox> labels = sc.label_boxes();
    ASSERT_GE(labels.size(), 3u) << size[0] << "x" << size[1];  // grid metres, width, height
    for (const scene::ScreenBox& label : labels)
      EXPECT_FALSE(sc.legend().box().overlaps(label))
          << size[0] << "x" << size[1] << ": label at " << label.x0 << "," << label.y0;
  }
  // A label in the lower-right corner sends the legend elsewhere.
  scene::SceneLegend legend(vtkSmartPointer<vtkRenderer>::New());
  legend.fit(1280, 720, {{1100, 20, 1270, 60}});
  EXPECT_FALSE(!legend.at_top() && !legend.at_left());
}

TEST(SceneReadability, TheFloorCarriesADistanceGridLabelledEveryMetre) {
  // A 3 m tunnel ahead of the camera: lines at 0.5 m steps over the floor's visible extent.
  const auto pf = test::make_synthetic_tunnel(1.0, 0.8, 3.0);
  scene::TunnelScene sc;
  sc.update(pf.scene_data());
  const vtkIdType lines = sc.layer_size(Layer::Grid);
  EXPECT_GE(lines, 4);
  EXPECT_LE(lines, 7);
  vtkPolyData* grid = sc.layer_polydata(Layer::Grid);
  ASSERT_NE(grid, nullptr);
  // Every line lies across the tunnel on the floor, 0.02 m above it (image-down is +y).
  const Wall& floor = pf.result.map.wall(WallClass::Bottom);
  for (vtkIdType i = 0; i < grid->GetNumberOfPoints(); ++i) {
    double p[3];
    grid->GetPoint(i, p);
    EXPECT_NEAR(floor.normal.dot(Eigen::Vector3d(p[0], p[1], p[2])) + floor.offset_m, 0.02, 1e-6);
  }
  const auto with = shoot(pf, scene::ViewPreset::Along, {Layer::Grid});
  EXPECT_GT(scene::distinct_colors(with.image), 1);
}

TEST(SceneReadability, WidthAndHeightAreWrittenOnTheBoundaryWithTheirSource) {
  auto pf = test::make_synthetic_tunnel(1.0, 0.8, 3.0);
  auto texts = [](vtkPolyData* poly) {
    std::vector<std::string> out;
    auto* a = vtkStringArray::SafeDownCast(poly->GetPointData()->GetAbstractArray("label"));
    for (vtkIdType i = 0; a && i < a->GetNumberOfValues(); ++i) out.push_back(a->GetValue(i));
    return out;
  };
  pf.result.map.width_source = pf.result.map.height_source = DimensionSource::Measured;
  auto labels = scene::make_dimension_labels(pf.result.map);
  ASSERT_EQ(labels->GetNumberOfPoints(), 2);
  EXPECT_EQ(texts(labels), (std::vector<std::string>{"width 1.000 m", "height 0.800 m"}));
  // The width label lies on the floor (y = +0.4 m in the camera frame, image-down).
  double p[3];
  labels->GetPoint(0, p);
  EXPECT_NEAR(p[1], 0.4, 0.05);
  // A height the frame took from the context says so.
  pf.result.map.height_source = DimensionSource::Context;
  EXPECT_EQ(texts(scene::make_dimension_labels(pf.result.map))[1], "height 0.800 m (context)");
  // Seen from the top the height runs along the line of sight, from the side the width: each
  // view writes only the other one.
  EXPECT_EQ(texts(scene::make_dimension_labels(pf.result.map, scene::ViewPreset::Top)),
            (std::vector<std::string>{"width 1.000 m"}));
  EXPECT_EQ(texts(scene::make_dimension_labels(pf.result.map, scene::ViewPreset::Side)),
            (std::vector<std::string>{"height 0.800 m (context)"}));
  // The scene swaps them with the view.
  scene::TunnelScene sc;
  sc.update(pf.scene_data());
  const auto shown = [&] {
    return texts(vtkPolyData::SafeDownCast(sc.dimension_label_actor()->GetMapper()->GetInputDataObject(0, 0)));
  };
  sc.apply_view(scene::ViewPreset::Top);
  EXPECT_EQ(shown(), (std::vector<std::string>{"width 1.000 m"}));
  sc.apply_view(scene::ViewPreset::Along);
  EXPECT_EQ(shown().size(), 2u);
  pf.result.map.detected = false;
  EXPECT_EQ(scene::make_dimension_labels(pf.result.map)->GetNumberOfPoints(), 0);
}

}  // namespace
}  // namespace tunnelmap
