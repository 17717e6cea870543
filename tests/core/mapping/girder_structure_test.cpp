// The girder's structure from a simulated walk through three plates with manholes: plates
// placed along the axis, their manholes measured, the compartments between them and the centre
// line, as `map --json` and `map --diaphragms-csv` write them.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "core/mapping/girder_structure.h"
#include "core/mapping/station_map.h"
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

const std::string kFieldPreset = std::string(TUNNELMAP_TEST_DATA_DIR) + "/presets/field.json";

// Field box girder (0.84 x 1.20 m), diaphragms at x = 3 and 6 m and the preset's manhole plate at
// 5 m, each with the simulator's elliptic 0.45 x 0.70 m manhole, walked from x = 0.4 to 8.2 m along
// the centre (through the manholes). Simulated and mapped once per build and shared by every test
// here (they only read it).
class GirderWalk : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    shared = testing::shared_cli_fixture(
        "GirderWalk", {{"simulate", "simulate {dir}/walk --preset field --frames 24 --seed 7 --quiet"
                                    " --diaphragms 3,6 --walk 0.4,8.2,12 --walk-pose 0,0.5,0"},
                       {"map", "map {dir}/walk --params " + kFieldPreset +
                                   " --json {dir}/map.json --diaphragms-csv {dir}/plates.csv --ply {dir}/map.ply"}});
    ASSERT_TRUE(shared.ok()) << shared.error;
    map = testing::kept_cli_run(shared, "map");
    ASSERT_EQ(map.exit_code, 0) << map.err;
    doc = nlohmann::json::parse(slurp(shared.file("map.json")));
    dataset = nlohmann::json::parse(slurp(shared.file("walk/dataset.json")));
  }
  // World x of map station s (the walk runs along +X).
  static double world_x(double s) {
    return doc["frame"]["origin"][0].get<double>() + s * doc["frame"]["axis"][0].get<double>();
  }
  static testing::SharedFixture shared;
  static CliRun map;
  static nlohmann::json doc, dataset;
};
testing::SharedFixture GirderWalk::shared;
CliRun GirderWalk::map;
nlohmann::json GirderWalk::doc, GirderWalk::dataset;

TEST_F(GirderWalk, EveryPlateIsFoundWithin20mmAndNoneIsInvented) {
  const nlohmann::json& plates = doc["diaphragms"];
  const nlohmann::json& truth = dataset["ground_truth"]["girder"]["diaphragms"];
  ASSERT_EQ(truth.size(), 3u);  // the field preset's manhole plate at 5 m besides the two diaphragms
  ASSERT_EQ(plates.size(), truth.size()) << plates.dump(1);
  for (std::size_t k = 0; k < truth.size(); ++k) {
    EXPECT_NEAR(world_x(plates[k]["station_m"].get<double>()), truth[k]["station_m"].get<double>(), 0.02) << k;
    EXPECT_NEAR(plates[k]["point"][0].get<double>(), truth[k]["point"][0].get<double>(), 0.02) << k;
    EXPECT_GT(std::abs(plates[k]["normal"][0].get<double>()), 0.99);
    EXPECT_GE(plates[k]["seen_by_frames"].get<int>(), 2);
    EXPECT_EQ(plates[k]["kind"], "diaphragm");  // each has its opening; no end wall was seen
  }
}

TEST_F(GirderWalk, ManholesAreMeasuredWithin15mm) {
  const nlohmann::json& plates = doc["diaphragms"];
  const nlohmann::json& truth = dataset["ground_truth"]["girder"]["diaphragms"];
  ASSERT_EQ(plates.size(), truth.size());
  for (std::size_t k = 0; k < truth.size(); ++k) {
    const nlohmann::json& m = plates[k]["manhole"];
    const nlohmann::json& t = truth[k]["manhole"];
    ASSERT_FALSE(m.is_null()) << plates[k].dump(1);
    EXPECT_EQ(m["shape"], t["shape"]);
    EXPECT_NEAR(m["width_m"].get<double>(), t["width_m"].get<double>(), 0.015);
    EXPECT_NEAR(m["height_m"].get<double>(), t["height_m"].get<double>(), 0.015);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(m["center"][c].get<double>(), t["center"][c].get<double>(), 0.015);
    // Side clearances: (0.84 - 0.45) / 2 from the opening to each wall.
    EXPECT_NEAR(m["clearance_m"]["left"].get<double>(), 0.195, 0.015);
    EXPECT_NEAR(m["clearance_m"]["right"].get<double>(), 0.195, 0.015);
  }
}

