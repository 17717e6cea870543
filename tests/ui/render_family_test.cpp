// tunnelmap-render reads its input as `detect` does (--intrinsics, --up, --depth-scale, --params,
// --set give the same tunnel), and draws a posed dataset's station map, over the fused mesh when
// one is given; misuse fails with one line and no image.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>
#include <sys/wait.h>

#include "core/util/build_paths.h"
#include "tests/ui/fresh_dir.h"
#include "ui/scene/image_checks.h"
#include "ui/scene/rgb_image.h"

namespace tunnelmap {
namespace {

namespace fs = std::filesystem;

struct ProcessRun {
  int status = -1;
  std::string out;
};

ProcessRun run_process(const std::string& command_line) {
  const std::string log = ::testing::TempDir() + "render_family_log.txt";
  const int raw = std::system(("env -u DISPLAY " + command_line + " > " + log + " 2>&1").c_str());
  ProcessRun r;
  r.status = WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
  std::ifstream in(log);
  r.out.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  return r;
}

ProcessRun render(const std::string& args) { return run_process(std::string(TUNNELMAP_RENDER_PATH) + " " + args); }
ProcessRun cli(const std::string& args) { return run_process(std::string(TUNNELMAP_CLI_PATH) + " " + args); }

const std::string kLabFrame = std::string(TUNNELMAP_SOURCE_DIR) + "/resources/sample/lab/depth/000000.png";

double number_after(const std::string& text, const std::string& key) {
  const auto at = text.find(key);
  return at == std::string::npos ? -1.0 : std::atof(text.c_str() + at + key.size());
}

// The width `detect --json` measures with the same input options.
double detect_width(const std::string& dir, const std::string& options) {
  const ProcessRun r = cli("detect " + kLabFrame + " " + options + " --json " + dir + "/d.json -q");
  EXPECT_EQ(r.status, 0) << r.out;
  std::ifstream in(dir + "/d.json");
  const nlohmann::json j = nlohmann::json::parse(in);
  return j["frames"][0]["width_m"].is_number() ? j["frames"][0]["width_m"].get<double>() : -1.0;
}

TEST(RenderInputOptions, IntrinsicsUpAndSetGiveTheTunnelDetectMeasures) {
  const std::string dir = fresh_dir("tunnelmap_render_family_options");
  // Focal lengths 10 % longer than the default: every lateral size shrinks by about 10 %.
  const std::string options =
      "--intrinsics 627.5,627.5,319.5,239.5 --up 0,-1,0 --depth-scale 1000 --set grow.angle_deg=4.5";
  const ProcessRun plain = render(kLabFrame + " --size 320x200 --screenshot " + dir + "/plain.png");
  const ProcessRun given = render(kLabFrame + " " + options + " --size 320x200 --screenshot " + dir + "/given.png");
  ASSERT_EQ(plain.status, 0) << plain.out;
  ASSERT_EQ(given.status, 0) << given.out;
  const double w_plain = number_after(plain.out, "(width "), w_given = number_after(given.out, "(width ");
  ASSERT_GT(w_plain, 0.5) << plain.out;
  ASSERT_GT(w_given, 0.5) << given.out;
  EXPECT_NEAR(w_given, detect_width(dir, options), 1e-4) << given.out;
  EXPECT_NEAR(w_plain, detect_width(dir, ""), 1e-4) << plain.out;
  EXPECT_NEAR(w_given / w_plain, 570.3 / 627.5, 0.02) << plain.out << given.out;
}

TEST(RenderInputOptions, MalformedIntrinsicsAreBadUsageWithNoImage) {
  const std::string dir = fresh_dir("tunnelmap_render_family_bad_intrinsics");
  const ProcessRun r = render(kLabFrame + " --intrinsics 1,2,3 --screenshot " + dir + "/x.png");
  EXPECT_EQ(r.status, 2) << r.out;
  EXPECT_NE(r.out.find("--intrinsics expects 4"), std::string::npos) << r.out;
  EXPECT_FALSE(fs::exists(dir + "/x.png"));
}

// A posed walk down one section, simulated and fused once for the suite.
class RenderStationMap : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir = fresh_dir("tunnelmap_render_station_map");
    const ProcessRun sim = cli("simulate " + dir + "/walk --preset lab --frames 12 --seed 3 --quiet --walk 0,2,4");
    ASSERT_EQ(sim.status, 0) << sim.out;
    const ProcessRun fuse = cli("fuse " + dir + "/walk --mesh " + dir + "/fused.ply --quiet");
    ASSERT_EQ(fuse.status, 0) << fuse.out;
  }
  static std::string dir;
};
std::string RenderStationMap::dir;

