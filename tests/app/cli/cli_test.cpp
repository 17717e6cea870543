// The tunnelmap-cli contract: commands, JSON fields, PLY output, exit codes, one-line errors
// and no partial output files. Runs the real binary on real files.
#include <gtest/gtest.h>

#include <filesystem>
#include <tuple>
#include <nlohmann/json.hpp>
#include <opencv2/imgcodecs.hpp>
#include <pcl/PolygonMesh.h>
#include <pcl/io/ply_io.h>
#include <pcl/conversions.h>
#include <pcl/point_types.h>

#include "core/util/build_paths.h"
#include "tests/support/cli_runner.h"

using namespace tunnelmap::testing;
namespace fs = std::filesystem;

namespace {
const std::string kSample = std::string(TUNNELMAP_SOURCE_DIR) + "/resources/sample/lab";
const std::string kLabPreset = std::string(TUNNELMAP_SOURCE_DIR) + "/resources/presets/lab.json";
const std::string kRealFrame = std::string(TUNNELMAP_SOURCE_DIR) + "/resources/real-frames/rtabmap_lab_depth_17.png";

nlohmann::json read_json(const std::string& path) {
  std::ifstream in(path);
  return nlohmann::json::parse(in);
}
}  // namespace

TEST(Cli, DetectWritesTheDocumentedJsonAndAMapPly) {
  IoTempDir tmp;
  const auto r = run_cli("detect " + kSample + " --params " + kLabPreset + " --json " + tmp.file("r.json") +
                         " --ply " + tmp.file("map.ply"));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("summary: 3/3 frames detected"), std::string::npos) << r.out;
  EXPECT_EQ(count_lines(r.out), 4);  // one line per frame and the summary

  const auto j = read_json(tmp.file("r.json"));
  EXPECT_EQ(j["tool"], "tunnelmap");
  EXPECT_EQ(j["method"], "pgc");
  EXPECT_TRUE(j["version"].is_string());
  EXPECT_DOUBLE_EQ(j["params"]["grow.distance_mm"].get<double>(), 8.0);  // from the preset
  ASSERT_EQ(j["frames"].size(), 3u);
  for (const auto& f : j["frames"]) {
    for (const char* key : {"index", "source", "detected", "status", "width_m", "height_m", "planes", "walls", "timings_ms"})
      EXPECT_TRUE(f.contains(key)) << key;
    EXPECT_TRUE(f["detected"].get<bool>());
    EXPECT_EQ(f["status"], "ok");
    EXPECT_NEAR(f["width_m"].get<double>(), 0.82, 0.015);
    EXPECT_NEAR(f["height_m"].get<double>(), 1.30, 0.015);
    for (const char* wall : {"left", "right", "top", "bottom"}) {
      ASSERT_TRUE(f["walls"].contains(wall)) << wall;
      EXPECT_EQ(f["walls"][wall]["normal"].size(), 3u);
      EXPECT_TRUE(f["walls"][wall]["offset_m"].is_number());
    }
    for (const char* t : {"normals", "planes", "tunnel", "total"}) EXPECT_GE(f["timings_ms"][t].get<double>(), 0.0) << t;
  }
  const auto& s = j["summary"];
  EXPECT_EQ(s["frames"], 3);
  EXPECT_EQ(s["detected"], 3);
  for (const char* key : {"width_mean_m", "width_std_m", "height_mean_m", "height_std_m"}) EXPECT_TRUE(s[key].is_number()) << key;
  EXPECT_NEAR(s["width_mean_m"].get<double>(), 0.82, 0.010);

  pcl::PolygonMesh mesh;
  ASSERT_EQ(pcl::io::loadPLYFile(tmp.file("map.ply"), mesh), 0);
  EXPECT_GT(mesh.polygons.size(), 20u);
  pcl::PointCloud<pcl::PointXYZRGB> cloud;
  pcl::fromPCLPointCloud2(mesh.cloud, cloud);
  int blue = 0, red = 0;
  for (const auto& p : cloud) {
    blue += p.b > 200 && p.r < 80;
    red += p.r > 200 && p.g < 60 && p.b < 60;
  }
  EXPECT_GT(blue, 0);
  EXPECT_GT(red, 0);
  const std::string text = slurp(tmp.file("map.ply"));
  EXPECT_NE(text.find("comment param grow.distance_mm 8"), std::string::npos);
}