TEST_F(GirderWalk, CompartmentsLieBetweenThePlatesWithTheGirdersCrossSection) {
  const nlohmann::json& c = doc["compartments"];
  ASSERT_EQ(c.size(), 4u);  // before, between the three plates, after
  int closed_and_measured = 0;
  for (std::size_t k = 0; k < c.size(); ++k) {
    EXPECT_EQ(c[k]["closed"][0].get<bool>(), k > 0);
    EXPECT_EQ(c[k]["closed"][1].get<bool>(), k + 1 < c.size());
    if (k > 0) {
      EXPECT_DOUBLE_EQ(c[k]["from_m"].get<double>(), doc["diaphragms"][k - 1]["station_m"].get<double>());
    }
    // A dimension no station measured in it stays unknown: null, never a number from elsewhere.
    if (!c[k]["width_m"].is_null()) { EXPECT_NEAR(c[k]["width_m"].get<double>(), 0.84, 0.008); }
    if (!c[k]["height_m"].is_null()) { EXPECT_NEAR(c[k]["height_m"].get<double>(), 1.20, 0.008); }
    if (k > 0 && k + 1 < c.size() && !c[k]["width_m"].is_null() && !c[k]["height_m"].is_null())
      ++closed_and_measured;
  }
  EXPECT_GE(closed_and_measured, 1);
}

TEST_F(GirderWalk, TheCentrelineRunsThroughTheCrossSectionsCentre) {
  const nlohmann::json& line = doc["centreline"];
  ASSERT_EQ(line.size(), doc["stations"].size());
  int measured = 0;
  for (const auto& p : line) {
    if (p["source"] != "measured") continue;
    ++measured;
    EXPECT_NEAR(p["point"][1].get<double>(), 0.0, 0.01);   // y: the girder is centred on y = 0
    EXPECT_NEAR(p["point"][2].get<double>(), 0.60, 0.01);  // z: half the height above the floor
  }
  EXPECT_GT(measured, static_cast<int>(line.size()) / 2);
}

TEST_F(GirderWalk, TheDiaphragmCsvHasARowPerPlate) {
  const std::string csv = slurp(shared.file("plates.csv"));
  EXPECT_EQ(std::count(csv.begin(), csv.end(), '\n'), 4);  // header + 3 plates
  EXPECT_NE(csv.find("ellipse"), std::string::npos);
  EXPECT_EQ(csv.find(",manhole_reason,kind\n"), csv.find('\n') - 20);  // the header's last columns
  std::size_t rows_ending_in_kind = 0;
  for (std::size_t at = csv.find(",diaphragm\n"); at != std::string::npos; at = csv.find(",diaphragm\n", at + 1))
    ++rows_ending_in_kind;
  EXPECT_EQ(rows_ending_in_kind, 3u);
}

