// The map of the whole tunnel against simulated truth: sections that change along a walk, an
// approach to a manhole plate where the floor leaves the view, single frames with a wall out of
// view, and the `map` command's outputs.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <limits>
#include <memory>
#include <nlohmann/json.hpp>
#include <opencv2/imgcodecs.hpp>

#include "core/mapping/station_sections.h"
#include "core/util/build_paths.h"
#include "tests/support/cli_runner.h"
#include "tests/support/io_temp_dir.h"
#include "tests/support/shared_cli_fixture.h"

namespace tunnelmap {
namespace {

using testing::CliRun;
using testing::IoTempDir;
using testing::run_cli;
using testing::slurp;

const std::string kLabPreset = std::string(TUNNELMAP_TEST_DATA_DIR) + "/presets/lab.json";
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

nlohmann::json read_json(const std::string& path) { return nlohmann::json::parse(slurp(path)); }

// --- Section splitting -------------------------------------------------------------------

TEST(StationSections, ARunOfAgreeingStationsStartsASectionAndAnIsolatedOneIsAnOutlier) {
  std::vector<double> w, h;
  for (int k = 0; k < 10; ++k) w.push_back(0.840), h.push_back(1.300);
  w[4] = 0.900;  // one station off by 60 mm: an outlier
  for (int k = 0; k < 8; ++k) w.push_back(0.800), h.push_back(1.280);
  w.push_back(kNaN), h.push_back(kNaN);  // an unseen station stays in the section
  for (int k = 0; k < 2; ++k) w.push_back(0.801), h.push_back(1.281);
  const SectionSplit s = split_sections(w, h, 0.012, 3);
  ASSERT_EQ(s.sections.size(), 2u);
  EXPECT_EQ(s.sections[0].first, 0);
  EXPECT_EQ(s.sections[0].last, 9);
  EXPECT_NEAR(s.sections[0].width_m, 0.840, 1e-9);
  EXPECT_EQ(s.sections[1].first, 10);
  EXPECT_EQ(s.sections[1].last, 20);
  EXPECT_NEAR(s.sections[1].width_m, 0.800, 0.0011);
  EXPECT_NEAR(s.sections[1].height_m, 1.280, 0.0011);
  EXPECT_TRUE(s.outlier[4]);
  EXPECT_EQ(std::count(s.outlier.begin(), s.outlier.end(), true), 1);
}

TEST(StationSections, AChangeInHeightAloneStartsASection) {
  std::vector<double> w(12, 0.82), h(12, 1.30);
  for (int k = 6; k < 12; ++k) h[k] = 1.33;
  for (int k = 0; k < 12; k += 2) w[k] = kNaN;  // width seen at every other station only
  const SectionSplit s = split_sections(w, h, 0.012, 3);
  ASSERT_EQ(s.sections.size(), 2u);
  EXPECT_EQ(s.sections[1].first, 6);
  EXPECT_NEAR(s.sections[1].height_m, 1.33, 1e-9);
  EXPECT_NEAR(s.sections[1].width_m, 0.82, 1e-9);
}

TEST(StationSections, ARunShorterThanTheMinimumDoesNotSplit) {
  std::vector<double> w(15, 0.82), h(15, 1.30);
  w[7] = w[8] = 0.86;
  const SectionSplit s = split_sections(w, h, 0.012, 3);
  ASSERT_EQ(s.sections.size(), 1u);
  EXPECT_TRUE(s.outlier[7] && s.outlier[8]);
  EXPECT_NEAR(s.sections[0].width_m, 0.82, 1e-9);
}

// --- Simulated sequences -----------------------------------------------------------------

// Section k of the walk: world X range and true cross-section.
struct TrueSection {
  double from_x, to_x, width, height;
};

std::vector<TrueSection> true_sections(const nlohmann::json& dataset) {
  std::vector<TrueSection> out;
  for (const auto& s : dataset["ground_truth"]["sections"])
    out.push_back({s["from_x_m"].get<double>(), s["to_x_m"].get<double>(),
                   s["width_m"].get<double>(), s["height_m"].get<double>()});
  return out;
}

// A walk over three sections, simulated and mapped once per build (simulation is the slow part)
// and shared by every test here: tests read `shared` and write into their own `tmp`.
class SectionWalk : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    shared = testing::shared_cli_fixture(
        "SectionWalk", {{"simulate", "simulate {dir}/walk --preset lab --frames 40 --seed 5 --quiet"
                                     " --sections 1.5:0.84x1.30,1.5:0.80x1.28,2:0.82x1.32"
                                     " --walk -1,3,10 --walk-pose 0,0.5,0"},
                        {"map", "map {dir}/walk --params " + kLabPreset +
                                    " --design 0.82x1.30 --tolerance-mm 10 --json {dir}/map.json"
                                    " --csv {dir}/map.csv --ply {dir}/map.ply"}});
    ASSERT_TRUE(shared.ok()) << shared.error;
    map = testing::kept_cli_run(shared, "map");
  }
  static testing::SharedFixture shared;  // the simulated walk and the map's outputs
  static CliRun map;
  IoTempDir tmp;  // this test's own outputs
};
testing::SharedFixture SectionWalk::shared;
CliRun SectionWalk::map;

