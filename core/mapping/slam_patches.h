#pragma once
// What one frame contributes to localisation against the structure: its wall points cut into
// bands along the girder (one patch per wall, band and zone) and its plates across the girder
// (one patch per plate), each reduced to the moments the pose graph needs.
#include <Eigen/Core>
#include <vector>

#include "core/mapping/frame_walls.h"
#include "core/mapping/slam_options.h"
#include "core/mapping/wall_band_grid.h"
#include "core/tunnel/tunnel_map.h"

namespace tunnelmap {

struct FramePatch {
  bool plate = false;     // across the girder; else a wall band
  int wall = 0;           // 0-3 (WallClass) for a band
  long band = 0;          // band along the girder (walls; core/mapping/wall_band_grid.h)
  double station_m = 0.0; // the centroid's position along the girder (odometry)
  Eigen::Vector3d centroid = Eigen::Vector3d::Zero();  // camera frame
  Eigen::Matrix3d spread = Eigen::Matrix3d::Zero();    // in-plane square-root scatter
  Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();   // camera frame: walls outward, plates forward
  double sigma_m = 0.0;
  double pixel_sigma_m = 0.0;  // one pixel's depth noise: the sensor model or the patch's scatter
  // Which zone of its wall the frame took a band patch for: the middle plate (inside the
  // outer surface), the outer surface (only when the frame saw the middle plate beside it:
  // alone, a middle plate looks like an outer surface), or unknown.
  enum class Zone { Unknown, Outer, Inner } zone = Zone::Unknown;
  int points = 0;
};

// `camera_station_m`: the camera's position along the girder; `axis_cam`: the girder's axis in
// the camera frame, pointing forward.
//
// The frame's plates. A frame that found no cross-section (`map.detected` false) chose its
// plates by its map's rough axis, not the girder's: a plate of it is kept only when its own
// normal lies within kTransverseMaxAngleDeg of `axis_cam`.
std::vector<FramePatch> frame_plate_patches(const TunnelMap& map, const FrameWalls& walls, double camera_station_m,
                                            const Eigen::Vector3d& axis_cam, const SlamOptions& options);

// The planes across the axis (kTransverseSample) of `walls` whose view the cloud's range cut:
// depth beyond `cloud_max_range_m` is dropped pixel by pixel, so such a plate keeps only the
// pixels its noise brought nearer and comes out too near. A view is cut unless its farthest
// block lies kRangeMarginSigmas of one pixel's noise (its scatter, or `point_sigma_m` at 1 m
// growing with z^2, whichever is larger) inside the range. Plane ids, ascending.
std::vector<int> plates_cut_by_range(const FrameWalls& walls, double cloud_max_range_m, double point_sigma_m);

// The frame's walls, cut into the bands of `grid`. A wall's zones (edge band, middle plate) are
// patches of their own: each is a layer of the wall's landmark (StructureSlam).
std::vector<FramePatch> frame_wall_patches(const TunnelMap& map, const FrameWalls& walls, double camera_station_m,
                                           const Eigen::Vector3d& axis_cam, const SlamOptions& options,
                                           const WallBandGrid& grid);

}  // namespace tunnelmap
