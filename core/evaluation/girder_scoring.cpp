#include "core/evaluation/girder_scoring.h"

#include <Eigen/Geometry>
#include <Eigen/SVD>
#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

#include "core/evaluation/truth_line.h"
#include "core/evaluation/truth_pose.h"

namespace tunnelmap {

namespace {

// A point the map placed, in its truth station: moved by the alignment first.
struct MapInTruth {
  const TruthLine& line;
  Eigen::Isometry3d to_truth;
  double station_of(const Eigen::Vector3d& mapped) const { return line.station_of(to_truth * mapped); }
};

struct TruthPlate {
  double station;
  bool manhole;
  double width, height;
};

struct TruthRoom {
  double from, to, width, height;
};

bool near_any(double s, const std::vector<double>& marks, double d) {
  return std::any_of(marks.begin(), marks.end(), [&](double m) { return std::abs(s - m) < d; });
}

void score_stations(const StationMap& m, const MapInTruth& line, const std::vector<TruthRoom>& rooms,
                    const std::vector<double>& changes, const GirderScoringOptions& o, GirderScore& g) {
  for (std::size_t k = 0; k < m.stations.size() && k < m.girder.centreline.size(); ++k) {
    const Station& st = m.stations[k];
    const double s = line.station_of(m.girder.centreline[k].point);
    if (near_any(s, changes, o.skip_near_change_m)) continue;
    const auto room = std::find_if(rooms.begin(), rooms.end(), [&](const TruthRoom& r) { return s >= r.from && s < r.to; });
    if (room == rooms.end()) continue;
    if (st.width_source == DimensionSource::Measured) g.width_error_mm.push_back((st.width_m - room->width) * 1000);
    if (st.height_source == DimensionSource::Measured) g.height_error_mm.push_back((st.height_m - room->height) * 1000);
  }
}

// Sections: the truth's cross-section changes against the map's section boundaries.
void score_sections(const StationMap& m, const MapInTruth& line, const std::vector<TruthRoom>& rooms,
                    const GirderScoringOptions& o, GirderScore& g) {
  std::vector<double> truth_joints;
  for (std::size_t k = 1; k < rooms.size(); ++k)
    if (std::abs(rooms[k].width - rooms[k - 1].width) > 1e-6 || std::abs(rooms[k].height - rooms[k - 1].height) > 1e-6)
      truth_joints.push_back(rooms[k].from);
  std::vector<double> found, stated;
  for (std::size_t k = 1; k < m.sections.size(); ++k) {
    found.push_back(line.station_of(m.to_world(m.sections[k].from_m, 0.0, 0.0)));
    stated.push_back(m.sections[k].joint_uncertainty_m);
  }
  g.sections_true = static_cast<int>(truth_joints.size()) + 1;
  g.sections_found = static_cast<int>(m.sections.size());
  g.joints_true = static_cast<int>(truth_joints.size());
  for (double j : truth_joints) {
    g.joint_station_m.push_back(j);
    g.joint_found.push_back(near_any(j, found, o.joint_tolerance_m));
    g.joints_found += g.joint_found.back() ? 1 : 0;
  }
  for (double j : truth_joints) {
    if (found.empty()) break;
    const auto nearest = std::min_element(found.begin(), found.end(),
                                          [&](double a, double b) { return std::abs(a - j) < std::abs(b - j); });
    const double error = *nearest - j;
    g.joint_error_mm.push_back(error * 1000);
    // A millimetre of slack: a joint placed exactly one stated step away is within it.
    g.joints_within_stated += std::abs(error) <= stated[static_cast<std::size_t>(nearest - found.begin())] + 1e-3 ? 1 : 0;
  }
  for (double f : found) g.phantom_sections += near_any(f, truth_joints, o.joint_tolerance_m) ? 0 : 1;
}

// Plates are seen from afar, so a map may show one beyond its stations' extent (the end wall
// ahead of the last stop): a plate outside the extent counts when the map found it, and is no
// miss when it did not.
void score_plates(const StationMap& m, const MapInTruth& line, const std::vector<TruthPlate>& plates,
                  double seen_from, double seen_to, const GirderScoringOptions& o, GirderScore& g) {
  std::vector<bool> used(plates.size(), false);
  for (const Diaphragm& d : m.girder.diaphragms) {
    const double s = line.station_of(d.point);
    int best = -1;
    for (std::size_t i = 0; i < plates.size(); ++i)
      if (!used[i] && (best < 0 || std::abs(plates[i].station - s) < std::abs(plates[best].station - s))) best = int(i);
    // Within the spacing of plates, the nearest truth plate is this one; the error decides.
    if (best < 0 || std::abs(plates[best].station - s) > 0.5) {
      ++g.plates_invented;
      continue;
    }
    used[best] = true;
    const TruthPlate& t = plates[best];
    g.plate_error_mm.push_back((s - t.station) * 1000);
    if (std::abs(s - t.station) <= o.plate_tolerance_m) ++g.plates_matched;
    if (!t.manhole) continue;
    if (!d.manhole) {
      ++g.manholes_unmeasured;
      continue;
    }
    g.manhole_width_error_mm.push_back((d.manhole->width_m - t.width) * 1000);
    g.manhole_height_error_mm.push_back((d.manhole->height_m - t.height) * 1000);
  }
  for (std::size_t i = 0; i < plates.size(); ++i) {
    const bool inside = plates[i].station >= seen_from && plates[i].station <= seen_to;
    if (!inside && !used[i]) continue;
    ++g.plates_true;
    if (!used[i]) ++g.plates_missed;
  }
}

// The truth girder's frame at `truth`: along its centre line, across it (horizontal, to the
// left; the simulator's world up is +z) and vertical. None where the line runs vertically.
std::optional<Eigen::Matrix3d> girder_frame(const Eigen::Vector3d& truth, const TruthLine& line) {
  const Eigen::Vector3d along = line.direction_at(truth);
  Eigen::Vector3d across = Eigen::Vector3d::UnitZ().cross(along);
  if (across.norm() < 1e-6) return std::nullopt;
  across.normalize();
  Eigen::Matrix3d axes;
  axes << along, across, along.cross(across);
  return axes;
}

// Every frame's true camera-to-world pose ("pose_true"), or none when a frame lacks one.
std::vector<Eigen::Isometry3d> truth_poses(const nlohmann::json& frames, std::size_t n) {
  if (n < 3) return {};
  std::vector<Eigen::Isometry3d> poses(n, Eigen::Isometry3d::Identity());
  for (std::size_t i = 0; i < n; ++i) {
    const std::optional<Eigen::Isometry3d> T = truth_pose(frames[i]);
    if (!T) return {};
    poses[i] = *T;
  }
  return poses;
}

// One rigid alignment of the whole sequence, map to truth: the one that fits the camera
// centres best (the trajectory error's usual alignment, Horn's). The centres of a straight
// walk lie almost on a line, which leaves the roll about it free, so each frame's orientation
// also counts, as much as a point a metre off its centre: on a walk of tens of metres the
// positions decide the heading and the pitch, and a camera mounted slightly askew does not
// tilt the walk.
Eigen::Isometry3d align_to_truth(const std::vector<Eigen::Isometry3d>& mapped, const std::vector<Eigen::Isometry3d>& truth) {
  const std::size_t n = truth.size();
  Eigen::Matrix3Xd est(3, n), tru(3, n);
  for (std::size_t i = 0; i < n; ++i) est.col(i) = mapped[i].translation(), tru.col(i) = truth[i].translation();
  const Eigen::Vector3d truth_mean = tru.rowwise().mean(), est_mean = est.rowwise().mean();
  const double orientation_weight_m2 = 1.0;
  Eigen::Matrix3d M = (tru.colwise() - truth_mean) * (est.colwise() - est_mean).transpose();
  for (std::size_t i = 0; i < n; ++i) M += orientation_weight_m2 * truth[i].linear() * mapped[i].linear().transpose();
  const Eigen::JacobiSVD<Eigen::Matrix3d> svd(M, Eigen::ComputeFullU | Eigen::ComputeFullV);
  Eigen::Matrix3d U = svd.matrixU();
  if ((U * svd.matrixV().transpose()).determinant() < 0) U.col(2) *= -1;
  Eigen::Isometry3d to_truth = Eigen::Isometry3d::Identity();
  to_truth.linear() = U * svd.matrixV().transpose();
  to_truth.translation() = truth_mean - to_truth.linear() * est_mean;
  return to_truth;
}

void score_poses(const DatasetMapping& dm, const std::vector<Eigen::Isometry3d>& truth,
                 const Eigen::Isometry3d& to_truth, const TruthLine& line, GirderScore& g) {
  for (std::size_t i = 0; i < truth.size(); ++i) {
    const Eigen::Isometry3d aligned = to_truth * dm.mapped.poses[i];
    const Eigen::Vector3d error = aligned.translation() - truth[i].translation();
    const Eigen::AngleAxisd turn(aligned.linear() * truth[i].linear().transpose());  // in the world
    FramePoseError f;
    f.frame = static_cast<int>(i);
    f.station_m = line.station_of(truth[i].translation());
    f.error_mm = error.norm() * 1000;
    f.rotation_deg = turn.angle() * 180 / M_PI;
    g.pose_error_mm.push_back(f.error_mm);
    g.pose_error_deg.push_back(f.rotation_deg);
    if (const auto axes = girder_frame(truth[i].translation(), line)) {
      const Eigen::Vector3d mm = axes->transpose() * error * 1000;
      const Eigen::Vector3d deg = axes->transpose() * turn.axis() * (turn.angle() * 180 / M_PI);
      f.along_mm = mm.x(), f.across_mm = mm.y(), f.vertical_mm = mm.z();
      f.roll_deg = deg.x(), f.pitch_deg = deg.y(), f.heading_deg = deg.z();
      f.split = true;
      g.pose_error_along_mm.push_back(f.along_mm);
      g.pose_error_across_mm.push_back(f.across_mm);
      g.pose_error_vertical_mm.push_back(f.vertical_mm);
    }
    g.frame_pose_errors.push_back(f);
  }
}

}  // namespace

GirderScore score_girder(const DatasetMapping& dm, const nlohmann::json& truth,
                         const nlohmann::json& frames, const GirderScoringOptions& o) {
  GirderScore g;
  const nlohmann::json& girder = truth["girder"];
  const TruthLine line(girder["centreline"]);
  std::vector<TruthRoom> rooms;
  for (const auto& r : girder["compartments"])
    rooms.push_back({r["from_m"].get<double>(), r["to_m"].get<double>(), r["width_m"].get<double>(),
                     r["height_m"].get<double>()});
  std::vector<TruthPlate> plates;
  std::vector<double> changes;
  for (const auto& p : girder["diaphragms"]) {
    const nlohmann::json& mh = p["manhole"];
    plates.push_back({p["station_m"].get<double>(), !mh.is_null(),
                      mh.is_null() ? 0.0 : mh["width_m"].get<double>(),
                      mh.is_null() ? 0.0 : mh["height_m"].get<double>()});
  }
  // The girder's end walls are plates too (without an opening).
  if (girder.contains("length_m")) {
    plates.push_back({0.0, false, 0.0, 0.0});
    plates.push_back({girder["length_m"].get<double>(), false, 0.0, 0.0});
  }
  for (const TruthPlate& p : plates) changes.push_back(p.station);
  for (const TruthRoom& r : rooms) changes.push_back(r.from);
  if (dm.mapped.refinement.ran) g.poses_kept = dm.mapped.refinement.given_poses_kept;
  for (const PoseCorrection& c : dm.mapped.refinement.groups) {
    g.correction_mm.push_back(c.translation_mm);
    g.correction_deg.push_back(c.rotation_deg);
  }
  // The map's frame is where its poses put it: everything it placed is scored after the same
  // rigid alignment as the poses (none without the true poses).
  const std::vector<Eigen::Isometry3d> truth_pose =
      truth_poses(frames, std::min<std::size_t>(dm.mapped.poses.size(), frames.size()));
  const Eigen::Isometry3d to_truth =
      truth_pose.empty() ? Eigen::Isometry3d::Identity() : align_to_truth(dm.mapped.poses, truth_pose);
  const MapInTruth placed{line, to_truth};
  const StationMap& m = dm.mapped.stations;
  score_stations(m, placed, rooms, changes, o, g);
  score_sections(m, placed, rooms, o, g);
  double seen_from = std::numeric_limits<double>::infinity(), seen_to = -seen_from;
  for (const CentrelinePoint& c : m.girder.centreline) {
    const double s = placed.station_of(c.point);
    seen_from = std::min(seen_from, s), seen_to = std::max(seen_to, s);
  }
  score_plates(m, placed, plates, seen_from - 0.1, seen_to + 0.1, o, g);
  if (!truth_pose.empty()) score_poses(dm, truth_pose, to_truth, line, g);
  const double n = std::max<std::size_t>(1, dm.maps.size());
  g.ms_per_frame = (dm.detect_ms + dm.map_ms) / n;
  return g;
}

}  // namespace tunnelmap