TEST_F(GirderWalk, APoseMetresOffIsToldAsUncheckedNotMappedSilently) {
  // The walk with stop 3 (frames 6 and 7) reported 10 m farther along the girder than it stood:
  // what it saw lands where no other frame looked, so nothing can tie it to the map.
  IoTempDir copy;
  std::filesystem::copy(shared.file("walk"), copy.file("walk"), std::filesystem::copy_options::recursive);
  nlohmann::json d = dataset;
  int moved = 0;
  for (nlohmann::json& f : d["frames"])
    if (f["pose_group"] == 3) f["pose"][3] = f["pose"][3].get<double>() + 10.0, ++moved;
  ASSERT_EQ(moved, 2);
  std::ofstream(copy.file("walk/dataset.json")) << d.dump();
  const CliRun run = run_cli("map " + copy.file("walk") + " --params " + kFieldPreset + " --json " + copy.file("m.json"));
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_NE(run.out.find("pose 3 (frames 6-7): nothing it saw was seen from another pose, so nothing checks it"),
            std::string::npos) << run.out;
  EXPECT_EQ(run.out.find("nothing it saw"), run.out.find("nothing it saw", run.out.find("pose 3 (frames 6-7)")))
      << "only the moved stop: " << run.out;
  EXPECT_EQ(run.out.find("nothing it saw", run.out.find("pose 3 (frames 6-7)") + 30), std::string::npos) << run.out;
  const nlohmann::json m = nlohmann::json::parse(slurp(copy.file("m.json")));
  for (const nlohmann::json& p : m["poses"])
    EXPECT_EQ(p["refinement"]["constrained"].empty(), p["group"] == 3) << p.dump();
  // The plate it saw lands 10 m past the girder's plates: told, not mapped as a fourth plate.
  EXPECT_EQ(m["diaphragms"].size(), doc["diaphragms"].size()) << m["diaphragms"].dump(1);
  const std::string note = m["notes"].empty() ? "" : m["notes"][0].get<std::string>();
  const auto at = note.find("but for the plate it saw at station ");
  ASSERT_NE(at, std::string::npos) << note;
  const double phantom = std::atof(note.c_str() + at + 36);
  EXPECT_GT(phantom, doc["diaphragms"].back()["station_m"].get<double>() + 5.0) << note;
  EXPECT_NE(note.find("which is not mapped"), std::string::npos) << note;
  // The walk as simulated has no such pose.
  EXPECT_EQ(map.out.find("nothing it saw"), std::string::npos) << map.out;
}

TEST_F(GirderWalk, ThePlyMapHoldsEachPlateWithItsOpening) {
  const std::string ply = slurp(shared.file("map.ply"));
  const std::string head = ply.substr(0, ply.find("end_header"));
  EXPECT_NE(head.find("comment plates 3\n"), std::string::npos) << head;
}


// A straight map, stations every 0.1 m over 8 m: a 0.90 x 1.20 m section up to station 6, then
// 0.80 x 1.10 m (a 50 mm step on every wall). `widen_m`: both sections that much wider and higher.
StationMap two_section_map(double widen_m = 0.0) {
  StationMap m;
  m.ok = true;
  m.line = Centreline::straight(m.origin, m.axis, m.up);
  for (int k = 0; k < 80; ++k) {
    Station st;
    st.station_m = 0.05 + 0.1 * k;
    const double half_w = (st.station_m < 6.0 ? 0.45 : 0.40) + widen_m / 2;
    const double half_h = (st.station_m < 6.0 ? 0.60 : 0.55) + widen_m / 2;
    st.width_m = 2 * half_w, st.height_m = 2 * half_h;
    st.width_source = st.height_source = DimensionSource::Measured;
    st.frames = 3;
    st.wall_m[0] = st.wall_m[1] = half_w;
    st.wall_m[2] = st.wall_m[3] = half_h;
    m.stations.push_back(st);
  }
  m.sections = {{0.0, 6.0, 0.90 + widen_m, 1.20 + widen_m}, {6.0, 8.0, 0.80 + widen_m, 1.10 + widen_m}};
  return m;
}

// One frame's view of a face across the girder at `station`: samples every 2.5 cm where `keep`.
template <typename Keep>
PlateView face_view(int frame, double station, Keep keep) {
  PlateView v;
  v.frame = frame;
  for (double y = -0.45; y <= 0.45; y += 0.025)
    for (double z = -0.60; z <= 0.60; z += 0.025)
      if (keep(y, z)) v.samples.push_back({station, y, z}), v.weights.push_back(64);
  return v;
}

TEST(GirderPlates, APlateSeenOnlyThroughTheOpeningBeforeItIsStillAPlate) {
  // A diaphragm at 3 m with a 0.5 x 0.7 m elliptic manhole, and a second plate 0.5 m behind it
  // that the frames saw only through that opening: 0.45 x 0.40 m of it, 0.18 m2 (15 % of the
  // section). A ring where the section steps at 6 m covers 0.19 m2 between the two sections'
  // walls. The first two are plates, the ring is not.
  const StationMap map = two_section_map();
  const auto in_manhole = [](double y, double z) { return std::pow(y / 0.25, 2) + std::pow(z / 0.35, 2) < 1.0; };
  std::vector<PlateView> views;
  for (int f = 0; f < 2; ++f) {
    views.push_back(face_view(f, 3.0, [&](double y, double z) { return !in_manhole(y, z); }));
    views.push_back(face_view(f, 3.5, [](double y, double z) { return std::abs(y) < 0.22 && z > -0.35 && z < 0.05; }));
    views.push_back(face_view(f, 6.0, [](double y, double z) { return std::abs(y) > 0.40 || std::abs(z) > 0.55; }));
  }
  const GirderStructure g = build_girder_structure(map, views);
  ASSERT_EQ(g.diaphragms.size(), 2u);
  EXPECT_NEAR(g.diaphragms[0].station_m, 3.0, 1e-9);
  EXPECT_NEAR(g.diaphragms[1].station_m, 3.5, 1e-9);
  EXPECT_LT(g.diaphragms[1].area_m2, 0.3 * 0.90 * 1.20);  // too little of the section by itself
}

