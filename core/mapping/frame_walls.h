#pragma once
// A frame's wall points in compact form: per plane, the mean of its pixels in each 8 x 8 pixel
// block (camera frame), with the wall it measures. Small enough to keep for every frame of a
// sequence (a few thousand samples), and enough to rebuild the station map, or to align the
// frame with the map, under other camera poses without the frame's images.
#include <Eigen/Core>
#include <cstdint>
#include <vector>

#include "core/pipeline/pipeline.h"

namespace tunnelmap {

// Walls 0-3 are WallClass Left..Bottom; kTransverseSample marks a plane across the tunnel axis
// (a manhole plate, the step between two sections).
constexpr std::uint8_t kTransverseSample = 4;
// A plane is across the axis when its normal lies within this angle of it.
constexpr double kTransverseMaxAngleDeg = 20.0;

struct WallSample {
  Eigen::Vector3f point = Eigen::Vector3f::Zero();  // mean of the block's pixels, camera frame
  int points = 0;
  int plane = 0;               // plane id (label) in the frame
  std::uint8_t wall = 0;       // 0-3: measured wall; kTransverseSample
  float inset_m = 0.0f;        // how far the plane lies inside its wall's outer surface there
                               // (the middle plate: its thickness; an edge band: 0)
  bool on_surface = true;      // the inset is known (false: a plane of no zone of the wall)
  bool inside = false;         // deeper inside the wall's outer surface than any zone lies:
                               // not the wall (a plate opening's edge seen from afar, a rib)
  std::uint8_t part = 0;       // the frame's cross-section part it lies in (0: the first or
                               // only one); zones are layers of one part's wall
};

// A point on the edge of an opening in a plane across the axis (a manhole's rim): the plate's
// last pixel before the view passes through the opening to something farther, moved along its
// ray onto the plate's fitted plane (camera frame).
struct RimPoint {
  Eigen::Vector3f point = Eigen::Vector3f::Zero();
  int plane = 0;  // plane id (label) of the plate
};

struct FrameWalls {
  std::vector<WallSample> samples;
  std::vector<RimPoint> rims;  // of the planes whose samples are kTransverseSample
};

struct FrameWallsOptions {
  int block_px = 8;
  int min_transverse_points = 300;  // a plane across the axis needs this many to be a face
  // Insets are found part by part: the frame's stations (`station_m` along its own axis) are
  // split where its cross-section changes (`section_change_m` over `min_section_stations`),
  // and within a part the planes' positions on a wall are clustered (`zone_gap_m`); the
  // outermost cluster with `min_part_points` is the outer surface, and planes up to
  // `max_inset_m` inside it are its zones (a plate). Planes further in belong to no zone.
  double station_m = 0.10;
  double section_change_m = 0.015;
  int min_section_stations = 4;
  // Stations beyond this along the axis follow the last part (far, grazing views through coarse
  // depth steps do not decide a split). A joint 1.3-2.5 m past a plate is seen whole only from
  // before the plate, 2.5-4 m away (past it, a camera in the manhole sees no floor for ~1.3 m);
  // at 3 m such a roof step was never split off, and its lower roof, deeper than any zone,
  // dropped as "inside". 4 m is also the default depth to which the pose graph reads walls
  // (slam.max_wall_depth_m).
  double max_split_distance_m = 4.0;
  double zone_gap_m = 0.005;
  int min_zone_points = 60;   // per station, to see where the cross-section changes
  int min_part_points = 300;  // per part, for the outer surface (the detector's zone support)
  double max_inset_m = 0.03;
  // A plate pixel is on an opening's rim when, within `rim_search_px` past the plate's edge,
  // the view lands at least `see_through_m` farther (through the opening, not on a wall).
  // Past the labels, pixels within `rim_on_plate_m` of the plate's plane are still the plate.
  double see_through_m = 0.15;
  double rim_on_plate_m = 0.01;
  int rim_search_px = 6;
  int max_rim_points_per_plate = 800;
  // Rims farther than this are left to nearer views: there a pixel spans 9 mm (z / f at VGA)
  // and the plate's depth noise is several times rim_on_plate_m, so the edge is found late.
  double max_rim_range_m = 5.0;
};

// The samples of `r` (its map must come from r.planes). Planes of walls the frame measured,
// edge-on planes excepted, and planes across the axis of at least min_transverse_points. A
// frame that found no cross-section gives its planes across its map's rough axis (the camera's
// forward direction levelled by the up it was given, or the walls' fitted axis) alone: too near
// a plate to see the walls beside it, it still sees the plate, which tells where it stands
// along the girder (whoever uses them checks them against the girder's axis), and the rims of
// the openings in them (often the only view of a plate just behind another, through its manhole).
void extract_frame_walls(const FrameResult& r, FrameWalls& out,
                         const FrameWallsOptions& options = FrameWallsOptions());

}  // namespace tunnelmap
