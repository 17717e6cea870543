#include "core/evaluation/joint_sightings.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <map>
#include <optional>
#include <string>

#include "core/evaluation/truth_pose.h"

namespace tunnelmap {

namespace {

constexpr double kBinM = 0.05;
// A 5 cm bin of a wall counts as seen with this many sampled pixels over all frames (one pixel
// in kPixelStep x kPixelStep: about 80 pixels), what a plane of the map needs at the least.
constexpr int kPixelStep = 4;
constexpr int kSeenSamples = 5;
// Frames whose camera stands farther from every joint than the sensor's range see neither side.
constexpr double kFrameReachM = 7.0;
// The line points searched either side of the camera's: 7 m at the truth's 0.1 m spacing.
constexpr std::size_t kLineReach = 70;

constexpr const char* kWalls[4] = {"left", "right", "top", "bottom"};

// The labels of the four walls' plates (edge bands and middle plates): per label id, the
// section and the wall (0-3), or -1; and per joint, the walls whose offsets step there.
struct WallLabels {
  std::vector<int> section = std::vector<int>(65536, -1), wall = std::vector<int>(65536, -1);
  std::vector<std::array<bool, 4>> steps;  // per joint n, between sections n and n + 1
};

double middle_offset(const nlohmann::json& surfaces, int section, const std::string& wall) {
  for (const auto& s : surfaces)
    if (s.value("section", -1) == section && s.value("wall", "") == wall && s.value("zone", "") == "middle")
      return s["offset_m"].get<double>();
  return std::numeric_limits<double>::quiet_NaN();
}

// Empty `steps` when the truth's sections are not one more than the joints.
WallLabels wall_labels(const nlohmann::json& truth, std::size_t joints) {
  const nlohmann::json& sections = truth.value("sections", nlohmann::json::array());
  const nlohmann::json& surfaces = truth.value("surfaces", nlohmann::json::array());
  WallLabels out;
  if (sections.size() != joints + 1) return out;
  for (const auto& s : surfaces) {
    const std::string wall = s.value("wall", ""), zone = s.value("zone", "");
    const int c = static_cast<int>(std::find(kWalls, kWalls + 4, wall) - kWalls);
    if (c == 4 || zone == "step" || s.value("section", -1) < 0) continue;
    const std::size_t id = s["id"].get<std::size_t>() & 0xffff;
    out.section[id] = s["section"].get<int>(), out.wall[id] = c;
  }
  for (int n = 0; n + 1 < static_cast<int>(sections.size()); ++n) {
    std::array<bool, 4> steps{};
    for (int c = 0; c < 4; ++c)
      steps[c] = std::abs(middle_offset(surfaces, n + 1, kWalls[c]) - middle_offset(surfaces, n, kWalls[c])) > 1e-4;
    out.steps.push_back(steps);
  }
  return out;
}

// Sampled pixels per 2 * joint + side (0 the section before the joint, 1 after) and 5 cm bin of truth station.
using Bins = std::vector<std::map<long, int>>;

void count_frame(const Dataset& ds, std::size_t i, const Eigen::Isometry3d& T, const TruthLine& line,
                 const WallLabels& walls, Bins& bins) {
  const std::vector<std::uint16_t> labels = ds.load_gt_surfaces(i);
  if (labels.empty()) return;
  const DepthFrame depth = ds.load_frame(i);
  const std::size_t camera = line.nearest(T.translation());
  const Intrinsics& K = ds.intrinsics;
  const int joints = static_cast<int>(walls.steps.size());
  for (int v = 0; v < K.height; v += kPixelStep)
    for (int u = 0; u < K.width; u += kPixelStep) {
      const std::uint16_t id = labels[static_cast<std::size_t>(v) * K.width + u];
      const int section = walls.section[id], c = walls.wall[id];
      const double z = depth.depth_m(u, v);
      if (section < 0 || !(z > 0)) continue;
      // The section's plate is the side before its own joint and the side after the previous one.
      const bool before = section < joints && walls.steps[static_cast<std::size_t>(section)][static_cast<std::size_t>(c)];
      const bool after = section > 0 && walls.steps[static_cast<std::size_t>(section - 1)][static_cast<std::size_t>(c)];
      if (!before && !after) continue;
      const long bin = static_cast<long>(std::floor(line.station_near(T * (K.ray(u, v) * z), camera, kLineReach) / kBinM));
      if (before) ++bins[static_cast<std::size_t>(2 * section)][bin];
      if (after) ++bins[static_cast<std::size_t>(2 * section - 1)][bin];
    }
}

JointSighting sighting(double joint_m, const std::map<long, int>& before, const std::map<long, int>& after) {
  JointSighting s;
  s.joint_m = joint_m;
  for (const auto& [bin, n] : before)
    if (n >= kSeenSamples && bin * kBinM < joint_m) s.seen_before_m = std::min(joint_m, (bin + 1) * kBinM);
  for (auto it = after.rbegin(); it != after.rend(); ++it)
    if (it->second >= kSeenSamples && (it->first + 1) * kBinM > joint_m) s.seen_after_m = std::max(joint_m, it->first * kBinM);
  return s;
}

}  // namespace

std::vector<JointSighting> joint_sightings(const Dataset& ds, const TruthLine& line, const std::vector<double>& joint_m) {
  if (joint_m.empty()) return {};
  const WallLabels walls = wall_labels(ds.ground_truth, joint_m.size());
  if (walls.steps.size() != joint_m.size()) return {};
  Bins bins(2 * joint_m.size());
  for (std::size_t i = 0; i < ds.frames.size(); ++i) {
    const std::optional<Eigen::Isometry3d> camera = truth_pose(ds.frames[i].raw);
    if (ds.frames[i].gt_path.empty() || !camera) return {};
    const double camera_m = line.station_of(camera->translation());
    const bool near = std::any_of(joint_m.begin(), joint_m.end(),
                                  [&](double j) { return std::abs(j - camera_m) < kFrameReachM; });
    if (near) count_frame(ds, i, *camera, line, walls, bins);
  }
  std::vector<JointSighting> out;
  for (std::size_t k = 0; k < joint_m.size(); ++k) out.push_back(sighting(joint_m[k], bins[2 * k], bins[2 * k + 1]));
  return out;
}

void score_joint_sightings(const Dataset& ds, const GirderScoringOptions& options, GirderScore& g) {
  if (!ds.ground_truth.contains("girder")) return;
  const TruthLine line(ds.ground_truth["girder"]["centreline"]);
  const std::vector<JointSighting> seen = joint_sightings(ds, line, g.joint_station_m);
  if (seen.size() != g.joint_station_m.size()) return;
  g.joints_seen = 0, g.joints_found_of_seen = 0;
  for (std::size_t k = 0; k < seen.size(); ++k) {
    g.joint_seen_before_m.push_back(seen[k].seen_before_m);
    g.joint_seen_after_m.push_back(seen[k].seen_after_m);
    if (!seen[k].seen_within(options.joint_tolerance_m)) continue;
    ++*g.joints_seen;
    *g.joints_found_of_seen += g.joint_found[k] ? 1 : 0;
  }
}

}  // namespace tunnelmap