TEST(GirderPlates, PlatesAFewCentimetresApartThatOneFrameSawAreTwo) {
  // A diaphragm at 3 m and a plate 11 cm behind it (within the 12 cm that chains views of one
  // plate): frame 0 saw both, the second through the first's opening; frames 1 and 2 saw the
  // first, frame 3 the second (from inside the opening). One frame's two faces have no pose
  // error between them.
  const StationMap map = two_section_map();
  const auto in_manhole = [](double y, double z) { return std::pow(y / 0.25, 2) + std::pow(z / 0.35, 2) < 1.0; };
  const auto plate = [&](double y, double z) { return !in_manhole(y, z); };
  std::vector<PlateView> views{face_view(0, 3.0, plate), face_view(0, 3.11, in_manhole), face_view(1, 3.0, plate),
                               face_view(2, 3.0, plate), face_view(3, 3.11, plate)};
  const GirderStructure g = build_girder_structure(map, views);
  ASSERT_EQ(g.diaphragms.size(), 2u);
  EXPECT_NEAR(g.diaphragms[0].station_m, 3.0, 1e-9);
  EXPECT_EQ(g.diaphragms[0].seen_by_frames, 3);
  EXPECT_NEAR(g.diaphragms[1].station_m, 3.11, 1e-9);
  EXPECT_EQ(g.diaphragms[1].seen_by_frames, 2);

  // Without frame 0 nothing tells them apart from one plate seen with 11 cm of pose error.
  views.erase(views.begin(), views.begin() + 2);
  EXPECT_EQ(build_girder_structure(map, views).diaphragms.size(), 1u);
}

TEST(GirderPlates, PlatesTwentyCentimetresApartAreTwoWhoeverSawThem) {
  // The field preset's manhole plate 19 cm behind a diaphragm: the frames before the diaphragm
  // saw the diaphragm, those in its opening the plate behind it, from 0.5 m, where the view
  // spans about 0.6 x 0.45 m: 0.14 m2 of plate around the opening.
  const StationMap map = two_section_map();
  const auto plate = [](double y, double z) { return std::pow(y / 0.25, 2) + std::pow(z / 0.35, 2) >= 1.0; };
  const auto near_view = [&](double y, double z) { return plate(y, z) && std::abs(y) < 0.35 && std::abs(z) < 0.25; };
  std::vector<PlateView> views{face_view(0, 4.81, plate), face_view(1, 4.81, plate), face_view(2, 5.0, near_view),
                               face_view(3, 5.0, near_view)};
  const GirderStructure g = build_girder_structure(map, views);
  ASSERT_EQ(g.diaphragms.size(), 2u);
  EXPECT_NEAR(g.diaphragms[0].station_m, 4.81, 1e-9);
  EXPECT_NEAR(g.diaphragms[1].station_m, 5.0, 1e-9);
}

TEST(GirderPlates, AViewLiesAcrossTheAxisWithinItsAngle) {
  const auto everywhere = [](double, double) { return true; };
  EXPECT_TRUE(view_lies_across_axis(face_view(0, 3.0, everywhere), 20.0));
  // The same face turned 30 degrees about the vertical (its station grows with lateral).
  PlateView turned = face_view(0, 3.0, everywhere);
  for (Eigen::Vector3d& p : turned.samples) p.x() += std::tan(30.0 * M_PI / 180.0) * p.y();
  EXPECT_FALSE(view_lies_across_axis(turned, 20.0));
  EXPECT_TRUE(view_lies_across_axis(turned, 35.0));
  // A strip of wall along the girder.
  PlateView wall;
  for (double s = 2.0; s <= 3.0; s += 0.025)
    for (double z = -0.5; z <= 0.5; z += 0.025) wall.samples.push_back({s, 0.45, z}), wall.weights.push_back(64);
  EXPECT_FALSE(view_lies_across_axis(wall, 20.0));
  EXPECT_FALSE(view_lies_across_axis(PlateView{}, 20.0));
}

