// What to rescan: the stretches of stations whose width or height no frame measured.
#include "core/mapping/rescan_stretches.h"

#include <gtest/gtest.h>

#include "core/report/station_map_json.h"

namespace tunnelmap {
namespace {

// 40 stations of 0.1 m (centres 0.05 ... 3.95 m), every size measured, one section; the
// shortest section is 3 stations (0.3 m).
StationMap measured_map() {
  StationMap m;
  m.options.station_step_m = 0.1;
  m.options.min_section_stations = 3;
  for (int k = 0; k < 40; ++k) {
    Station s;
    s.station_m = 0.05 + 0.1 * k;
    s.width_m = 0.8;
    s.height_m = 1.2;
    s.width_source = s.height_source = DimensionSource::Measured;
    m.stations.push_back(s);
  }
  m.sections.push_back({0.0, 4.0, 0.8, 1.2, 10, true, 0.0});
  return m;
}

void leave_unmeasured(StationMap& m, int first, int last, StationDimension d, DimensionSource how) {
  for (int k = first; k <= last; ++k)
    (d == StationDimension::Width ? m.stations[k].width_source : m.stations[k].height_source) = how;
}

// A joint placed between views at `at_m`: the section after it starts there.
void add_hidden_joint(StationMap& m, double at_m) {
  m.sections.back().to_m = at_m;
  m.sections.push_back({at_m, 4.0, 0.8, 1.23, 10, false, 0.5});
}

TEST(RescanStretches, AFullyMeasuredMapHasNothingToRescan) {
  EXPECT_TRUE(rescan_stretches(measured_map()).empty());
}

TEST(RescanStretches, AHeightFilledFromContextPastAPlateIsOneStretchWithItsJoint) {
  StationMap m = measured_map();
  leave_unmeasured(m, 12, 27, StationDimension::Height, DimensionSource::Context);  // 1.2-2.8 m
  add_hidden_joint(m, 2.0);
  const std::vector<RescanStretch> r = rescan_stretches(m);
  ASSERT_EQ(r.size(), 1u);
  EXPECT_NEAR(r[0].from_m, 1.2, 1e-9);
  EXPECT_NEAR(r[0].to_m, 2.8, 1e-9);
  EXPECT_EQ(r[0].dimension, StationDimension::Height);
  EXPECT_TRUE(r[0].joint_inside);
  EXPECT_EQ(r[0].reason, "no frame measured the height here; a joint lies somewhere in this stretch");
}

TEST(RescanStretches, AGapShorterThanASectionCountsOnlyWhenAJointLiesInIt) {
  StationMap m = measured_map();
  leave_unmeasured(m, 5, 6, StationDimension::Width, DimensionSource::Unseen);    // 0.5-0.7 m
  leave_unmeasured(m, 20, 21, StationDimension::Width, DimensionSource::Design);  // 2.0-2.2 m
  EXPECT_TRUE(rescan_stretches(m).empty());
  add_hidden_joint(m, 2.1);
  const std::vector<RescanStretch> r = rescan_stretches(m);
  ASSERT_EQ(r.size(), 1u);
  EXPECT_NEAR(r[0].from_m, 2.0, 1e-9);
  EXPECT_TRUE(r[0].joint_inside);
}

TEST(RescanStretches, WidthAndHeightStretchesAreApartAndInOrder) {
  StationMap m = measured_map();
  leave_unmeasured(m, 30, 35, StationDimension::Width, DimensionSource::Context);   // 3.0-3.6 m
  leave_unmeasured(m, 10, 19, StationDimension::Height, DimensionSource::Context);  // 1.0-2.0 m
  leave_unmeasured(m, 10, 13, StationDimension::Width, DimensionSource::Context);   // 1.0-1.4 m
  const std::vector<RescanStretch> r = rescan_stretches(m);
  ASSERT_EQ(r.size(), 3u);
  EXPECT_EQ(r[0].dimension, StationDimension::Width);
  EXPECT_NEAR(r[0].to_m, 1.4, 1e-9);
  EXPECT_EQ(r[1].dimension, StationDimension::Height);
  EXPECT_NEAR(r[1].to_m, 2.0, 1e-9);
  EXPECT_NEAR(r[2].from_m, 3.0, 1e-9);
  for (const RescanStretch& s : r) EXPECT_FALSE(s.joint_inside);
}

TEST(RescanStretches, TheMapDocumentListsThemAndCountsThemInItsSummary) {
  StationMap m = measured_map();
  m.ok = true;
  m.status = "ok";
  leave_unmeasured(m, 12, 27, StationDimension::Height, DimensionSource::Context);
  add_hidden_joint(m, 2.0);
  const nlohmann::json doc = station_map_document(m, nlohmann::json::object(), nlohmann::json::array(), "in");
  ASSERT_EQ(doc["rescan"].size(), 1u);
  EXPECT_EQ(doc["rescan"][0]["unmeasured"], "height");
  EXPECT_EQ(doc["rescan"][0]["joint_inside"], true);
  EXPECT_DOUBLE_EQ(doc["rescan"][0]["from_m"].get<double>(), 1.2);
  EXPECT_EQ(doc["summary"]["rescan_stretches"], 1);
}

}  // namespace
}  // namespace tunnelmap
