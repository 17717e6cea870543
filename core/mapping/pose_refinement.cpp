#include "core/mapping/pose_refinement.h"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <map>
#include <unordered_map>

namespace tunnelmap {

namespace {

constexpr double kDeg = M_PI / 180.0;

// The map every group is aligned with: per station and wall the outer surface's position, and
// the transverse faces' positions along the axis, from the wall samples of the other groups.
// Only targets that more than one group measured say anything about a group's pose: a face
// only the group itself saw (the same plate twice) agrees with it by construction.
struct Targets {
  std::unordered_map<long long, double> wall;  // key(station, wall) -> outward position
  std::vector<std::pair<double, double>> transverse;  // [from, to] intervals along the axis
  std::vector<double> transverse_at;                  // their positions
};

long long key(int station, int wall) { return static_cast<long long>(station) * 8 + wall; }

double weighted_median(std::vector<std::pair<double, double>>& v) {
  std::sort(v.begin(), v.end());
  double total = 0.0;
  for (const auto& p : v) total += p.second;
  double acc = 0.0;
  for (const auto& p : v) {
    acc += p.second;
    if (acc >= 0.5 * total) return p.first;
  }
  return v.back().first;
}

struct TunnelFrame {
  Eigen::Vector3d origin, axis, up, left;
  Eigen::Vector3d outward[4];
};

// Where a frame's samples are, in the tunnel frame, under the current poses.
struct Placed {
  int station;
  int wall;
  double position;  // wall: outward position + inset (the outer surface); transverse: along axis
  double weight;
  Eigen::Vector3d world;
};

void place(const FrameWalls& fw, const Eigen::Isometry3d& T, const TunnelFrame& tf, double step,
           double max_transverse_depth, std::vector<Placed>& out) {
  for (const WallSample& s : fw.samples) {
    if (!s.on_surface) continue;  // no known zone: its position says nothing comparable
    // A face seen head-on far away: structured light quantises its depth in steps of
    // centimetres (depth^2 / (f b subpixels)), all in one direction over the whole face.
    if (s.wall == kTransverseSample && s.point.z() > max_transverse_depth) continue;
    const Eigen::Vector3d x = T * s.point.cast<double>();
    const Eigen::Vector3d d = x - tf.origin;
    const int station = static_cast<int>(std::floor(tf.axis.dot(d) / step));
    const double position = s.wall < 4 ? tf.outward[s.wall].dot(d) + s.inset_m : tf.axis.dot(d);
    out.push_back({station, s.wall, position, static_cast<double>(s.points), x});
  }
}

Targets build_targets(const std::vector<std::vector<Placed>>& placed, const std::vector<int>& group_of,
                      int excluded, double gap) {
  std::unordered_map<long long, std::vector<std::pair<double, double>>> walls;
  std::unordered_map<long long, std::vector<int>> wall_groups;
  std::vector<std::pair<double, double>> across;
  std::vector<std::pair<double, int>> across_groups;
  for (std::size_t f = 0; f < placed.size(); ++f) {
    if (group_of[f] == excluded) continue;
    for (const Placed& p : placed[f]) {
      if (p.wall < 4) {
        walls[key(p.station, p.wall)].push_back({p.position, p.weight});
        std::vector<int>& g = wall_groups[key(p.station, p.wall)];
        if (std::find(g.begin(), g.end(), group_of[f]) == g.end()) g.push_back(group_of[f]);
      } else {
        across.push_back({p.position, p.weight});
        across_groups.push_back({p.position, group_of[f]});
      }
    }
  }
  Targets t;
  for (auto& [k, v] : walls)
    if (wall_groups[k].size() >= 2) t.wall[k] = weighted_median(v);
  std::sort(across.begin(), across.end());
  std::sort(across_groups.begin(), across_groups.end());
  for (std::size_t i = 0; i < across.size();) {
    std::size_t j = i + 1;
    while (j < across.size() && across[j].first - across[j - 1].first < gap) ++j;
    std::vector<int> g;
    for (std::size_t k = i; k < j; ++k)
      if (std::find(g.begin(), g.end(), across_groups[k].second) == g.end()) g.push_back(across_groups[k].second);
    if (g.size() >= 2) {
      std::vector<std::pair<double, double>> cluster(across.begin() + i, across.begin() + j);
      t.transverse.push_back({across[i].first - gap, across[j - 1].first + gap});
      t.transverse_at.push_back(weighted_median(cluster));
    }
    i = j;
  }
  return t;
}

// One Gauss-Newton step of a group's correction: x' = x + w x (x - c) + t (world frame).
struct Step {
  Eigen::Matrix<double, 6, 1> delta = Eigen::Matrix<double, 6, 1>::Zero();
  bool degenerate[6] = {false, false, false, false, false, false};
  int samples = 0;
};

Step solve_group(const std::vector<const std::vector<Placed>*>& frames, const Targets& t,
                 const TunnelFrame& tf, const Eigen::Vector3d& centre,
                 const PoseRefinementOptions& o) {
  Eigen::Matrix<double, 6, 6> H = Eigen::Matrix<double, 6, 6>::Zero();
  Eigen::Matrix<double, 6, 1> b = Eigen::Matrix<double, 6, 1>::Zero();
  Step step;
  for (const std::vector<Placed>* placed : frames)
    for (const Placed& p : *placed) {
      double target = 0.0;
      Eigen::Vector3d dir;
      if (p.wall < 4) {
        const auto it = t.wall.find(key(p.station, p.wall));
        if (it == t.wall.end()) continue;
        target = it->second;
        dir = tf.outward[p.wall];
      } else {
        int hit = -1;
        for (std::size_t k = 0; k < t.transverse.size(); ++k)
          if (p.position >= t.transverse[k].first && p.position <= t.transverse[k].second) hit = int(k);
        if (hit < 0) continue;
        target = t.transverse_at[static_cast<std::size_t>(hit)];
        dir = tf.axis;
      }
      const double r = p.position - target;
      if (std::abs(r) > o.gross_m) continue;
      const double w = p.weight * (std::abs(r) <= o.huber_m ? 1.0 : o.huber_m / std::abs(r));
      Eigen::Matrix<double, 6, 1> J;
      J.head<3>() = (p.world - centre).cross(dir);
      J.tail<3>() = dir;
      H += w * J * J.transpose();
      b -= w * J * r;
      ++step.samples;
    }
  // Only the directions the samples constrain: the rest keep their value.
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix<double, 6, 6>> eig(H);
  const double top = eig.eigenvalues().maxCoeff();
  if (!(top > 0)) {
    std::fill(std::begin(step.degenerate), std::end(step.degenerate), true);
    return step;
  }
  Eigen::Matrix<double, 6, 6> null_space = Eigen::Matrix<double, 6, 6>::Zero();
  for (int i = 0; i < 6; ++i) {
    const Eigen::Matrix<double, 6, 1> v = eig.eigenvectors().col(i);
    if (eig.eigenvalues()[i] > o.degenerate_ratio * top)
      step.delta += v * (v.dot(b) / eig.eigenvalues()[i]);
    else
      null_space += v * v.transpose();
  }
  // The tunnel-frame directions: a direction mostly in the null space is degenerate.
  const Eigen::Vector3d basis[6] = {tf.axis, tf.left, tf.up, tf.left, tf.up, tf.axis};
  for (int a = 0; a < 6; ++a) {
    Eigen::Matrix<double, 6, 1> e = Eigen::Matrix<double, 6, 1>::Zero();
    if (a < 3) e.head<3>() = basis[a];
    else e.tail<3>() = basis[a];
    step.degenerate[a] = e.dot(null_space * e) > 0.5;
  }
  return step;
}

Eigen::Isometry3d small_motion(const Eigen::Matrix<double, 6, 1>& d, const Eigen::Vector3d& centre) {
  // x' = R (x - c) + c + t
  Eigen::Isometry3d m = Eigen::Isometry3d::Identity();
  const double angle = d.head<3>().norm();
  if (angle > 0) m.linear() = Eigen::AngleAxisd(angle, d.head<3>() / angle).toRotationMatrix();
  m.translation() = centre - m.linear() * centre + d.tail<3>();
  return m;
}

}  // namespace

const char* pose_axis_name(int axis) {
  static const char* names[] = {"roll", "pitch", "yaw", "lateral", "vertical", "axial"};
  return axis >= 0 && axis < 6 ? names[axis] : "?";
}

PoseRefinement refine_poses(const std::vector<TunnelMap>& maps, const std::vector<FrameWalls>& walls,
                            const std::vector<Eigen::Isometry3d>& poses,
                            const std::vector<int>& groups, const PoseRefinementOptions& o) {
  const auto t0 = std::chrono::steady_clock::now();
  PoseRefinement out;
  out.poses = poses;
  const std::size_t n = poses.size();
  std::map<int, std::vector<int>> members;  // group -> frames
  for (std::size_t i = 0; i < n; ++i) members[i < groups.size() ? groups[i] : 0].push_back(int(i));
  for (const auto& [g, frames] : members) {
    PoseCorrection c;
    c.group = g;
    c.frames = frames;
    out.groups.push_back(c);
  }
  // The tunnel frame: axis and up of the first detected frame, origin at the first camera.
  int first = -1;
  for (std::size_t i = 0; i < n && first < 0; ++i)
    if (i < maps.size() && maps[i].detected) first = int(i);
  if (first < 0 || n == 0) return out;
  TunnelFrame tf;
  tf.origin = poses[0].translation();
  tf.axis = (poses[first].linear() * maps[first].axis_dir).normalized();
  if (tf.axis.dot(poses[0].linear().col(2)) < 0) tf.axis = -tf.axis;
  tf.up = poses[first].linear() * maps[first].up;
  tf.up = (tf.up - tf.axis * tf.axis.dot(tf.up)).normalized();
  tf.left = tf.up.cross(tf.axis);
  tf.outward[0] = tf.left;
  tf.outward[1] = -tf.left;
  tf.outward[2] = tf.up;
  tf.outward[3] = -tf.up;
  out.ran = true;

  std::vector<int> group_of(n);
  for (const PoseCorrection& c : out.groups)
    for (int f : c.frames) group_of[static_cast<std::size_t>(f)] = c.group;
  std::vector<std::vector<Placed>> placed(n);
  for (int it = 0; it < o.max_iterations; ++it) {
    for (std::size_t f = 0; f < n; ++f) {
      placed[f].clear();
      if (f < maps.size() && maps[f].detected && f < walls.size())
        place(walls[f], out.poses[f], tf, o.station_step_m, o.max_transverse_depth_m, placed[f]);
    }
    double worst_deg = 0.0, worst_m = 0.0;
    std::vector<Eigen::Isometry3d> motion(out.groups.size(), Eigen::Isometry3d::Identity());
    // The map of every group, the group itself included: where most groups agree, the median
    // is theirs, so one sagging pose cannot pull the others (leaving a group out would make the
    // median of two groups flip between them).
    const Targets targets = build_targets(placed, group_of, -1, o.transverse_gap_m);
    for (std::size_t s = 0; s < out.groups.size(); ++s) {
      PoseCorrection& c = out.groups[s];
      std::vector<const std::vector<Placed>*> frames;
      Eigen::Vector3d centre = Eigen::Vector3d::Zero();
      for (int f : c.frames) {
        frames.push_back(&placed[static_cast<std::size_t>(f)]);
        centre += out.poses[static_cast<std::size_t>(f)].translation();
      }
      centre /= double(c.frames.size());
      const Step step = solve_group(frames, targets, tf, centre, o);
      c.samples = step.samples;
      c.constrained.clear();
      c.degenerate.clear();
      for (int a = 0; a < 6; ++a)
        (step.degenerate[a] ? c.degenerate : c.constrained).push_back(pose_axis_name(a));
      motion[s] = small_motion(step.delta, centre);
      worst_deg = std::max(worst_deg, step.delta.head<3>().norm() / kDeg);
      worst_m = std::max(worst_m, step.delta.tail<3>().norm());
    }
    // Every group moves at once (Jacobi): the map of the next round comes from the new poses.
    for (std::size_t s = 0; s < out.groups.size(); ++s) {
      out.groups[s].delta = motion[s] * out.groups[s].delta;
      for (int f : out.groups[s].frames)
        out.poses[static_cast<std::size_t>(f)] = out.groups[s].delta * poses[static_cast<std::size_t>(f)];
    }
    out.iterations = it + 1;
    if (worst_deg < o.converged_deg && worst_m < o.converged_m) break;
  }
  for (PoseCorrection& c : out.groups) {
    c.rotation_deg = Eigen::AngleAxisd(c.delta.linear()).angle() / kDeg;
    Eigen::Vector3d centre = Eigen::Vector3d::Zero();
    for (int f : c.frames) centre += poses[static_cast<std::size_t>(f)].translation();
    centre /= double(c.frames.size());
    c.translation_mm = ((c.delta * centre) - centre).norm() * 1000.0;
  }
  out.ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
  return out;
}

}  // namespace tunnelmap
