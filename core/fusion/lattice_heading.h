#pragma once
// The sparse volume's lattice turned about the vertical to the girder's heading, so that its
// walls lie along lattice planes: a wall at 45 deg to the lattice crosses ~40 % more blocks and
// lattice edges, and a wall a few hundredths of a degree off sweeps through every place within
// a block over 100 m, which costs ~25 % more blocks than a wall that keeps its place
// (docs/fusion.md). The heading is fitted once, before the first integration.
#include <Eigen/Geometry>
#include <vector>

#include "core/tunnel/tunnel_map.h"

namespace tunnelmap {

// A detected frame's map (camera frame) and the pose it is fused with.
struct PosedMap {
  const TunnelMap* map = nullptr;
  Eigen::Isometry3d camera_to_world = Eigen::Isometry3d::Identity();
};

enum class HeadingSource { World, CentreLine, MergedAxis };
const char* heading_source_name(HeadingSource s);

struct LatticeHeading {
  Eigen::Matrix3d lattice_to_world = Eigen::Matrix3d::Identity();
  double yaw_deg = 0.0;  // of the lattice's x about the world vertical
  HeadingSource source = HeadingSource::World;
  // The lattice's origin moved by this along its own axes (each less than a block), fitted
  // from the depth data (core/fusion/lattice_offset.h); zero when not fitted.
  Eigen::Vector3d offset_m = Eigen::Vector3d::Zero();
  double offset_fit_ms = 0.0;  // what the fit cost
  // Where the lattice's origin lies in the world.
  Eigen::Vector3d origin() const { return lattice_to_world * offset_m; }
};

// Frames' centre-line points further apart than this along the girder give the heading
// by a line fit through them (a long baseline: hundredths of a degree over a few metres).
inline constexpr double kCentreLineBaselineM = 5.0;

// The heading of the line fitted through the detected frames' centre points (the middle of
// each frame's visible stretch of the centre line, in the world) when they span at least
// kCentreLineBaselineM; otherwise the merged map's averaged axis, kept to the world's axes
// within 1 deg (one frame's axis is good to tenths of a degree). A fitted heading within
// 0.01 deg of a world axis keeps the world's axes (source still says where the heading came
// from). Without a detected frame, or when the world
// is not z-up, the world's axes.
LatticeHeading lattice_heading(const std::vector<PosedMap>& frames, const TunnelMap& merged,
                               const Eigen::Vector3d& world_up);

}  // namespace tunnelmap
