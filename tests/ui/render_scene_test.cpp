// Renders TunnelScene through OSMesa (no DISPLAY) and checks what a person would see: not blank,
// boundary blue and traversable red where the tunnel projects, layers switch off, views differ.
#include <gtest/gtest.h>
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <filesystem>
#include <sys/wait.h>
#include <vtkCoordinate.h>

#include "app/render/osmesa_window.h"
#include "core/util/build_paths.h"
#include "tests/ui/synthetic_tunnel.h"
#include "ui/scene/image_checks.h"
#include "ui/scene/tunnel_scene.h"

namespace tunnelmap {
namespace {

using scene::Layer;

struct Rendered {
  scene::RgbImage image;
  // Display-space box of the map's boundary corners (top row = 0).
  int x0 = 1 << 30, y0 = 1 << 30, x1 = -1, y1 = -1;
};

Rendered render(const scene::ProcessedFrame& pf, scene::ViewPreset view,
                const std::vector<Layer>& layers, int w = 320, int h = 240) {
  render::OsMesaWindow window(w, h);
  scene::TunnelScene sc;
  sc.update(pf.scene_data());
  sc.show_only(layers);
  window.add_renderer(sc.renderer());
  sc.apply_view(view);
  Rendered r;
  r.image = window.render();
  // TUNNELMAP_UI_DUMP=dir keeps every rendered image for a person to look at.
  if (const char* dump = std::getenv("TUNNELMAP_UI_DUMP")) {
    static int n = 0;
    scene::save_png(r.image, std::string(dump) + "/render_" + std::to_string(n++) + "_" +
                                 scene::view_name(view) + ".png");
  }
  for (const Wall& wall : pf.result.map.walls)
    for (const auto& c : wall.boundary) {
      auto coord = vtkSmartPointer<vtkCoordinate>::New();
      coord->SetCoordinateSystemToWorld();
      coord->SetValue(c.x(), c.y(), c.z());
      const int* d = coord->GetComputedDisplayValue(sc.renderer());
      const int x = d[0], y = h - 1 - d[1];
      r.x0 = std::min(r.x0, x); r.x1 = std::max(r.x1, x);
      r.y0 = std::min(r.y0, y); r.y1 = std::max(r.y1, y);
    }
  return r;
}

const std::vector<Layer> kMapLayers = {Layer::Cloud, Layer::Planes, Layer::Boundary,
                                       Layer::Traversable, Layer::Forbidden, Layer::Frustum,
                                       Layer::Axes};

TEST(RenderScene, AlongViewShowsBlueBoundaryAndRedZonesInsideTheTunnel) {
  const auto pf = test::make_synthetic_tunnel();
  const Rendered r = render(pf, scene::ViewPreset::Along, kMapLayers);
  ASSERT_EQ(r.image.width, 320);
  ASSERT_EQ(r.image.height, 240);
  EXPECT_GT(scene::distinct_colors(r.image), 8) << "blank or flat image";
  const auto blue = scene::find_boundary_blue(r.image);
  const auto red = scene::find_traversable_red(r.image);
  EXPECT_GT(blue.count, 200);
  EXPECT_GT(red.count, 2000);
  // Both lie inside the projected tunnel boundary (a few pixels of line width allowed).
  ASSERT_LT(r.x0, r.x1);
  EXPECT_GE(blue.x0, r.x0 - 4); EXPECT_LE(blue.x1, r.x1 + 4);
  EXPECT_GE(blue.y0, r.y0 - 4); EXPECT_LE(blue.y1, r.y1 + 4);
  EXPECT_GE(red.x0, r.x0 - 4); EXPECT_LE(red.x1, r.x1 + 4);
  EXPECT_GE(red.y0, r.y0 - 4); EXPECT_LE(red.y1, r.y1 + 4);
  // The tunnel fills a good part of the view.
  EXPECT_GT((r.x1 - r.x0) * (r.y1 - r.y0), 320 * 240 / 6);
}

TEST(RenderScene, HidingTheMapLayersRemovesBlueAndRed) {
  const auto pf = test::make_synthetic_tunnel();
  const Rendered r = render(pf, scene::ViewPreset::Along, {Layer::Cloud, Layer::Planes});
  EXPECT_GE(scene::distinct_colors(r.image), 5);  // background + four wall classes
  EXPECT_EQ(scene::find_boundary_blue(r.image).count, 0);
  EXPECT_EQ(scene::find_traversable_red(r.image).count, 0);
}

TEST(RenderScene, EmptySceneIsBackgroundOnly) {
  scene::ProcessedFrame empty;
  const Rendered r = render(empty, scene::ViewPreset::Reset, {Layer::Cloud, Layer::Boundary});
  EXPECT_EQ(scene::distinct_colors(r.image), 1);
}

TEST(RenderScene, ViewsDiffer) {
  const auto pf = test::make_synthetic_tunnel();
  const auto along = render(pf, scene::ViewPreset::Along, kMapLayers).image;
  const auto top = render(pf, scene::ViewPreset::Top, kMapLayers).image;
  const auto side = render(pf, scene::ViewPreset::Side, kMapLayers).image;
  EXPECT_GT(scene::compare_images(along, top, 30).fraction_over, 0.2);
  EXPECT_GT(scene::compare_images(along, side, 30).fraction_over, 0.2);
  EXPECT_GT(scene::find_traversable_red(top).count, 1000);  // the roof's zones seen from above
}

TEST(RenderScene, LegendDrawsText) {
  const auto pf = test::make_synthetic_tunnel();
  const auto without = render(pf, scene::ViewPreset::Along, kMapLayers).image;
  auto with_layers = kMapLayers;
  with_layers.push_back(Layer::Legend);
  const auto with = render(pf, scene::ViewPreset::Along, with_layers).image;
  // The legend box occupies the lower right corner.
  const auto diff = scene::compare_images(without, with, 30);
  EXPECT_GT(diff.fraction_over, 0.003);
  EXPECT_LT(diff.fraction_over, 0.10);
}

// The real executable end to end: simulate a lab and a field frame (with manhole plate) with
// tunnelmap-cli, render them headless, check the PNGs.
TEST(RenderExecutable, SimulatedLabAndFieldFramesRenderWithMap) {
  const std::string dir = ::testing::TempDir() + "tunnelmap_render_exe";
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  struct Case { const char* preset; const char* extra; };
  for (const Case c : {Case{"lab", ""}, Case{"field", " --distance-to-manhole 1.5"}}) {
    const std::string data = dir + "/" + c.preset, png = dir + "/" + c.preset + ".png";
    ASSERT_EQ(std::system((std::string(TUNNELMAP_CLI_PATH) + " simulate --quiet --frames 1 --preset " +
                           c.preset + c.extra + " " + data + " > /dev/null").c_str()), 0);
    ASSERT_EQ(std::system((std::string("env -u DISPLAY ") + TUNNELMAP_RENDER_PATH + " " + data +
                           " --size 480x360 --layers cloud,planes,boundary,traversable,forbidden"
                           " --screenshot " + png + " > " + png + ".txt").c_str()), 0) << c.preset;
    std::ifstream summary(png + ".txt");
    const std::string line((std::istreambuf_iterator<char>(summary)), std::istreambuf_iterator<char>());
    const bool detected = line.find("tunnel ok") != std::string::npos ||
                          line.find("tunnel partial") != std::string::npos;
    const scene::RgbImage img = scene::load_png(png);
    EXPECT_EQ(img.width, 480);
    EXPECT_EQ(img.height, 360);
    EXPECT_GT(scene::distinct_colors(img), 20) << c.preset;
    // The lab frame must be detected; the field frame's detection belongs to the pipeline's
    // tests, so its map colours are only checked when the pipeline found the tunnel.
    if (std::string(c.preset) == "lab") {
      EXPECT_TRUE(detected) << line;
    }
    if (!detected) {
      std::cout << "[ NOTE     ] " << c.preset << ": pipeline did not detect the tunnel: " << line;
      EXPECT_EQ(scene::find_boundary_blue(img).count, 0);
      continue;
    }
    // Map colours appear, around the image centre where the tunnel is.
    const auto blue = scene::find_boundary_blue(img);
    const auto red = scene::find_traversable_red(img);
    EXPECT_GT(blue.count, 100) << c.preset;
    EXPECT_GT(red.count, 1000) << c.preset;
    if (red.count > 0) {
      EXPECT_LT(red.x0, 240); EXPECT_GT(red.x1, 240);
    }
  }
  // Bad usage and bad input: exit codes 2 and 3, no output file.
  EXPECT_EQ(WEXITSTATUS(std::system((std::string(TUNNELMAP_RENDER_PATH) + " " + dir +
                                     "/lab --screenshot " + dir + "/x.png --view sideways 2> /dev/null").c_str())), 2);
  EXPECT_EQ(WEXITSTATUS(std::system((std::string(TUNNELMAP_RENDER_PATH) + " " + dir +
                                     "/missing.png --screenshot " + dir + "/x.png 2> /dev/null").c_str())), 3);
  EXPECT_FALSE(std::filesystem::exists(dir + "/x.png"));
}

// Reference images: the shipped samples rendered by tunnelmap-render (640x360, along view) and
// compared with tests/ui/reference/*.png. The raw-cloud layer is left out (it is covered above
// and its speckle would only make the PNGs large). Regenerate after an intended visual change:
//   TUNNELMAP_UPDATE_REFERENCES=1 ctest -R ui.render
// then look at the new PNGs before committing them.
struct ReferenceCase {
  const char* name;    // reference file stem
  const char* sample;  // resources/sample/<sample>
  const char* preset;  // resources/presets/<preset>.json
  int frame;
};

// A rendered pixel "differs" when any channel is off by more than this (antialiased edges and
// point rasterisation move by a pixel; a changed colour or a missing layer moves far more)...
constexpr int kPixelTolerance = 48;
// ...and the image matches when at most this fraction of its pixels differ.
constexpr double kMaxDifferingFraction = 0.01;
constexpr const char* kReferenceLayers = "planes,boundary,traversable,forbidden,legend";

struct RenderRun {
  scene::RgbImage image;
  std::string summary;
  scene::PixelBox boundary;  // projected tunnel boundary, from the summary line
};

RenderRun run_renderer(const ReferenceCase& c, const std::string& png) {
  const std::string root = std::string(TUNNELMAP_UI_TEST_DIR) + "/../..";
  const std::string cmd = std::string("env -u DISPLAY ") + TUNNELMAP_RENDER_PATH + " " + root +
                          "/resources/sample/" + c.sample + " --params " + root + "/resources/presets/" +
                          c.preset + ".json --frame " + std::to_string(c.frame) +
                          " --size 640x360 --view along --layers " + kReferenceLayers +
                          " --screenshot " + png + " > " + png + ".txt";
  RenderRun r;
  if (std::system(cmd.c_str()) != 0) {
    ADD_FAILURE() << "failed: " << cmd;
    return r;
  }
  std::ifstream in(png + ".txt");
  std::getline(in, r.summary);
  const auto at = r.summary.find("boundary box ");
  if (at != std::string::npos &&
      std::sscanf(r.summary.c_str() + at, "boundary box %d,%d %d,%d", &r.boundary.x0, &r.boundary.y0,
                  &r.boundary.x1, &r.boundary.y1) == 4)
    r.boundary.count = 4;
  r.image = scene::load_png(png);
  return r;
}

TEST(ReferenceImages, SampleLabAndFieldFramesMatchTheirReferences) {
  const std::string dir = ::testing::TempDir() + "tunnelmap_reference";
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  const bool update = std::getenv("TUNNELMAP_UPDATE_REFERENCES") &&
                      std::string(std::getenv("TUNNELMAP_UPDATE_REFERENCES")) == "1";
  // Field frame 2 is the one nearest the manhole plate (1.8 m, dataset.json).
  for (const ReferenceCase c : {ReferenceCase{"lab_frame0", "lab", "lab", 0},
                                ReferenceCase{"field_frame2_manhole", "field", "field", 2}}) {
    SCOPED_TRACE(c.name);
    const std::string png = dir + "/" + c.name + ".png";
    const RenderRun r = run_renderer(c, png);
    ASSERT_EQ(r.image.width, 640);
    ASSERT_EQ(r.image.height, 360);
    ASSERT_NE(r.summary.find("tunnel ok"), std::string::npos) << r.summary;
    ASSERT_EQ(r.boundary.count, 4) << r.summary;
    EXPECT_GT(scene::distinct_colors(r.image), 20) << "blank or flat image";

    // Map colours are drawn, and (nearly) all of them inside the projected tunnel boundary. The
    // legend (lower right, its swatches are blue and red too) is blacked out first.
    scene::RgbImage map_only = r.image;
    for (int y = map_only.height * 64 / 100; y < map_only.height; ++y)
      for (int x = map_only.width * 83 / 100; x < map_only.width; ++x)
        std::fill_n(&map_only.rgb[(static_cast<std::size_t>(y) * map_only.width + x) * 3], 3, 0);
    const auto blue = scene::find_boundary_blue(map_only);
    const auto red = scene::find_traversable_red(map_only);
    const auto& b = r.boundary;
    const auto blue_in = scene::find_boundary_blue(map_only, b.x0 - 4, b.y0 - 4, b.x1 + 4, b.y1 + 4);
    const auto red_in = scene::find_traversable_red(map_only, b.x0 - 4, b.y0 - 4, b.x1 + 4, b.y1 + 4);
    EXPECT_GT(blue.count, 300);
    EXPECT_GT(red.count, 10000);
    EXPECT_GE(blue_in.count, blue.count * 0.98) << r.summary;
    EXPECT_GE(red_in.count, red.count * 0.98) << r.summary;
    // Red on both side walls: left and right of the image centre.
    EXPECT_LT(red.x0, 200);
    EXPECT_GT(red.x1, 440);

    const std::string ref_path = std::string(TUNNELMAP_UI_TEST_DIR) + "/reference/" + c.name + ".png";
    if (update) {
      std::filesystem::create_directories(std::string(TUNNELMAP_UI_TEST_DIR) + "/reference");
      scene::save_png(r.image, ref_path);
      std::cout << "[ UPDATED  ] " << ref_path << "\n";
      continue;
    }
    ASSERT_TRUE(std::filesystem::exists(ref_path))
        << ref_path << " is missing: run with TUNNELMAP_UPDATE_REFERENCES=1 to create it";
    const scene::RgbImage ref = scene::load_png(ref_path);
    const auto diff = scene::compare_images(r.image, ref, kPixelTolerance);
    std::cout << "[ COMPARE  ] " << c.name << ": " << diff.fraction_over * 100.0
              << " % of pixels differ (limit " << kMaxDifferingFraction * 100.0
              << " %), mean abs " << diff.mean_abs << "\n";
    EXPECT_LE(diff.fraction_over, kMaxDifferingFraction)
        << "differs from " << ref_path << "; the new image is " << png
        << " (TUNNELMAP_UPDATE_REFERENCES=1 regenerates the references)";
    // The tolerance is tight enough that a blank (background) or black image fails.
    scene::RgbImage black = ref, background = ref;
    std::fill(black.rgb.begin(), black.rgb.end(), 0);
    for (std::size_t i = 0; i < background.rgb.size(); i += 3)
      std::copy(ref.rgb.begin(), ref.rgb.begin() + 3, background.rgb.begin() + i);  // corner colour
    EXPECT_GT(scene::compare_images(black, ref, kPixelTolerance).fraction_over, 20 * kMaxDifferingFraction);
    EXPECT_GT(scene::compare_images(background, ref, kPixelTolerance).fraction_over, 20 * kMaxDifferingFraction);
  }
}

// The same input renders to the same pixels twice in a row (what makes the references stable).
TEST(ReferenceImages, RenderingIsDeterministic) {
  const std::string dir = ::testing::TempDir() + "tunnelmap_determinism";
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  const ReferenceCase c{"lab", "lab", "lab", 0};
  const RenderRun a = run_renderer(c, dir + "/a.png");
  const RenderRun b = run_renderer(c, dir + "/b.png");
  ASSERT_FALSE(a.image.empty());
  const auto diff = scene::compare_images(a.image, b.image, 0);
  EXPECT_EQ(diff.fraction_over, 0.0);
  EXPECT_EQ(a.summary.substr(a.summary.find(':')), b.summary.substr(b.summary.find(':')));
}

}  // namespace
}  // namespace tunnelmap