TEST_F(SectionWalk, StationProfileIsWithin4mmAwayFromTheJointsAndJointsWithin20cm) {
  ASSERT_EQ(map.exit_code, 0) << map.err;
  const nlohmann::json ds = read_json(shared.file("walk/dataset.json"));
  const nlohmann::json m = read_json(shared.file("map.json"));
  const std::vector<TrueSection> truth = true_sections(ds);
  ASSERT_EQ(truth.size(), 3u);
  const double ox = m["frame"]["origin"][0].get<double>(), ax = m["frame"]["axis"][0].get<double>();
  ASSERT_GT(ax, 0.999);  // the walk goes along +X
  double ew = 0, eh = 0;
  int nw = 0, nh = 0;
  for (const auto& st : m["stations"]) {
    const double x = ox + ax * st["station_m"].get<double>();
    bool near_joint = false;
    const TrueSection* sec = nullptr;
    for (const TrueSection& t : truth) {
      if (x >= t.from_x && x < t.to_x) sec = &t;
      near_joint |= std::abs(x - t.from_x) < 0.2 || std::abs(x - t.to_x) < 0.2;
    }
    ASSERT_NE(sec, nullptr) << x;
    if (near_joint) continue;
    if (st["width_source"] == "measured") ew += std::abs(st["width_m"].get<double>() - sec->width), ++nw;
    if (st["height_source"] == "measured") eh += std::abs(st["height_m"].get<double>() - sec->height), ++nh;
  }
  ASSERT_GE(nw, 30);
  ASSERT_GE(nh, 30);
  EXPECT_LT(ew / nw, 0.004) << "width MAE over " << nw << " stations";
  EXPECT_LT(eh / nh, 0.004) << "height MAE over " << nh << " stations";

  // Three sections, each boundary within 0.2 m of the true joint, values within 4 mm.
  ASSERT_EQ(m["sections"].size(), 3u) << m["sections"].dump();
  for (int i = 0; i < 3; ++i) {
    const auto& s = m["sections"][i];
    EXPECT_NEAR(s["width_m"].get<double>(), truth[i].width, 0.004);
    EXPECT_NEAR(s["height_m"].get<double>(), truth[i].height, 0.004);
    EXPECT_GT(s["frames"].get<int>(), 5);
    if (i == 0) {
      EXPECT_TRUE(s["joint"].is_null());
    } else {
      EXPECT_NEAR(ox + ax * s["from_m"].get<double>(), truth[i].from_x, 0.2);
      // The joint says how it was found and how far off it may be; the truth lies within that.
      const double off = std::abs(ox + ax * s["from_m"].get<double>() - truth[i].from_x);
      EXPECT_TRUE(s["joint"]["source"] == "seen" || s["joint"]["source"] == "between_views") << s.dump();
      EXPECT_LE(off, s["joint"]["uncertainty_m"].get<double>() + 0.1) << s.dump();
    }
  }
}

TEST_F(SectionWalk, FarViewsCannotBiasASectionsSize) {
  // Seen 3-5 m ahead, a cell plane may span a wall's edge band and its middle plate; pooled
  // with other frames' positions it chained the two zones into one cluster (sections 2 and 3
  // came out 4.2 and 3.8 mm high with every view). A station's size is now each frame's own
  // width and height there (near views first), so with every view (map.near_range_m = 0) as with
  // the near ones alone, every section is within 1.5 mm.
  for (const char* near : {"2.5", "0"}) {
    const std::string json = tmp.file(std::string("near_") + near + ".json");
    const CliRun r = run_cli("map " + shared.file("walk") + " --params " + kLabPreset +
                             " --set map.near_range_m=" + near + " --json " + json + " -q");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const nlohmann::json m = read_json(json);
    const std::vector<TrueSection> truth = true_sections(read_json(shared.file("walk/dataset.json")));
    ASSERT_EQ(m["sections"].size(), truth.size());
    for (std::size_t i = 0; i < truth.size(); ++i) {
      EXPECT_NEAR(m["sections"][i]["height_m"].get<double>(), truth[i].height, 0.0015) << near << " " << i;
      EXPECT_NEAR(m["sections"][i]["width_m"].get<double>(), truth[i].width, 0.0015) << near << " " << i;
    }
  }
}

