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
  // Cameras on the centre line looking along it, two frames per stop: the first mapped 6 mm
  // ahead, 4 mm to the left and 2 mm high of the truth, the second as far behind, right and
  // low. Nothing rigid moves one frame of a stop one way and the other the other way, so the
  // alignment has nothing to remove, and the split must follow the curve.
  const CurvedTruth t;
  const int stops = 15;
  std::vector<Eigen::Isometry3d> truths;
  std::vector<Eigen::Vector3d> errors;
  for (int i = 0; i < 2 * stops; ++i) {
    const double s = 1.0 + 2.0 * (i / 2);
    const Eigen::Vector3d along = t.along_at(s), up = Eigen::Vector3d::UnitZ(), left = up.cross(along);
    Eigen::Isometry3d truth = Eigen::Isometry3d::Identity();
    truth.linear().col(2) = along, truth.linear().col(1) = -up, truth.linear().col(0) = -left;
    truth.translation() = t.point_at(s);
    truths.push_back(truth);
    const double sign = i % 2 == 0 ? 1.0 : -1.0;
    errors.push_back(sign * (0.006 * along + 0.004 * left + 0.002 * up));
  }
  nlohmann::json frames = nlohmann::json::array();
  DatasetMapping mapped;
  for (std::size_t i = 0; i < truths.size(); ++i) {
    frames.push_back({{"pose_true", pose_json(truths[i])}});
    Eigen::Isometry3d estimate = truths[i];
    estimate.translation() += errors[i];
    mapped.mapped.poses.push_back(estimate);
  }
  const GirderScore g = score_girder(mapped, t.truth, frames);
  ASSERT_EQ(g.pose_error_along_mm.size(), truths.size());
  ASSERT_EQ(g.frame_pose_errors.size(), truths.size());
  for (std::size_t i = 0; i < truths.size(); ++i) {
    const double s = 1.0 + 2.0 * static_cast<double>(i / 2);
    const Eigen::Vector3d along = t.along_at(s), up = Eigen::Vector3d::UnitZ(), left = up.cross(along);
    const Eigen::Vector3d e = 1000.0 * errors[i];
    EXPECT_NEAR(g.pose_error_along_mm[i], e.dot(along), 0.01) << i;
    EXPECT_NEAR(g.pose_error_across_mm[i], e.dot(left), 0.01) << i;  // positive to the left
    EXPECT_NEAR(g.pose_error_vertical_mm[i], e.dot(up), 0.01) << i;
    EXPECT_NEAR(g.pose_error_mm[i], e.norm(), 0.01) << i;
    EXPECT_NEAR(g.pose_error_deg[i], 0.0, 1e-6) << i;
    const FramePoseError& f = g.frame_pose_errors[i];  // the same, frame by frame
    EXPECT_EQ(f.frame, static_cast<int>(i));
    EXPECT_NEAR(f.station_m, s, 0.01) << i;
    EXPECT_NEAR(f.along_mm, e.dot(along), 0.01) << i;
    EXPECT_NEAR(f.across_mm, e.dot(left), 0.01) << i;
    EXPECT_NEAR(f.vertical_mm, e.dot(up), 0.01) << i;
  }
}

TEST(GirderScoring, TheAlignmentFitsTheCameraCentresNotACommonTiltOfTheCameras) {
  // The walk's centres mapped exactly, only moved and turned as a whole; every camera pitched
  // 0.2 degrees more than its truth (a camera mounted askew). Aligned by the orientations, a
  // 0.2 degree tilt of the 30 m walk would leave 50 mm at its ends; aligned by the centres, the
  // orientations' small weight leaves about 1.4 mm there.
  const CurvedTruth t;
  const double tilt_rad = 0.2 * M_PI / 180.0;
  const Eigen::Isometry3d moved = Eigen::Translation3d(3.0, -2.0, 0.5) * Eigen::AngleAxisd(0.3, Eigen::Vector3d::UnitZ());
  nlohmann::json frames = nlohmann::json::array();
  DatasetMapping mapped;
  for (int i = 0; i < 30; ++i) {
    const double s = 1.0 + i;
    const Eigen::Vector3d along = t.along_at(s), up = Eigen::Vector3d::UnitZ(), left = up.cross(along);
    Eigen::Isometry3d truth = Eigen::Isometry3d::Identity();
    truth.linear().col(2) = along, truth.linear().col(1) = -up, truth.linear().col(0) = -left;
    truth.translation() = t.point_at(s);
    frames.push_back({{"pose_true", pose_json(truth)}});
    Eigen::Isometry3d estimate = moved * truth;
    estimate.linear() = estimate.linear() * Eigen::AngleAxisd(tilt_rad, Eigen::Vector3d::UnitX()).toRotationMatrix();
    mapped.mapped.poses.push_back(estimate);
  }
  const GirderScore g = score_girder(mapped, t.truth, frames);
  ASSERT_EQ(g.pose_error_mm.size(), 30u);
  for (std::size_t i = 0; i < 30; ++i) {
    EXPECT_LT(g.pose_error_mm[i], 2.0) << i;
    EXPECT_NEAR(g.pose_error_deg[i], 0.2, 0.01) << i;
    // The cameras pitched up about their own x axis (to the right): about the girder's
    // across axis (to the left), negative; no roll, no heading.
    EXPECT_NEAR(g.frame_pose_errors[i].pitch_deg, -0.2, 0.01) << i;
    EXPECT_NEAR(g.frame_pose_errors[i].roll_deg, 0.0, 0.01) << i;
    EXPECT_NEAR(g.frame_pose_errors[i].heading_deg, 0.0, 0.01) << i;
  }
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

TEST(GirderScoring, WhatTheMapPlacedIsScoredAfterThePosesAlignment) {
  // The whole map 30 mm ahead of the truth, its poses as well: where a map's frame starts is
  // the odometry's choice, not a plate's error. Without the true poses nothing is aligned.
  StraightGirder t;
  const Eigen::Vector3d ahead(0.03, 0.0, 0.0);
  for (CentrelinePoint& c : t.mapped.mapped.stations.girder.centreline) c.point += ahead;
  for (Diaphragm& d : t.mapped.mapped.stations.girder.diaphragms) d.point += ahead;
  nlohmann::json frames = nlohmann::json::array();
  for (int k = 1; k <= 8; ++k) {
    Eigen::Isometry3d truth = Eigen::Isometry3d::Identity();
    truth.linear() << 0, 0, 1, -1, 0, 0, 0, -1, 0;  // looking along world x
    truth.translation() = Eigen::Vector3d(k, 0.0, 0.6);
    frames.push_back({{"pose_true", pose_json(truth)}});
    t.mapped.mapped.poses.push_back(Eigen::Translation3d(ahead) * truth);
  }
  GirderScore g = score_girder(t.mapped, t.truth, frames);
  ASSERT_EQ(g.plate_error_mm.size(), 2u);
  EXPECT_NEAR(g.plate_error_mm[0], 4.0, 1e-6);
  EXPECT_NEAR(g.plate_error_mm[1], 10.0, 1e-6);
  ASSERT_EQ(g.pose_error_mm.size(), 8u);
  EXPECT_NEAR(g.pose_error_mm.back(), 0.0, 1e-6);
  g = score_girder(t.mapped, t.truth, nlohmann::json::array());
  ASSERT_EQ(g.plate_error_mm.size(), 2u);
  EXPECT_NEAR(g.plate_error_mm[0], 34.0, 1e-6);
  EXPECT_TRUE(g.pose_error_mm.empty());
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