TEST_F(RenderStationMap, DrawsTheStationMapOfTheDataset) {
  const ProcessRun r = render(dir + "/walk --map --size 480x300 --screenshot " + dir + "/map.png");
  ASSERT_EQ(r.status, 0) << r.out;
  EXPECT_NE(r.out.find("view oblique, station map "), std::string::npos) << r.out;
  // The map the CLI builds from the same dataset has as many stations and sections.
  const ProcessRun m = cli("map " + dir + "/walk --json " + dir + "/map.json -q");
  ASSERT_EQ(m.status, 0) << m.out;
  std::ifstream in(dir + "/map.json");
  const nlohmann::json j = nlohmann::json::parse(in);
  EXPECT_EQ(static_cast<std::size_t>(number_after(r.out, "station map ")), j["stations"].size()) << r.out;
  EXPECT_NE(r.out.find(std::to_string(j["sections"].size()) + " section(s)"), std::string::npos) << r.out;
  const scene::RgbImage img = scene::load_png(dir + "/map.png");
  EXPECT_EQ(img.width, 480);
  int x0 = 0, y0 = 0, x1 = 0, y1 = 0;
  const auto at = r.out.find("map box ");
  ASSERT_NE(at, std::string::npos) << r.out;
  ASSERT_EQ(std::sscanf(r.out.c_str() + at, "map box %d,%d %d,%d", &x0, &y0, &x1, &y1), 4) << r.out;
  EXPECT_GT(x1 - x0, 480 / 3) << r.out;  // the map fills a good part of the view
}

TEST_F(RenderStationMap, WithTheFusedMeshTheMeshShowsUnderTheMap) {
  const ProcessRun alone = render(dir + "/walk --map --size 480x300 --screenshot " + dir + "/alone.png");
  const ProcessRun over = render(dir + "/walk --map --mesh " + dir + "/fused.ply --size 480x300 --screenshot " + dir +
                          "/over.png");
  ASSERT_EQ(alone.status, 0) << alone.out;
  ASSERT_EQ(over.status, 0) << over.out;
  EXPECT_NE(over.out.find("fused mesh "), std::string::npos) << over.out;
  EXPECT_GT(number_after(over.out, "fused mesh "), 1000) << over.out;
  // Same camera (the map frames the view), different picture: the mesh's grey surface.
  const auto diff = scene::compare_images(scene::load_png(dir + "/alone.png"), scene::load_png(dir + "/over.png"), 30);
  EXPECT_GT(diff.fraction_over, 0.05);
}

TEST_F(RenderStationMap, MisuseIsOneLineAndNoImage) {
  const ProcessRun mesh_alone = render(dir + "/walk --mesh " + dir + "/fused.ply --screenshot " + dir + "/a.png");
  EXPECT_EQ(mesh_alone.status, 2) << mesh_alone.out;
  EXPECT_NE(mesh_alone.out.find("--mesh goes with --map"), std::string::npos) << mesh_alone.out;
  const ProcessRun not_dataset = render(kLabFrame + " --map --screenshot " + dir + "/b.png");
  EXPECT_EQ(not_dataset.status, 3) << not_dataset.out;
  EXPECT_NE(not_dataset.out.find("000000.png"), std::string::npos) << not_dataset.out;
  { std::ofstream(dir + "/bad.ply") << "ply\nformat ascii 1.0\nelement vertex 3\n"; }
  const ProcessRun bad_mesh = render(dir + "/walk --map --mesh " + dir + "/bad.ply --screenshot " + dir + "/c.png");
  EXPECT_EQ(bad_mesh.status, 3) << bad_mesh.out;
  EXPECT_NE(bad_mesh.out.find("bad.ply"), std::string::npos) << bad_mesh.out;
  for (const char* png : {"a.png", "b.png", "c.png"}) EXPECT_FALSE(fs::exists(dir + "/" + png)) << png;
  EXPECT_EQ(std::count(bad_mesh.out.begin(), bad_mesh.out.end(), '\n'), 1) << bad_mesh.out;
}

}  // namespace
}  // namespace tunnelmap