TEST(GirderPlates, AFaceInsideTheSectionMustStillBeAsLargeAsAPlate) {
  // A 0.25 x 0.25 m face in the middle of the passage (a bracket, a stiffener's end): 0.06 m2.
  const StationMap map = two_section_map();
  std::vector<PlateView> views{face_view(0, 2.0, [](double y, double z) { return std::abs(y) < 0.125 && std::abs(z) < 0.125; })};
  EXPECT_TRUE(build_girder_structure(map, views).diaphragms.empty());
}

// One frame's view of a diaphragm at `station` with a 0.50 x 0.70 m elliptic manhole, all of it
// moved by (dy, dz) in the plate's plane: its pose's error, the same for every point it saw.
// `upper_only`: the frame saw only the rim's upper half (from near the plate, looking up).
PlateView shifted_manhole_view(int frame, double station, double dy, double dz, bool upper_only = false) {
  const auto in_manhole = [](double y, double z) { return std::pow(y / 0.25, 2) + std::pow(z / 0.35, 2) < 1.0; };
  PlateView v = face_view(frame, station, [&](double y, double z) { return !in_manhole(y, z); });
  for (Eigen::Vector3d& p : v.samples) p += Eigen::Vector3d(0.0, dy, dz);
  for (int k = 0; k < 160; ++k) {
    const double a = 2 * M_PI * k / 160;
    if (upper_only && std::sin(a) < 0.2) continue;
    v.rim.push_back({station, 0.25 * std::cos(a) + dy, 0.35 * std::sin(a) + dz});
  }
  return v;
}

TEST(GirderPlates, AManholesSizeDoesNotGrowWithThePosesDisagreement) {
  // Three frames saw the whole rim, each moved by its pose's error (up to 6 mm). Two more, near
  // the plate, saw only the rim's top, 20 and 25 mm too high (a pitch 0.3-0.4 degrees off, seen
  // from 3.5 m). Each view moved onto the outline they agree on, it is the opening; pooled, the
  // top of the rim rises with the two near views.
  const StationMap map = two_section_map();
  std::vector<PlateView> views{shifted_manhole_view(0, 3.0, 0.0, 0.0), shifted_manhole_view(1, 3.0, 0.004, -0.006),
                               shifted_manhole_view(2, 3.0, -0.003, 0.005),
                               shifted_manhole_view(3, 3.0, 0.0, 0.020, true),
                               shifted_manhole_view(4, 3.0, 0.0, 0.025, true)};
  const GirderStructure g = build_girder_structure(map, views);
  ASSERT_EQ(g.diaphragms.size(), 1u);
  ASSERT_TRUE(g.diaphragms[0].manhole);
  EXPECT_NEAR(g.diaphragms[0].manhole->width_m, 0.50, 0.001);
  EXPECT_NEAR(g.diaphragms[0].manhole->height_m, 0.70, 0.001);

  // Pooled as they are, the rim's top is too high.
  GirderStructureOptions pooled;
  pooled.view_shift_sigma_m = 0.0;
  const GirderStructure p = build_girder_structure(map, views, pooled);
  ASSERT_TRUE(p.diaphragms.at(0).manhole);
  EXPECT_GT(p.diaphragms[0].manhole->height_m, 0.70 + 0.004);
}

// Rim points scattered over a plate, as depth spikes behind its surface give them: `count` points
// on a spiral from the middle out to (`half_y`, `half_z`), around (`y0`, `z0`).
std::vector<Eigen::Vector3d> spike_rims(double station, int count, double y0, double z0, double half_y, double half_z) {
  std::vector<Eigen::Vector3d> out;
  for (int k = 0; k < count; ++k) {
    const double a = 2.4 * k, r = std::sqrt((k + 0.5) / count);
    out.push_back({station, y0 + half_y * r * std::cos(a), z0 + half_z * r * std::sin(a)});
  }
  return out;
}