TEST_F(SectionWalk, DeviationsFromTheDesignMarkTheNarrowSectionOutOfTolerance) {
  ASSERT_EQ(map.exit_code, 0) << map.err;
  const nlohmann::json m = read_json(shared.file("map.json"));
  EXPECT_NEAR(m["design"]["width_m"].get<double>(), 0.82, 1e-9);
  EXPECT_EQ(m["tolerance_mm"].get<double>(), 10.0);
  EXPECT_EQ(m["params"]["tunnel.design_width_m"].get<double>(), 0.82);
  // Section 2 is 20 mm narrower than the design: its stations are out of tolerance; section 1
  // is 20 mm wider; section 3 is 20 mm higher.
  int out = 0;
  for (const auto& st : m["stations"]) {
    ASSERT_TRUE(st.contains("width_dev_mm"));
    if (st["width_source"] == "measured") {
      const double dev = st["width_dev_mm"].get<double>();
      EXPECT_NEAR(dev, (st["width_m"].get<double>() - 0.82) * 1000.0, 0.011);
      if (std::abs(dev) > 10.0) {
        EXPECT_TRUE(st["out_of_tolerance"].get<bool>());
      }
    }
    out += st["out_of_tolerance"].get<bool>();
  }
  EXPECT_EQ(m["summary"]["out_of_tolerance"].get<int>(), out);
  EXPECT_GT(out, 30);
  EXPECT_NE(map.out.find("out of tolerance"), std::string::npos) << map.out;
}

TEST_F(SectionWalk, CsvHasOneRowPerStationAndPlyOneSweptBoxPerSection) {
  ASSERT_EQ(map.exit_code, 0) << map.err;
  const nlohmann::json m = read_json(shared.file("map.json"));
  const std::string csv = slurp(shared.file("map.csv"));
  EXPECT_EQ(csv.rfind("station_m,width_m,height_m,width_source,height_source,frames,width_dev_mm,"
                      "height_dev_mm,out_of_tolerance\n", 0), 0u);
  EXPECT_EQ(testing::count_lines(csv), static_cast<int>(m["stations"].size()) + 1);
  const std::string ply = slurp(shared.file("map.ply"));
  EXPECT_NE(ply.find("comment sections 3\n"), std::string::npos);
  // Each section's comment carries its box's width and height, within 5 mm of the section's true
  // size (0.84 x 1.30, 0.80 x 1.28, 0.82 x 1.32 m).
  const double truth[3][2] = {{0.84, 1.30}, {0.80, 1.28}, {0.82, 1.32}};
  for (int i = 0; i < 3; ++i) {
    const std::string key = "comment section " + std::to_string(i) + " ";
    const std::size_t at = ply.find(key);
    ASSERT_NE(at, std::string::npos) << key;
    double w = 0, h = 0;
    ASSERT_EQ(std::sscanf(ply.c_str() + at + key.size(), "%lf %lf", &w, &h), 2) << key;
    EXPECT_NEAR(w, truth[i][0], 0.005) << key;
    EXPECT_NEAR(h, truth[i][1], 0.005) << key;
  }
}

TEST_F(SectionWalk, FuseMapFollowsTheSectionsToo) {
  const CliRun fuse = run_cli("fuse " + shared.file("walk") + " --params " + kLabPreset +
                              " --set fusion.voxel_mm=20 --map " + tmp.file("fused_map.ply") +
                              " --json " + tmp.file("fuse.json"));
  ASSERT_EQ(fuse.exit_code, 0) << fuse.err;
  const std::string ply = slurp(tmp.file("fused_map.ply"));
  EXPECT_NE(ply.find("comment sections 3\n"), std::string::npos);
  const nlohmann::json j = read_json(tmp.file("fuse.json"));
  const nlohmann::json m = read_json(shared.file("map.json"));
  ASSERT_EQ(j["sections"].size(), 3u);
  for (int i = 0; i < 3; ++i) {  // the same map as `map`
    EXPECT_NEAR(j["sections"][i]["width_m"].get<double>(), m["sections"][i]["width_m"].get<double>(), 1e-6);
    EXPECT_NEAR(j["sections"][i]["from_m"].get<double>(), m["sections"][i]["from_m"].get<double>(), 1e-6);
  }
}