TEST(Cli, PlanesReportsPlanesMedianTimingsAndALabelImage) {
  IoTempDir tmp;
  const auto r = run_cli("planes " + kRealFrame + " --intrinsics 525,525,319.5,239.5 --repeat 3 --json " +
                         tmp.file("p.json") + " --labels " + tmp.file("labels.png") + " --set grow.cell_px=0");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = read_json(tmp.file("p.json"));
  ASSERT_EQ(j["frames"].size(), 1u);
  const auto& f = j["frames"][0];
  ASSERT_GT(f["planes"].size(), 3u);
  for (const auto& p : f["planes"]) {
    for (const char* key : {"id", "normal", "centroid", "points", "area_m2"}) EXPECT_TRUE(p.contains(key)) << key;
    EXPECT_GE(p["points"].get<int>(), 40);
    EXPECT_GE(p["area_m2"].get<double>(), 0.004);
  }
  for (const char* t : {"normals", "planes", "total"}) EXPECT_GT(f["timings_ms"][t].get<double>(), 0.0) << t;
  // The plane stage's parts (coarse-to-fine by default), each within the stage's time.
  for (const char* t : {"grow", "refine", "contours"}) {
    ASSERT_TRUE(f["timings_ms"].contains(t)) << t;
    EXPECT_GT(f["timings_ms"][t].get<double>(), 0.0) << t;
    EXPECT_LE(f["timings_ms"][t].get<double>(), f["timings_ms"]["planes"].get<double>() * 1.05) << t;
  }
  const cv::Mat labels = cv::imread(tmp.file("labels.png"), cv::IMREAD_ANYDEPTH);
  ASSERT_EQ(labels.type(), CV_16UC1);
  double max_label = 0;
  cv::minMaxLoc(labels, nullptr, &max_label);
  EXPECT_EQ(static_cast<std::size_t>(max_label), f["planes"].size());
}

// The cell order reports its own stages and no normals stage (it reads no per-pixel normals).
TEST(Cli, PlanesInCellOrderReportsItsStages) {
  IoTempDir tmp;
  const auto r = run_cli("planes " + kRealFrame + " --intrinsics 525,525,319.5,239.5 --repeat 3 --json " +
                         tmp.file("p.json") + " --set grow.cell_px=8");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = read_json(tmp.file("p.json"));
  const auto& f = j["frames"][0];
  ASSERT_GT(f["planes"].size(), 3u);
  const auto& t = f["timings_ms"];
  EXPECT_EQ(t.value("normals", 0.0), 0.0);
  for (const char* stage : {"cell_fits", "block_normals", "grow", "assign", "contours"}) {
    ASSERT_TRUE(t.contains(stage)) << stage;
    EXPECT_GT(t[stage].get<double>(), 0.0) << stage;
    EXPECT_LE(t[stage].get<double>(), t["planes"].get<double>() * 1.05) << stage;
  }
}

TEST(Cli, ParamsListsEveryKeyWithDefaultsAndRanges) {
  const auto r = run_cli("params");
  ASSERT_EQ(r.exit_code, 0);
  for (const char* key : {"grow.angle_deg", "grow.distance_mm", "grow.candidate_distance_mm", "grow.min_points",
                          "grow.min_area_m2", "cloud.max_range_m", "grow.neighbourhood_n", "tunnel.zone_cluster_mm"})
    EXPECT_NE(r.out.find(key), std::string::npos) << key;
  const auto j = run_cli("params --json");
  ASSERT_EQ(j.exit_code, 0);
  EXPECT_GE(nlohmann::json::parse(j.out).size(), 20u);
}