TEST(GirderPlates, AClosedPlateAtTheEndOfTheMapIsTheGirdersEndWall) {
  // A diaphragm with its manhole at 3 m, a plate seen closed at 5 m (stations measured beyond
  // it) and another at 7.88 m, beyond which only the last station's centre lies (its corner's
  // samples). Both closed plates carry spikes' rim points all over them.
  const StationMap map = two_section_map();
  const auto all = [](double, double) { return true; };
  std::vector<PlateView> views;
  for (int f = 0; f < 3; ++f) {
    views.push_back(shifted_manhole_view(f, 3.0, 0.0, 0.0));
    views.push_back(face_view(f, 5.0, all));
    views.push_back(face_view(f, 7.88, all));
    for (PlateView* v : {&views[views.size() - 2], &views.back()})
      v->rim = spike_rims(v->samples.front().x(), 30, 0.0, 0.0, 0.35, 0.5);
  }
  const GirderStructure g = build_girder_structure(map, views);
  ASSERT_EQ(g.diaphragms.size(), 3u);
  EXPECT_EQ(g.diaphragms[0].kind, "diaphragm");
  EXPECT_TRUE(g.diaphragms[0].manhole);
  EXPECT_FALSE(g.diaphragms[0].closed);
  for (int k : {1, 2}) {
    const Diaphragm& d = g.diaphragms[static_cast<std::size_t>(k)];
    EXPECT_TRUE(d.closed) << k;
    EXPECT_FALSE(d.manhole) << k;
    EXPECT_EQ(d.manhole_reason, "no opening: the plate was seen closed across the section") << k;
  }
  EXPECT_EQ(g.diaphragms[1].kind, "diaphragm");  // the map goes on beyond it
  EXPECT_EQ(g.diaphragms[2].kind, "end_wall");
  // No compartment past the end wall, although the last station (7.95 m) lies 7 cm beyond it.
  ASSERT_FALSE(g.compartments.empty());
  EXPECT_NEAR(g.compartments.back().to_m, 7.88, 1e-9);
  EXPECT_TRUE(g.compartments.back().closed_to);

  // The same plate at 7 m, with the girder measured beyond it, is a diaphragm without an opening.
  for (PlateView& v : views)
    if (v.samples.front().x() > 7) {
      for (Eigen::Vector3d& p : v.samples) p.x() = 7.0;
      for (Eigen::Vector3d& p : v.rim) p.x() = 7.0;
    }
  const GirderStructure inside = build_girder_structure(map, views);
  ASSERT_EQ(inside.diaphragms.size(), 3u);
  EXPECT_EQ(inside.diaphragms[2].kind, "diaphragm");
  EXPECT_TRUE(inside.diaphragms[2].closed);
}

TEST(GirderPlates, APlatesAreaIsWhatItCoversNotTheCellsItsEdgesCut) {
  // The 0.90 x 1.20 m section's plate at 3 m with a 0.5 x 0.7 m elliptic manhole and a closed
  // plate at 5 m (0.805 and 1.080 m2), sampled every centimetre, their edges wherever they fall
  // on the 5 cm grid (the grid is the map's, the walls stand where they are). Over the offsets
  // the area is right; counted whole, the cells the edges cut came to about 0.89 and 1.19 m2.
  const StationMap map = two_section_map();
  const auto in_manhole = [](double y, double z) { return std::pow(y / 0.25, 2) + std::pow(z / 0.35, 2) < 1.0; };
  const auto dense_view = [](int frame, double station, double offset, auto keep) {
    PlateView v;
    v.frame = frame;
    for (double y = -0.445; y < 0.45; y += 0.01)
      for (double z = -0.595; z < 0.60; z += 0.01)
        if (keep(y, z)) v.samples.push_back({station, y + offset, z + 0.8 * offset}), v.weights.push_back(64);
    return v;
  };
  // The samples reach half their spacing short of each edge: 0.89 x 1.19 m less 0.51 x 0.71 m.
  const double spacing = 0.01, closed = (0.90 - spacing) * (1.20 - spacing);
  const double truth[2] = {closed - M_PI * 0.25 * (0.50 + spacing) * (0.70 + spacing), closed};
  double sum[2] = {0, 0};
  constexpr int kOffsets = 10;
  for (int k = 0; k < kOffsets; ++k) {
    const double offset = 0.005 * k;  // a whole cell in ten steps
    std::vector<PlateView> views;
    for (int f = 0; f < 2; ++f) {
      views.push_back(dense_view(f, 3.0, offset, [&](double y, double z) { return !in_manhole(y, z); }));
      views.push_back(dense_view(f, 5.0, offset, [](double, double) { return true; }));
    }
    const GirderStructure g = build_girder_structure(map, views);
    ASSERT_EQ(g.diaphragms.size(), 2u) << offset;
    for (int p = 0; p < 2; ++p) {
      // Half a cell along the whole edge at worst (edges on the cell lines): 0.105 m2.
      EXPECT_NEAR(g.diaphragms[p].area_m2, truth[p], 0.11) << p << " at offset " << offset;
      sum[p] += g.diaphragms[p].area_m2;
    }
  }
  for (int p = 0; p < 2; ++p) EXPECT_NEAR(sum[p] / kOffsets, truth[p], 0.01) << p;
}