TEST_F(SectionWalk, PosedDetectionTakesTheChangesOfSectionAndMeasuresEachPartOfAFrame) {
  const CliRun det = run_cli("detect " + shared.file("walk") + " --params " + kLabPreset +
                             " --json " + tmp.file("detect.json"));
  ASSERT_EQ(det.exit_code, 0) << det.err;
  const nlohmann::json d = read_json(tmp.file("detect.json"));
  const nlohmann::json ds = read_json(shared.file("walk/dataset.json"));
  const std::vector<TrueSection> truth = true_sections(ds);
  const nlohmann::json m = read_json(shared.file("map.json"));
  const double ox = m["frame"]["origin"][0].get<double>();
  int two_part_frames = 0;
  for (const auto& f : d["frames"]) {
    SCOPED_TRACE(f.dump().substr(0, 300));
    // A change of section is never taken for an inconsistency with the context.
    ASSERT_TRUE(f["detected"].get<bool>());
    ASSERT_TRUE(f.contains("parts"));
    // Each part the frame saw is measured separately: its width is the true width of the
    // section it lies in, within 4 mm (parts that end near a joint are left out).
    for (const auto& p : f["parts"]) {
      if (p["width_m"].is_null()) continue;
      const double a = ox + p["from_m"].get<double>(), b = ox + p["to_m"].get<double>();
      for (const TrueSection& t : truth)
        if (a >= t.from_x + 0.15 && b <= t.to_x - 0.15 && b - a > 0.3) {
          EXPECT_NEAR(p["width_m"].get<double>(), t.width, 0.004);
        }
    }
    two_part_frames += f["parts"].size() >= 2;
  }
  EXPECT_GE(two_part_frames, 10) << "frames that see a joint";
}

TEST_F(SectionWalk, AnIsolatedOutlierFrameIsStillRejected) {
  // Frame 20's depth scaled by 8 %: its walls move 30-35 mm outwards, where several frames
  // before it measured the tunnel.
  IoTempDir copy;
  std::filesystem::copy(shared.file("walk"), copy.file("walk"), std::filesystem::copy_options::recursive);
  const std::string png = copy.file("walk/depth/000020.png");
  cv::Mat depth = cv::imread(png, cv::IMREAD_UNCHANGED);
  ASSERT_EQ(depth.type(), CV_16UC1);
  depth.convertTo(depth, CV_16UC1, 1.08);
  ASSERT_TRUE(cv::imwrite(png, depth));
  const CliRun det = run_cli("detect " + copy.file("walk") + " --params " + kLabPreset +
                             " --json " + copy.file("d.json"));
  ASSERT_EQ(det.exit_code, 0) << det.err;
  const nlohmann::json d = read_json(copy.file("d.json"));
  for (const auto& f : d["frames"]) {
    if (f["index"] == 20) {
      EXPECT_FALSE(f["detected"].get<bool>());
      EXPECT_EQ(f["status"], "inconsistent_with_context");
      EXPECT_NE(f["reason"].get<std::string>().find("differs from the map at"), std::string::npos);
    } else {
      EXPECT_TRUE(f["detected"].get<bool>()) << f["index"];
    }
  }
}

