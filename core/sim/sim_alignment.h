#pragma once
// SimAlignment: where the simulated girder lies in the world (docs/simulator.md#curves).
// The geometry is built in *local* coordinates (x = station along the girder, y to the left,
// z up from the floor), as the straight tunnel always was. A straight girder (no curve,
// gradient or cross-fall) has local = world. Otherwise the girder is a chain of straight
// compartments, as fabricated: the alignment (in plan a horizontal circle of radius R, or a
// straight, a transition curve and the circle; rising at a gradient that is constant or
// changes evenly (a vertical curve); through the point (0, 0, zc) heading +X; zc = half the
// height at station 0) is sampled at joint stations, every plate's and at most 4 m apart;
// each compartment is the chord between two joints, with its own rigid frame (x along the
// chord, y level across, rolled by the cross-fall); neighbours meet on the mitre plane that
// bisects their chords.
// Stations are arc length along that polyline, so a plate at station s is s metres of
// centreline from the girder start.
#include <Eigen/Geometry>
#include <vector>

#include "core/sim/sim_config.h"

namespace tunnelmap::sim {

struct SimJoint {
  double station = 0.0;
  Eigen::Vector3d point = Eigen::Vector3d::Zero();   // alignment point (local (s, 0, zc))
  Eigen::Vector3d normal = Eigen::Vector3d::UnitX(); // mitre plane normal, to larger stations
  Eigen::Vector3d up = Eigen::Vector3d::UnitZ();     // in-plane "up" (mean of both frames)
  Eigen::Vector3d left = Eigen::Vector3d::UnitY();   // up x normal
};

class SimAlignment {
 public:
  SimAlignment() = default;
  // `joints`: stations that must be joints (plates); `lo`..`hi`: the stretch to cover.
  SimAlignment(const SimConfig& config, std::vector<double> joints, double lo, double hi);

  bool straight() const { return straight_; }
  int compartment_count() const { return static_cast<int>(frames_.size()); }
  // Compartment k lies between joints k-1 and k (the first and last are unbounded).
  const std::vector<SimJoint>& joints() const { return joints_; }
  const Eigen::Isometry3d& world_from_local(int k) const { return frames_[k]; }
  const Eigen::Isometry3d& local_from_world(int k) const { return inverse_[k]; }
  int compartment_at_station(double s) const;             // a joint's station: the one after
  int compartment_containing(const Eigen::Vector3d& world) const;
  // Local (station, y, z) -> world, in the compartment of that station.
  Eigen::Vector3d to_world(const Eigen::Vector3d& local) const;
  Eigen::Isometry3d to_world(const Eigen::Isometry3d& local) const;  // pose at its own station
  // Girder axis direction (unit, to larger stations) in the compartment of that station.
  Eigen::Vector3d axis_at(double s) const;
  double reference_z() const { return zc_; }

 private:
  double heading(double h) const;              // plan direction at horizontal length h, rad
  Eigen::Vector2d plan(double h) const;        // plan position at horizontal length h
  Eigen::Vector3d curve(double h) const;       // alignment at horizontal length h
  Eigen::Vector3d curve_dir(double h) const;   // d curve / dh
  double chord_to(double h_a, double length, double sign) const;

  bool straight_ = true;
  double curvature_ = 0.0, transition_ = 0.0, transition_start_ = 0.0;  // plan
  double gradient_ = 0.0, vertical_curvature_ = 0.0, zc_ = 0.0;         // elevation
  std::vector<SimJoint> joints_;
  std::vector<Eigen::Isometry3d> frames_, inverse_;
};

}  // namespace tunnelmap::sim