TEST(GirderPlates, APlateOnlyPosesNothingChecksSawIsToldNotMapped) {
  // Closed plates at 3 and 5 m: frames 0-1 (checked) saw both, frame 2 (a pose nothing checks)
  // saw the one at 5 m and one at 7 m that no one else saw.
  const StationMap map = two_section_map();
  const auto all = [](double, double) { return true; };
  std::vector<PlateView> views{face_view(0, 3.0, all), face_view(1, 3.0, all), face_view(0, 5.0, all),
                               face_view(1, 5.0, all), face_view(2, 5.0, all), face_view(2, 7.0, all)};
  for (PlateView& v : views) v.checked = v.frame != 2;
  const GirderStructure g = build_girder_structure(map, views);
  ASSERT_EQ(g.diaphragms.size(), 2u);
  EXPECT_NEAR(g.diaphragms[1].station_m, 5.0, 1e-9);
  EXPECT_EQ(g.diaphragms[1].seen_by_frames, 3);  // the unchecked view of a checked plate counts
  ASSERT_EQ(g.unchecked_plates.size(), 1u);
  EXPECT_NEAR(g.unchecked_plates[0].station_m, 7.0, 1e-9);
  EXPECT_EQ(g.unchecked_plates[0].frames, std::vector<int>{2});
  EXPECT_EQ(transverse_plate_stations(views), (std::vector<double>{3.0, 5.0}));
}

TEST(GirderPlates, APlateOnlyViewsAtTheEdgeOfTheRangeSawIsToldNotMapped) {
  // Closed plates at 3 and 5 m seen from near by frames 0-1. Frame 2 saw the one at 5 m, and
  // one at 7 m, only near the end of its range, each placed 3 cm too near; frame 3 so saw a
  // face at 9 m too small to be a plate.
  const StationMap map = two_section_map();
  const auto all = [](double, double) { return true; };
  const auto small = [](double y, double z) { return std::abs(y) < 0.1 && std::abs(z) < 0.1; };
  const std::vector<PlateView> near{face_view(0, 3.0, all), face_view(1, 3.0, all), face_view(0, 5.0, all),
                                    face_view(1, 5.0, all)};
  const std::vector<PlateView> cut{face_view(2, 4.97, all), face_view(2, 6.97, all), face_view(3, 8.97, small)};
  const GirderStructure g = build_girder_structure(map, near, {}, cut);
  ASSERT_EQ(g.diaphragms.size(), 2u);
  EXPECT_NEAR(g.diaphragms[1].station_m, 5.0, 1e-9);  // the far view does not move it
  EXPECT_EQ(g.diaphragms[1].seen_by_frames, 2);
  ASSERT_EQ(g.plates_beyond_range.size(), 1u);
  EXPECT_NEAR(g.plates_beyond_range[0].station_m, 6.97, 1e-9);
  EXPECT_EQ(g.plates_beyond_range[0].frames, std::vector<int>{2});
  EXPECT_TRUE(g.unchecked_plates.empty());
  EXPECT_EQ(transverse_plate_stations(near), (std::vector<double>{3.0, 5.0}));
}

