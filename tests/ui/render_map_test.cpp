// tunnelmap-render on a map mesh PLY (as write_map_ply writes it): the oblique view shows the
// whole map, lit and in its zone colours; the other views work too; bad files fail cleanly.
// Also the CLI's helper that runs the renderer for the inspection report.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <sys/wait.h>

#include "ui/report/report_map_image.h"
#include "core/export/map_ply.h"
#include "core/export/plate_mesh.h"
#include "core/util/build_paths.h"
#include "tests/ui/fresh_dir.h"
#include "tests/ui/synthetic_tunnel.h"
#include "ui/scene/image_checks.h"
#include "ui/scene/rgb_image.h"
#include "ui/scene/scene_colors.h"

namespace tunnelmap {
namespace {

namespace fs = std::filesystem;

// A 12 m map of a 0.82 x 1.30 m tunnel in a world frame whose axis is not a world axis.
std::string write_map(const std::string& dir) {
  const auto pf = test::make_synthetic_tunnel(0.82, 1.30, 12.0);
  Eigen::Isometry3d to_world = Eigen::Isometry3d::Identity();
  to_world.linear() = (Eigen::AngleAxisd(0.4, Eigen::Vector3d::UnitZ()) *
                       Eigen::AngleAxisd(-0.5 * M_PI, Eigen::Vector3d::UnitX())).toRotationMatrix();
  to_world.translation() = Eigen::Vector3d(3.0, -1.0, 0.7);
  const std::string path = dir + "/map.ply";
  write_map_ply(path, pf.result.map, nlohmann::json::object(), to_world);
  return path;
}

// The same tunnel in its own frame with a plate across it at 6 m, its manhole 0.5 x 0.7 m.
std::string write_map_with_plate(const std::string& dir) {
  const TunnelMap map = test::make_synthetic_tunnel(0.82, 1.30, 12.0).result.map;
  PlateOutline plate;
  const Eigen::Vector3d axis = map.axis_dir.normalized(), up = map.up.normalized();
  plate.centre = map.axis_point + 6.0 * axis;
  plate.up = up;
  plate.left = up.cross(axis).normalized();
  plate.width_m = map.width_m;
  plate.height_m = map.height_m;
  plate.opening = PlateOpening{0.0, 0.0, 0.5, 0.7, "ellipse", 0.0};
  const std::string path = dir + "/plated.ply";
  write_sectioned_map_ply(path, {map}, nlohmann::json::object(), {plate});
  return path;
}

// Lit plate grey (the map's plates are 150,155,165): nearly equal channels, neither dark nor the
// background.
int grey_pixels(const scene::RgbImage& img) {
  int n = 0;
  for (int y = 0; y < img.height; ++y)
    for (int x = 0; x < img.width; ++x) {
      const int r = img.at(x, y)[0], g = img.at(x, y)[1], b = img.at(x, y)[2];
      if (r > 80 && std::abs(r - g) < 25 && b >= g && b - r < 40) ++n;
    }
  return n;
}

struct RenderRun {
  int status = -1;
  std::string line;
};

RenderRun render(const std::string& args, const std::string& png) {
  RenderRun r;
  const std::string cmd = std::string("env -u DISPLAY ") + TUNNELMAP_RENDER_PATH + " " + args + " --screenshot " +
                          png + " > " + png + ".txt 2>&1";
  const int raw = std::system(cmd.c_str());
  r.status = WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
  std::ifstream in(png + ".txt");
  std::getline(in, r.line);
  return r;
}

// Pixels that are not the scene background.
double foreground_fraction(const scene::RgbImage& img) {
  const int bg[3] = {static_cast<int>(scene::kBackground[0] * 255 + 0.5), static_cast<int>(scene::kBackground[1] * 255 + 0.5),
                     static_cast<int>(scene::kBackground[2] * 255 + 0.5)};
  std::size_t n = 0;
  for (int y = 0; y < img.height; ++y)
    for (int x = 0; x < img.width; ++x) {
      const auto* p = img.at(x, y);
      if (std::abs(p[0] - bg[0]) + std::abs(p[1] - bg[1]) + std::abs(p[2] - bg[2]) > 30) ++n;
    }
  return static_cast<double>(n) / (static_cast<double>(img.width) * img.height);
}

// Lit zone colours: red (traversable) and orange (forbidden) by hue, bright enough not to read
// as black.
void count_zone_colours(const scene::RgbImage& img, int& red, int& orange) {
  red = orange = 0;
  for (int y = 0; y < img.height; ++y)
    for (int x = 0; x < img.width; ++x) {
      const int r = img.at(x, y)[0], g = img.at(x, y)[1], b = img.at(x, y)[2];
      if (r < 90) continue;
      if (g < 0.3 * r && b < 0.3 * r) ++red;
      else if (g > 0.4 * r && g < 0.8 * r && b < 0.3 * r) ++orange;
    }
}

TEST(RenderMapPly, ObliqueViewShowsTheWholeMapLitInItsColours) {
  const std::string dir = fresh_dir("tunnelmap_render_map");
  const std::string ply = write_map(dir), png = dir + "/map.png";
  const RenderRun r = render(ply + " --size 640x400", png);  // a mesh PLY defaults to the oblique view
  ASSERT_EQ(r.status, 0) << r.line;
  EXPECT_NE(r.line.find("view oblique, map mesh"), std::string::npos) << r.line;
  // The boundary runs from 0.5 to 12 m.
  const auto len = r.line.find("(length ");
  ASSERT_NE(len, std::string::npos) << r.line;
  EXPECT_NEAR(std::atof(r.line.c_str() + len + 8), 11.5, 0.01) << r.line;
  // The whole map is in the image and fills most of it.
  int x0 = 0, y0 = 0, x1 = 0, y1 = 0;
  const auto at = r.line.find("mesh box ");
  ASSERT_NE(at, std::string::npos) << r.line;
  ASSERT_EQ(std::sscanf(r.line.c_str() + at, "mesh box %d,%d %d,%d", &x0, &y0, &x1, &y1), 4) << r.line;
  EXPECT_GE(x0, 0);
  EXPECT_GE(y0, 0);
  EXPECT_LT(x1, 640);
  EXPECT_LT(y1, 400);
  EXPECT_GT(x1 - x0, 640 * 7 / 10) << r.line;
  const scene::RgbImage img = scene::load_png(png);
  ASSERT_EQ(img.width, 640);
  ASSERT_EQ(img.height, 400);
  EXPECT_GT(foreground_fraction(img), 0.15);
  int red = 0, orange = 0;
  count_zone_colours(img, red, orange);
  EXPECT_GT(red, 3000) << "traversable zones missing or too dark";
  EXPECT_GT(orange, 1000) << "forbidden zones missing or too dark";
  if (const char* dump = std::getenv("TUNNELMAP_UI_DUMP")) fs::copy_file(png, std::string(dump) + "/map_oblique.png", fs::copy_options::overwrite_existing);
}

TEST(RenderMapPly, AlongSideAndTopViewsWorkOnAMap) {
  const std::string dir = fresh_dir("tunnelmap_render_map_views");
  const std::string ply = write_map(dir);
  const scene::RgbImage oblique = [&] {
    EXPECT_EQ(render(ply + " --size 320x200 --view oblique", dir + "/oblique.png").status, 0);
    return scene::load_png(dir + "/oblique.png");
  }();
  for (const char* view : {"along", "side", "top"}) {
    const std::string png = dir + "/" + view + ".png";
    const RenderRun r = render(ply + " --size 320x200 --view " + view, png);
    ASSERT_EQ(r.status, 0) << view << ": " << r.line;
    EXPECT_NE(r.line.find(std::string("view ") + view), std::string::npos) << r.line;
    const scene::RgbImage img = scene::load_png(png);
    // Seen from the side or from above the 12 m map is a thin strip, but it spans the image.
    EXPECT_GT(foreground_fraction(img), 0.02) << view;
    int x0 = 0, y0 = 0, x1 = 0, y1 = 0;
    const auto at = r.line.find("mesh box ");
    ASSERT_NE(at, std::string::npos) << r.line;
    ASSERT_EQ(std::sscanf(r.line.c_str() + at, "mesh box %d,%d %d,%d", &x0, &y0, &x1, &y1), 4) << r.line;
    if (std::string(view) != "along") {
      EXPECT_GT(std::max((x1 - x0) / 320.0, (y1 - y0) / 200.0), 0.8) << r.line;
    }
    EXPECT_GT(scene::compare_images(img, oblique, 30).fraction_over, 0.1) << view << " looks like oblique";
  }
}

TEST(RenderMapPly, TheCutawayShowsThePlateInsideTheBox) {
  const std::string dir = fresh_dir("tunnelmap_render_map_cutaway");
  const std::string ply = write_map_with_plate(dir);
  const RenderRun closed = render(ply + " --size 640x400", dir + "/closed.png");
  const RenderRun open = render(ply + " --size 640x400 --cutaway", dir + "/open.png");
  ASSERT_EQ(closed.status, 0) << closed.line;
  ASSERT_EQ(open.status, 0) << open.line;
  // The frame is still the whole tunnel's: the same size either way.
  EXPECT_NE(open.line.find("width 0.82"), std::string::npos) << open.line;
  EXPECT_NE(open.line.find("height 1.3"), std::string::npos) << open.line;
  const int hidden = grey_pixels(scene::load_png(dir + "/closed.png"));
  const int shown = grey_pixels(scene::load_png(dir + "/open.png"));
  // A 0.82 x 1.30 m plate less its manhole, seen obliquely in a 12 m view 640 px wide.
  EXPECT_GT(shown, 400) << "the plate does not show through the cutaway";
  EXPECT_LT(hidden, shown / 4) << "the closed box should hide its plate";
  int red = 0, orange = 0;
  count_zone_colours(scene::load_png(dir + "/open.png"), red, orange);
  EXPECT_GT(red, 3000) << "the floor and the left wall should still show";
  // One frame's scene has no map to open.
  const RenderRun frame = render(std::string(TUNNELMAP_SOURCE_DIR) + "/resources/sample/lab/depth/000000.png --cutaway",
                                 dir + "/frame.png");
  EXPECT_EQ(frame.status, 2) << frame.line;
  EXPECT_NE(frame.line.find("--cutaway"), std::string::npos) << frame.line;
  EXPECT_FALSE(fs::exists(dir + "/frame.png"));
  if (const char* dump = std::getenv("TUNNELMAP_UI_DUMP")) fs::copy_file(dir + "/open.png", std::string(dump) + "/map_cutaway.png", fs::copy_options::overwrite_existing);
}

TEST(RenderMapPly, BadPlyIsExitThreeAndNoImage) {
  const std::string dir = fresh_dir("tunnelmap_render_map_bad");
  { std::ofstream(dir + "/bad.ply") << "ply\nformat ascii 1.0\nelement vertex 99\n"; }
  const RenderRun r = render(dir + "/bad.ply", dir + "/bad.png");
  EXPECT_EQ(r.status, 3) << r.line;
  EXPECT_NE(r.line.find("bad.ply"), std::string::npos) << r.line;
  EXPECT_FALSE(fs::exists(dir + "/bad.png"));
}

TEST(MapImage, RendersThroughTheRendererOrSaysWhyNot) {
  const std::string dir = fresh_dir("tunnelmap_map_image");
  const std::string ply = write_map_with_plate(dir);
  std::string why;
  EXPECT_TRUE(render_map_image_with(TUNNELMAP_RENDER_PATH, ply, dir + "/map.png", why)) << why;
  EXPECT_TRUE(why.empty()) << why;
  const scene::RgbImage img = scene::load_png(dir + "/map.png");
  EXPECT_EQ(img.width, 1600);
  EXPECT_EQ(img.height, 1000);
  // The report's image looks into the box: its plate shows (6 times the pixels of a 640 px one).
  EXPECT_GT(grey_pixels(img), 2000) << "the report's map image hides the plates";

  EXPECT_FALSE(render_map_image_with(dir + "/no-such-renderer", ply, dir + "/x.png", why));
  EXPECT_NE(why.find("no-such-renderer"), std::string::npos) << why;
  EXPECT_EQ(why.find('\n'), std::string::npos) << why;

  { std::ofstream(dir + "/bad.ply") << "not a ply"; }
  EXPECT_FALSE(render_map_image_with(TUNNELMAP_RENDER_PATH, dir + "/bad.ply", dir + "/x.png", why));
  EXPECT_NE(why.find("bad.ply"), std::string::npos) << why;
  EXPECT_EQ(why.find('\n'), std::string::npos) << why;
  EXPECT_FALSE(fs::exists(dir + "/x.png"));

  // A renderer that does not know an option the report passes (an older build): its parser's
  // error, named after it, not its "--help" hint.
  const std::string older = dir + "/older-render";
  {
    std::ofstream(older) << "#!/bin/sh\necho 'The following arguments were not expected: --cutaway' >&2\n"
                            "echo 'Run with --help for more information.' >&2\nexit 109\n";
  }
  fs::permissions(older, fs::perms::owner_all);
  EXPECT_FALSE(render_map_image_with(older, ply, dir + "/z.png", why));
  EXPECT_EQ(why, older + ": The following arguments were not expected: --cutaway");

  // From a test executable there is no renderer beside it: a reason, not a crash.
  EXPECT_FALSE(render_map_image(ply, dir + "/y.png", why));
  EXPECT_FALSE(why.empty());
}

}  // namespace
}  // namespace tunnelmap