TEST(Cli, BadUsageExitsTwoWithOneLine) {
  const std::vector<std::string> cases = {"frobnicate", "detect", "detect " + kSample + " --set grow.nope=1",
                                 "detect " + kSample + " --set grow.angle_deg=-4",
                                 "detect " + kSample + " --set grow.angle_deg=abc",
                                 "detect " + kSample + " --intrinsics 1,2,3", "detect " + kSample + " --up 0,0,0",
                                 "planes " + kRealFrame + " --repeat 0"};
  for (const std::string& args : cases) {
    const auto r = run_cli(args);
    EXPECT_EQ(r.exit_code, 2) << args << "\n" << r.err;
    EXPECT_EQ(count_lines(r.err), 1) << args << "\n" << r.err;
  }
}

TEST(Cli, BadInputExitsThreeNamingTheFile) {
  IoTempDir tmp;
  write_text_file(tmp.file("corrupt.png"), "\x89PNG\r\n\x1a\nthis is not a png");
  write_text_file(tmp.file("bad.json"), "{\"params\": {\"grow.angle_deg\": ");
  write_text_file(tmp.file("unknown.json"), "{\"params\": {\"grow.nope\": 1}}");
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"detect " + tmp.file("missing.png"), "missing.png"},
      {"detect " + tmp.file("corrupt.png"), "corrupt.png"},
      {"detect " + kSample + " --params " + tmp.file("bad.json"), "bad.json"},
      {"detect " + kSample + " --params " + tmp.file("unknown.json"), "grow.nope"},
      {"planes " + tmp.file("missing-folder"), "missing-folder"},
  };
  for (const auto& [args, needle] : cases) {
    const auto r = run_cli(args);
    EXPECT_EQ(r.exit_code, 3) << args << "\n" << r.err;
    EXPECT_EQ(count_lines(r.err), 1) << args << "\n" << r.err;
    EXPECT_NE(r.err.find(needle), std::string::npos) << r.err;
  }
}

TEST(Cli, AFrameSmallerThanTheNormalWindowIsRefused) {
  // normals.smoothing_px (default 10) is the side of the normal window: a smaller frame has no
  // pixel with a normal, so it is an input error (exit 3, one line naming the file), not a run.
  IoTempDir tmp;
  ASSERT_TRUE(cv::imwrite(tmp.file("tiny.png"), cv::Mat(1, 1, CV_16UC1, cv::Scalar(1500))));
  ASSERT_TRUE(cv::imwrite(tmp.file("narrow.png"), cv::Mat(40, 9, CV_16UC1, cv::Scalar(1500))));
  ASSERT_TRUE(cv::imwrite(tmp.file("window.png"), cv::Mat(12, 12, CV_16UC1, cv::Scalar(1500))));
  const std::string tiny = tmp.file("tiny.png"), narrow = tmp.file("narrow.png"), window = tmp.file("window.png");
  const std::vector<std::tuple<std::string, std::string, std::string>> refused = {
      {"detect " + tiny + " --json " + tmp.file("d.json") + " --ply " + tmp.file("d.ply"), tiny, "1x1 pixels"},
      {"detect " + tiny + " --method ransac --json " + tmp.file("d.json"), tiny, "1x1 pixels"},
      {"planes " + tiny + " --json " + tmp.file("p.json") + " --labels " + tmp.file("p.png"), tiny, "1x1 pixels"},
      {"detect " + narrow + " --json " + tmp.file("d.json"), narrow, "9x40 pixels"},
      {"planes " + window + " --set normals.smoothing_px=13 --json " + tmp.file("p.json"), window,
       "smaller than the 13x13 normal window"},
  };
  for (const auto& [args, file, problem] : refused) {
    const auto r = run_cli(args);
    EXPECT_EQ(r.exit_code, 3) << args << "\n" << r.err << r.out;
    EXPECT_EQ(count_lines(r.err), 1) << args << "\n" << r.err;
    EXPECT_EQ(r.err.rfind("tunnelmap-cli: " + file + ": image is ", 0), 0u) << r.err;
    EXPECT_NE(r.err.find(problem), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("normals.smoothing_px"), std::string::npos) << r.err;
    EXPECT_EQ(r.out, "") << args;  // refused before any frame was processed
    for (const char* out : {"d.json", "d.ply", "p.json", "p.png", "p_000000.png"})
      EXPECT_FALSE(fs::exists(tmp.file(out))) << args << " left " << out;
  }
  // A frame as large as the window is processed (no tunnel in a flat 12x12 frame, exit 0).
  for (const char* cmd : {"detect", "planes"}) {
    const auto r = run_cli(std::string(cmd) + " " + window);
    EXPECT_EQ(r.exit_code, 0) << cmd << "\n" << r.err;
  }
}