TEST(GirderPlates, ASmallManholeIsNotClosedByTheCellsTheSectionsEdgeCuts) {
  // Walls 2.6 cm into a 5 cm cell (a 0.952 x 1.252 m section), the plate seen to 2 cm past them,
  // and a 0.30 x 0.40 m manhole (0.094 m2). Every cell the box's edge cuts holds plate samples;
  // counted whole, they would cover more than the opening leaves uncovered.
  const StationMap map = two_section_map(0.052);
  const auto in_manhole = [](double y, double z) { return std::pow(y / 0.15, 2) + std::pow(z / 0.20, 2) < 1.0; };
  std::vector<PlateView> views;
  for (int f = 0; f < 3; ++f) {
    PlateView v;
    v.frame = f;
    for (double y = -0.496; y <= 0.496; y += 0.02)
      for (double z = -0.646; z <= 0.646; z += 0.02)
        if (!in_manhole(y, z)) v.samples.push_back({3.0, y, z}), v.weights.push_back(64);
    for (int k = 0; k < 120; ++k) {
      const double a = 2 * M_PI * k / 120;
      v.rim.push_back({3.0, 0.15 * std::cos(a), 0.20 * std::sin(a)});
    }
    views.push_back(v);
  }
  const GirderStructure g = build_girder_structure(map, views);
  ASSERT_EQ(g.diaphragms.size(), 1u);
  EXPECT_FALSE(g.diaphragms[0].closed);
  ASSERT_TRUE(g.diaphragms[0].manhole) << g.diaphragms[0].manhole_reason;
  EXPECT_NEAR(g.diaphragms[0].manhole->width_m, 0.30, 0.005);
  EXPECT_NEAR(g.diaphragms[0].manhole->height_m, 0.40, 0.005);

  // Without its rim (an opening no frame saw the edge of) the plate is still not closed.
  for (PlateView& v : views) v.rim.clear();
  const GirderStructure unseen = build_girder_structure(map, views);
  ASSERT_EQ(unseen.diaphragms.size(), 1u);
  EXPECT_FALSE(unseen.diaphragms[0].closed);
  EXPECT_EQ(unseen.diaphragms[0].manhole_reason, "no opening seen in the plate");
}

TEST(GirderPlates, RimPointsWhereThePlateWasSeenAreNoOpening) {
  // A plate at 3 m seen only in its upper half (not closed, as far as the frames tell), with 60
  // spikes' rim points scattered over what they saw. The fit of those points lies on plate.
  const StationMap map = two_section_map();
  std::vector<PlateView> views;
  for (int f = 0; f < 2; ++f) {
    views.push_back(face_view(f, 3.0, [](double, double z) { return z > 0.0; }));
    views.back().rim = spike_rims(3.0, 30, 0.0, 0.3, 0.4, 0.25);
  }
  const GirderStructure g = build_girder_structure(map, views);
  ASSERT_EQ(g.diaphragms.size(), 1u);
  EXPECT_FALSE(g.diaphragms[0].closed);
  EXPECT_FALSE(g.diaphragms[0].manhole);
  EXPECT_EQ(g.diaphragms[0].manhole_reason.rfind("no opening seen: the plate was seen where its 60 rim points lie", 0), 0u)
      << g.diaphragms[0].manhole_reason;
  EXPECT_EQ(g.diaphragms[0].kind, "diaphragm");

  // A real opening there, seen from the same frames: measured.
  const auto in_manhole = [](double y, double z) { return std::pow(y / 0.25, 2) + std::pow((z - 0.3) / 0.2, 2) < 1.0; };
  for (PlateView& v : views) {
    v = face_view(v.frame, 3.0, [&](double y, double z) { return z > 0.0 && !in_manhole(y, z); });
    for (int k = 0; k < 120; ++k) {
      const double a = 2 * M_PI * k / 120;
      v.rim.push_back({3.0, 0.25 * std::cos(a), 0.3 + 0.2 * std::sin(a)});
    }
  }
  const GirderStructure real = build_girder_structure(map, views);
  ASSERT_EQ(real.diaphragms.size(), 1u);
  ASSERT_TRUE(real.diaphragms[0].manhole) << real.diaphragms[0].manhole_reason;
  EXPECT_NEAR(real.diaphragms[0].manhole->width_m, 0.50, 0.005);
}

}  // namespace
}  // namespace tunnelmap