TEST_F(SectionWalk, ReportPdfHoldsTheSectionsAndTheOutOfToleranceStations) {
  ASSERT_EQ(map.exit_code, 0) << map.err;
  const CliRun report = run_cli("map " + shared.file("walk") + " --params " + kLabPreset +
                                " --design 0.82x1.30 --quiet --report " + tmp.file("report.pdf"));
  if (report.exit_code == 2 && report.err.find("needs the Qt build") != std::string::npos)
    GTEST_SKIP() << "tunnelmap-cli was built without Qt: " << report.err;
  ASSERT_EQ(report.exit_code, 0) << report.err;
  const std::string txt = tmp.file("report.txt");
  ASSERT_EQ(std::system(("pdftotext -layout " + tmp.file("report.pdf") + " " + txt).c_str()), 0);
  const std::string text = slurp(txt);
  const nlohmann::json m = read_json(shared.file("map.json"));
  for (const char* heading : {"Tunnel inspection report", "Sections", "Stations out of tolerance",
                              "Width against station", "Height against station", "Map"})
    EXPECT_NE(text.find(heading), std::string::npos) << heading;
  // Every section's width and height as the JSON gives them, to the millimetre.
  char buf[32];
  for (const auto& s : m["sections"]) {
    std::snprintf(buf, sizeof buf, "%.3f", s["width_m"].get<double>());
    EXPECT_NE(text.find(buf), std::string::npos) << buf;
    std::snprintf(buf, sizeof buf, "%.3f", s["height_m"].get<double>());
    EXPECT_NE(text.find(buf), std::string::npos) << buf;
  }
  // The first out-of-tolerance station is listed with its station.
  for (const auto& st : m["stations"])
    if (st["out_of_tolerance"].get<bool>()) {
      std::snprintf(buf, sizeof buf, "%.2f", st["station_m"].get<double>());
      EXPECT_NE(text.find(buf), std::string::npos) << buf;
      break;
    }
  // A page renders to an image.
  ASSERT_EQ(std::system(("pdftoppm -r 30 -png -f 1 -l 1 " + tmp.file("report.pdf") + " " +
                         tmp.file("page")).c_str()), 0);
  EXPECT_TRUE(std::filesystem::exists(tmp.file("page-1.png")) ||
              std::filesystem::exists(tmp.file("page-01.png")));
}

// Camera under the roof, pitched 3 deg down, walking to 1.8 m from a diaphragm: about 2.3 m
// from it the plate hides the floor (at 1.8 m the floor shows again through the manhole), and
// those frames take their height from the earlier frames' map. Simulated once per build and
// shared by both tests that detect it.
testing::SharedFixture approach_walk() {
  return testing::shared_cli_fixture("StationMapApproach", {{"simulate", "simulate {dir}/appr --preset lab --frames 24"
                                                                         " --quiet --diaphragms 5 --walk 0,3.2,8"
                                                                         " --walk-pose 0,0.9,-3"}});
}

// Detects the approach walk with the lab preset and `options` into dir/d.json, expects every
// frame within 12 mm, and returns the frames whose height came from context.
int approach_within_12mm(const testing::SharedFixture& walk, const IoTempDir& dir, const std::string& options,
                         CliRun& det) {
  EXPECT_TRUE(walk.ok()) << walk.error;
  det = run_cli("detect " + walk.file("appr") + " --params " + kLabPreset + options + " --json " +
                dir.file("d.json"));
  EXPECT_EQ(det.exit_code, 0) << det.err;
  if (!walk.ok() || det.exit_code != 0) return 0;
  const nlohmann::json d = read_json(dir.file("d.json"));
  int from_context = 0;
  for (const auto& f : d["frames"]) {
    SCOPED_TRACE(f.dump());
    EXPECT_TRUE(f["detected"].get<bool>());
    if (!f["detected"].get<bool>()) continue;
    EXPECT_NEAR(f["width_m"].get<double>(), 0.82, 0.012);
    EXPECT_NEAR(f["height_m"].get<double>(), 1.30, 0.012);
    if (f["height_source"] == "context") {
      ++from_context;
      EXPECT_EQ(f["status"], "partial");
      EXPECT_EQ(f["inferred_walls"], nlohmann::json({"bottom"}));
      EXPECT_EQ(f["measured_walls"], nlohmann::json({"left", "right", "top"}));
    }
  }
  return from_context;
}

TEST(StationMapApproach, FramesApproachingAPlateKeepBothDimensionsWithin12mm) {
  // The cell order finds slivers of floor at 2.5-3.5 m: their normals come from the
  // disparity-space fit, they weigh in the template by their points, and those seen through the
  // manhole measure no zone (with least squares, the plain mean and no such rule, 11 of 24
  // frames came out 15-129 mm low).
  const testing::SharedFixture walk = approach_walk();
  IoTempDir dir;
  CliRun det;
  EXPECT_GE(approach_within_12mm(walk, dir, "", det), 3) << "the floor must leave the view near the plate";
  EXPECT_NE(det.out.find("partial: height from context"), std::string::npos) << det.out;

  // The same last frame alone (a depth PNG, no pose): partial, with the width measured.
  const CliRun one = run_cli("detect " + walk.file("appr/depth/000023.png") + " --params " +
                             kLabPreset + " --json " + dir.file("one.json"));
  ASSERT_EQ(one.exit_code, 0) << one.err;
  const nlohmann::json f = read_json(dir.file("one.json"))["frames"][0];
  if (f["status"] == "partial") {
    EXPECT_EQ(f["width_source"], "measured");
    EXPECT_NEAR(f["width_m"].get<double>(), 0.82, 0.012);
    EXPECT_TRUE(f["height_m"].is_null());
    EXPECT_TRUE(f["height_source"].is_null());
  }
}