TEST(Cli, FailedRunLeavesNoPartialOutputAndKeepsExistingFiles) {
  IoTempDir tmp;
  write_text_file(tmp.file("corrupt.png"), "not an image");
  write_text_file(tmp.file("old.json"), "previous results");
  auto r = run_cli("detect " + tmp.file("corrupt.png") + " --json " + tmp.file("old.json") + " --ply " + tmp.file("new.ply"));
  EXPECT_EQ(r.exit_code, 3);
  EXPECT_EQ(slurp(tmp.file("old.json")), "previous results");
  EXPECT_FALSE(fs::exists(tmp.file("new.ply")));
  // An output folder that does not exist: error, nothing written anywhere.
  r = run_cli("detect " + kSample + " --json " + tmp.file("no/such/dir/r.json"));
  EXPECT_EQ(r.exit_code, 3);
  EXPECT_NE(r.err.find("r.json"), std::string::npos);
  for (const auto& e : fs::directory_iterator(tmp.path()))
    EXPECT_EQ(e.path().filename().string().find(".tmp-"), std::string::npos) << e.path();
}

TEST(Cli, SimulateThenDetectRoundTrip) {
  IoTempDir tmp;
  const std::string dir = tmp.file("field");
  auto r = run_cli("simulate " + dir + " --preset field --frames 2 --seed 5 --quiet");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  r = run_cli("detect " + dir + " --params " + std::string(TUNNELMAP_SOURCE_DIR) + "/resources/presets/field.json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("summary: 2/2 frames detected"), std::string::npos) << r.out;
}

TEST(Cli, AFrameWithoutATunnelStillExitsZero) {
  // An office room is no tunnel: status explains why, exit code is still 0.
  IoTempDir tmp;
  const auto r = run_cli("detect " + std::string(TUNNELMAP_SOURCE_DIR) +
                         "/resources/real-frames/pcl_office_depth.png --intrinsics 525,525,320,240 --json " + tmp.file("o.json"));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = read_json(tmp.file("o.json"));
  EXPECT_FALSE(j["frames"][0]["detected"].get<bool>());
  EXPECT_NE(j["frames"][0]["status"], "ok");
  EXPECT_TRUE(j["frames"][0]["width_m"].is_null());
}

TEST(Cli, AResultsJsonServesAsAParameterPreset) {
  // The params a run used can be replayed: `--params results.json` reuses its "params".
  IoTempDir tmp;
  auto r = run_cli("detect " + kSample + " --params " + kLabPreset + " --set grow.angle_deg=5.5 -q --json " + tmp.file("a.json"));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  r = run_cli("detect " + kSample + " -q --params " + tmp.file("a.json") + " --json " + tmp.file("b.json"));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto a = read_json(tmp.file("a.json")), b = read_json(tmp.file("b.json"));
  EXPECT_EQ(a["params"], b["params"]);
  EXPECT_DOUBLE_EQ(b["params"]["grow.angle_deg"].get<double>(), 5.5);
  EXPECT_EQ(a["summary"]["width_mean_m"], b["summary"]["width_mean_m"]);
}
