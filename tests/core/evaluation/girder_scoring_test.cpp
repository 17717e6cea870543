// Scoring one mapped girder against its truth: the poses' remaining error, after one rigid
// alignment, split along the girder's centre line, across it and vertically.
#include "core/evaluation/girder_scoring.h"

#include <gtest/gtest.h>

#include <cmath>
#include <nlohmann/json.hpp>
#include <vector>

namespace tunnelmap {
namespace {

nlohmann::json pose_json(const Eigen::Isometry3d& T) {
  nlohmann::json a = nlohmann::json::array();
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c) a.push_back(T.matrix()(r, c));
  return a;
}

// A girder along a quarter of a 20 m circle in the horizontal plane, its centre line sampled
// every 0.1 m, without plates or compartments (only the poses are scored here).
struct CurvedTruth {
  static constexpr double kRadiusM = 20.0;
  nlohmann::json truth;
  Eigen::Vector3d point_at(double s) const {
    return {kRadiusM * std::sin(s / kRadiusM), kRadiusM * (1.0 - std::cos(s / kRadiusM)), 0.7};
  }
  Eigen::Vector3d along_at(double s) const { return {std::cos(s / kRadiusM), std::sin(s / kRadiusM), 0.0}; }
  CurvedTruth() {
    nlohmann::json line = nlohmann::json::array();
    for (int k = 0; k <= 320; ++k) {
      const Eigen::Vector3d p = point_at(0.1 * k);
      line.push_back({{"station_m", 0.1 * k}, {"point", {p.x(), p.y(), p.z()}}});
    }
    truth = {{"girder", {{"centreline", line}, {"compartments", nlohmann::json::array()},
                         {"diaphragms", nlohmann::json::array()}}}};
  }
};

TEST(GirderScoring, ThePoseErrorIsSplitAlongAcrossAndVerticallyInTheGirdersFrame) {
  // Cameras on the centre line looking along it. The first half of the walk is mapped 6 mm
  // ahead, 4 mm to the left and 2 mm high of the truth, the second half as far behind, right
  // and low, less the errors' mean: the rigid alignment (the orientations are exact, so a
  // translation) then has nothing to remove, and the split must follow the curve.
  const CurvedTruth t;
  const int n = 30;
  std::vector<Eigen::Isometry3d> truths;
  std::vector<Eigen::Vector3d> errors;
  Eigen::Vector3d mean = Eigen::Vector3d::Zero();
  for (int i = 0; i < n; ++i) {
    const double s = 1.0 + i;
    const Eigen::Vector3d along = t.along_at(s), up = Eigen::Vector3d::UnitZ(), left = up.cross(along);
    Eigen::Isometry3d truth = Eigen::Isometry3d::Identity();
    truth.linear().col(2) = along, truth.linear().col(1) = -up, truth.linear().col(0) = -left;
    truth.translation() = t.point_at(s);
    truths.push_back(truth);
    const double sign = i < n / 2 ? 1.0 : -1.0;
    errors.push_back(sign * (0.006 * along + 0.004 * left + 0.002 * up));
    mean += errors.back() / n;
  }
  nlohmann::json frames = nlohmann::json::array();
  DatasetMapping mapped;
  for (int i = 0; i < n; ++i) {
    frames.push_back({{"pose_true", pose_json(truths[static_cast<std::size_t>(i)])}});
    Eigen::Isometry3d estimate = truths[static_cast<std::size_t>(i)];
    estimate.translation() += errors[static_cast<std::size_t>(i)] - mean;
    mapped.mapped.poses.push_back(estimate);
  }
  const GirderScore g = score_girder(mapped, t.truth, frames);
  ASSERT_EQ(g.pose_error_along_mm.size(), static_cast<std::size_t>(n));
  for (int i = 0; i < n; ++i) {
    const double s = 1.0 + i;
    const Eigen::Vector3d along = t.along_at(s), up = Eigen::Vector3d::UnitZ(), left = up.cross(along);
    const Eigen::Vector3d e = 1000.0 * (errors[static_cast<std::size_t>(i)] - mean);
    EXPECT_NEAR(g.pose_error_along_mm[i], e.dot(along), 0.01) << i;
    EXPECT_NEAR(g.pose_error_across_mm[i], e.dot(left), 0.01) << i;  // positive to the left
    EXPECT_NEAR(g.pose_error_vertical_mm[i], e.dot(up), 0.01) << i;
    EXPECT_NEAR(g.pose_error_mm[i], e.norm(), 0.01) << i;
  }
  // The mean removed is small against the split itself: the split is not all mean.
  EXPECT_NEAR(g.pose_error_along_mm.front(), 6.0, 2.5);
  EXPECT_NEAR(g.pose_error_vertical_mm.front(), 2.0, 0.01);
}


// A straight 10 m girder along world x with one diaphragm at 4 m; the map's stations run
// from 1 to 8 m, and it found the diaphragm and (seen from afar) the end wall at 10 m.
struct StraightGirder {
  nlohmann::json truth;
  DatasetMapping mapped;
  StraightGirder() {
    nlohmann::json line = nlohmann::json::array();
    for (int k = 0; k <= 100; ++k) line.push_back({{"station_m", 0.1 * k}, {"point", {0.1 * k, 0.0, 0.6}}});
    nlohmann::json plate = {{"station_m", 4.0}, {"manhole", nullptr}};
    truth = {{"girder", {{"centreline", line}, {"length_m", 10.0},
                         {"compartments", nlohmann::json::array()}, {"diaphragms", {plate}}}}};
    for (int k = 10; k <= 80; ++k)
      mapped.mapped.stations.girder.centreline.push_back({0.1 * k, Eigen::Vector3d(0.1 * k, 0.0, 0.6), "measured"});
    for (double x : {4.004, 10.01}) {
      Diaphragm d;
      d.station_m = x;
      d.point = Eigen::Vector3d(x, 0.0, 0.6);
      mapped.mapped.stations.girder.diaphragms.push_back(d);
    }
  }
};

TEST(GirderScoring, APlateTheMapFoundBeyondItsStationsCountsAndOneItDidNotIsNoMiss) {
  StraightGirder t;
  GirderScore g = score_girder(t.mapped, t.truth, nlohmann::json::array());
  // The end wall beyond the stations is found, not invented; the start wall behind them,
  // which the map did not show, is no miss.
  EXPECT_EQ(g.plates_true, 2);
  EXPECT_EQ(g.plates_matched, 2);
  EXPECT_EQ(g.plates_invented, 0);
  EXPECT_EQ(g.plates_missed, 0);
  ASSERT_EQ(g.plate_error_mm.size(), 2u);
  EXPECT_NEAR(g.plate_error_mm[0], 4.0, 1e-6);
  EXPECT_NEAR(g.plate_error_mm[1], 10.0, 1e-6);
  // Without the end wall in the map: one plate, found; the diaphragm within the stations,
  // when the map misses it, is a miss.
  t.mapped.mapped.stations.girder.diaphragms.pop_back();
  g = score_girder(t.mapped, t.truth, nlohmann::json::array());
  EXPECT_EQ(g.plates_true, 1);
  EXPECT_EQ(g.plates_missed, 0);
  t.mapped.mapped.stations.girder.diaphragms.clear();
  g = score_girder(t.mapped, t.truth, nlohmann::json::array());
  EXPECT_EQ(g.plates_true, 1);
  EXPECT_EQ(g.plates_missed, 1);
}

// Two compartments, 0.80 m wide to 5 m and 0.83 m beyond: the map placed their joint at 5.3 m.
TEST(GirderScoring, AJointIsScoredAgainstTheUncertaintyTheMapStatedForIt) {
  StraightGirder t;
  t.truth["girder"]["compartments"] = {{{"from_m", 0.0}, {"to_m", 5.0}, {"width_m", 0.80}, {"height_m", 1.2}},
                                       {{"from_m", 5.0}, {"to_m", 10.0}, {"width_m", 0.83}, {"height_m", 1.2}}};
  Section before, after;
  before.from_m = 1.0, before.to_m = 5.3, after.from_m = 5.3, after.to_m = 8.0;
  after.joint_seen = false, after.joint_uncertainty_m = 0.5;  // a plate hid a metre of it
  t.mapped.mapped.stations.sections = {before, after};
  GirderScore g = score_girder(t.mapped, t.truth, nlohmann::json::array());
  EXPECT_EQ(g.joints_true, 1);
  EXPECT_EQ(g.joints_found, 0);  // 0.3 m off: beyond the 0.2 m a found joint may be
  ASSERT_EQ(g.joint_error_mm.size(), 1u);
  EXPECT_NEAR(g.joint_error_mm[0], 300.0, 1e-6);
  EXPECT_EQ(g.joints_within_stated, 1);
  // The same place stated as seen within one station step is outside what the map claimed.
  t.mapped.mapped.stations.sections[1].joint_seen = true;
  t.mapped.mapped.stations.sections[1].joint_uncertainty_m = 0.1;
  g = score_girder(t.mapped, t.truth, nlohmann::json::array());
  EXPECT_EQ(g.joints_within_stated, 0);
  t.mapped.mapped.stations.sections[1].from_m = 5.08;
  g = score_girder(t.mapped, t.truth, nlohmann::json::array());
  EXPECT_EQ(g.joints_found, 1);
  EXPECT_EQ(g.joints_within_stated, 1);
}

}  // namespace
}  // namespace tunnelmap