TEST(StationMapApproach, ThePixelGridKeepsBothDimensionsWithin12mm) {
  // The same walk on the pixel grid (grow.cell_px = 0), which keeps no plane on the floor's
  // slivers at 2.5-3.5 m.
  IoTempDir dir;
  CliRun det;
  EXPECT_GE(approach_within_12mm(approach_walk(), dir, " --set grow.cell_px=0", det), 3);
}

TEST(StationMapApproach, SingleFramesAt1_8mWithoutPosesArePartialWithTheWidthMeasured) {
  IoTempDir dir;
  // Every frame 1.8 m from the plate, camera just under the roof and level.
  const CliRun sim = run_cli("simulate " + dir.file("s") +
                             " --preset lab --frames 3 --quiet --diaphragms 5"
                             " --walk 3.2,3.2,1 --walk-pose 0,0.95,0");
  ASSERT_EQ(sim.exit_code, 0) << sim.err;
  for (int i = 0; i < 3; ++i) {
    const std::string png = dir.file("s/depth/00000" + std::to_string(i) + ".png");
    const CliRun r = run_cli("detect " + png + " --params " + kLabPreset + " --json " + dir.file("f.json"));
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const nlohmann::json f = read_json(dir.file("f.json"))["frames"][0];
    SCOPED_TRACE(f.dump());
    EXPECT_EQ(f["status"], "partial");
    EXPECT_TRUE(f["detected"].get<bool>());
    EXPECT_EQ(f["width_source"], "measured");
    EXPECT_NEAR(f["width_m"].get<double>(), 0.82, 0.012);
    EXPECT_TRUE(f["height_m"].is_null());
    EXPECT_EQ(f["inferred_walls"], nlohmann::json::array());
    EXPECT_EQ(std::find(f["measured_walls"].begin(), f["measured_walls"].end(), "bottom"),
              f["measured_walls"].end());
    EXPECT_NE(r.out.find("partial: height unknown"), std::string::npos) << r.out;
    // With a design prior, the height comes from the design and the floor is inferred.
    const CliRun d = run_cli("detect " + png + " --params " + kLabPreset +
                             " --set tunnel.design_height_m=1.3 --json " + dir.file("g.json"));
    const nlohmann::json g = read_json(dir.file("g.json"))["frames"][0];
    EXPECT_EQ(g["height_source"], "design");
    EXPECT_NEAR(g["height_m"].get<double>(), 1.3, 1e-9);
    EXPECT_TRUE(g["detected"].get<bool>());
  }
}

TEST(StationMapCli, RefusesADatasetWithoutPosesAndBadDesigns) {
  IoTempDir dir;
  const CliRun design = run_cli("map " + std::string(TUNNELMAP_TEST_DATA_DIR) +
                                "/sample/lab --design 0.82 --json " + dir.file("m.json"));
  EXPECT_EQ(design.exit_code, 2);
  EXPECT_NE(design.err.find("--design expects WIDTHxHEIGHT"), std::string::npos) << design.err;
  EXPECT_FALSE(std::filesystem::exists(dir.file("m.json")));
  const CliRun png = run_cli("map " + std::string(TUNNELMAP_TEST_DATA_DIR) +
                             "/real-frames/cape_tunnel_depth.png --json " + dir.file("m.json"));
  EXPECT_EQ(png.exit_code, 3);
  EXPECT_EQ(testing::count_lines(png.err), 1) << png.err;
  EXPECT_FALSE(std::filesystem::exists(dir.file("m.json")));
  const CliRun tol = run_cli("map " + std::string(TUNNELMAP_TEST_DATA_DIR) +
                             "/sample/lab --tolerance-mm -3");
  EXPECT_EQ(tol.exit_code, 2) << tol.err;
}

}  // namespace
}  // namespace tunnelmap
