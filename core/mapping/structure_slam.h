#pragma once
// Localisation and mapping against the girder's structure: one pose graph (core/solvers) over
// the pose groups of a posed sequence, with odometry factors between consecutive groups and
// plane landmarks for what the camera sees of the structure: each wall, one plane per band of
// the girder's length (cut at the plates: core/mapping/wall_band_grid.h), and each plate across
// it (diaphragm, step face, end wall).
//
// Landmarks are told apart by their position along the girder as the odometry measures it
// (arc length of the walk): over the few metres in which one plate is seen, odometry drifts by
// millimetres, far less than the metres between plates, so a repeated plate is never taken for
// its neighbour. Directions no landmark constrains (along the girder between plates) are left
// to odometry and reported as degenerate.
//
// Two modes share the graph: add_frame() re-estimates a window of the latest pose groups
// (bounded time per frame, for a robot on the move), finish() optimises all of them. Both keep
// the given poses unless the structure shows, beyond its noise, that they are wrong
// (core/solvers/correction_evidence.h).
#include <Eigen/Geometry>
#include <map>
#include <optional>
#include <utility>
#include <vector>

#include "core/mapping/compartment_bends.h"
#include "core/mapping/frame_walls.h"
#include "core/mapping/plate_tracks.h"
#include "core/mapping/pose_refinement.h"
#include "core/mapping/section_sizes.h"
#include "core/mapping/slam_options.h"
#include "core/mapping/slam_patches.h"
#include "core/mapping/wall_band_grid.h"
#include "core/solvers/pose_graph.h"
#include "core/tunnel/tunnel_map.h"

namespace tunnelmap {

class StructureSlam {
 public:
  explicit StructureSlam(SlamOptions options = SlamOptions());

  // Frames in order. `pose`: its odometry / forward-kinematics camera-to-world pose; `group`:
  // its pose group (a group's frames share one correction). Returns the frame's pose as now
  // estimated (after the window's optimisation).
  // `gravity`: where things fall in the camera's frame (unit), when an IMU tells it.
  Eigen::Isometry3d add_frame(const TunnelMap& map, const FrameWalls& walls, const Eigen::Isometry3d& pose,
                              int group, const std::optional<Eigen::Vector3d>& gravity = std::nullopt);
  // Optimises every pose group and landmark; the corrections and the refined pose per frame.
  PoseRefinement finish();

  // Each pose group's station: arc length of the walk as the odometry gives it, along each
  // group's own view of the girder's axis (so it follows a curving girder).
  std::vector<double> group_stations_m() const;
  double last_frame_ms() const { return last_frame_ms_; }  // add_frame's time, window included
  int plate_landmarks() const { return plates_.size(); }
  int landmarks() const { return static_cast<int>(graph_.planes.size()); }

 private:
  struct Group {
    int id = 0;
    Eigen::Isometry3d odometry = Eigen::Isometry3d::Identity();  // its first frame's pose as given
    std::vector<int> frames;
    std::vector<Eigen::Isometry3d> offsets;  // per frame: odometry^-1 * frame's pose
    double station_m = 0.0;                  // along the walk (odometry)
    Eigen::Vector3d axis = Eigen::Vector3d::UnitZ(), up = Eigen::Vector3d::UnitY();  // world
    bool has_axis = false;
    int samples = 0;
  };

  void start_group(const Eigen::Isometry3d& pose, int id);
  void split_by_information(const PoseInformation& H, const Group& group, PoseCorrection& c) const;
  void add_patches(const TunnelMap& map, const FrameWalls& walls, const Eigen::Isometry3d& offset);
  int plate_landmark(const FramePatch& patch, const Eigen::Isometry3d& camera_to_world, double camera_station_m);
  // The layers (zones) of wall landmarks that the patches of a frame's two opposite walls land
  // on: the shift along the walls' normals that lands most of them on known layers (the frame's
  // own pose error, opposite on the two walls), then each patch on the nearest layer within
  // reach or on a new one. Per patch, its plane.
  std::vector<int> wall_layers(const std::vector<const FramePatch*>& patches, const Eigen::Isometry3d& camera_to_world);
  int add_plane(const Eigen::Vector3d& normal, double offset);
  void solve_window();
  PoseGraphSolution solve_at_given_poses(PoseGraph given) const;
  PoseGraphSolution solve_window_at_given_poses(PoseGraph window, int from, int free_from,
                                                const PoseGraphOptions& options) const;
  PoseCorrection correction(std::size_t g) const;

  SlamOptions options_;
  std::vector<Group> groups_;
  bool walk_has_axis_ = false;  // a detected frame has given the girder's axis
  PoseGraph graph_;  // poses = groups' current estimates (their first frame's camera)
  std::map<std::pair<int, long>, std::vector<int>> wall_landmarks_;  // (wall, band) -> layers
  std::vector<FramePatch::Zone> layer_zone_;  // per plane: the wall zone its views took it for
  struct ZoneLayer {
    int plane;
    Eigen::Vector3d point;  // world, where it was first seen
    double station_m;       // of that point, along the walk
  };
  // (wall * 2 + 1 for the middle plate, band) -> that zone's layer there.
  using ZoneLayers = std::map<std::pair<int, long>, ZoneLayer>;
  ZoneLayers zone_layers_;
  void continue_wall(const FramePatch& patch, int plane, const Eigen::Vector3d& point);
  std::vector<PlaneBend> turn_ties() const;
  std::vector<std::vector<EvenTurn>> even_turns() const;
  std::vector<WallBand> wall_bands() const;
  PoseGraphSolution with_even_turns(const PoseGraphSolution& tied) const;
  Eigen::Vector3d wall_at_plate(const ZoneLayer& a, const ZoneLayer& b, double plate_m) const;
  double plate_between(const ZoneLayer& a, const ZoneLayer& b) const;
  // Per continuity tie (graph_.continuities, in order): its wall's dimension (0 width, 1
  // height), the plate it crosses (NaN: none tracked between its two points) and its bands
  // before and after it.
  struct TieCrossing {
    int dimension;
    double plate_m;
    long before, after;
  };
  std::vector<TieCrossing> tie_crossings_;
  SectionSizes section_sizes_;
  void free_ties_across_section_changes();
  PlateTracks plates_;
  // The wall bands, cut at the plates (core/mapping/wall_band_grid.h).
  void cut_bands_at_plates();
  std::vector<long> cut_cells_;  // per plate: the cell of the band it cuts
  std::vector<double> cuts_m_;   // per plate: where it cuts
  WallBandGrid bands_;
  void share_systematic_error(int pose, int plane, double sigma_m);
  struct SharedView {
    int frames = 0, last_frame = -1;
    std::vector<std::size_t> patches;  // indices into graph_.patches
  };
  std::map<std::pair<int, int>, SharedView> shared_views_;  // (pose group, plane)
  std::vector<double> base_sigma_m_;                        // per patch, before sharing
  int frames_ = 0;
  double frames_ms_ = 0.0, last_frame_ms_ = 0.0;
};

}  // namespace tunnelmap
