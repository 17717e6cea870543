#pragma once
// StationMapBuilder: builds the StationMap frame by frame, in frame order, and is the context of
// a posed sequence: each frame is compared with the map at the stations it sees, and a wall it
// did not see is inferred from the map there (or from the design).
#include <Eigen/Geometry>
#include <array>
#include <cmath>
#include <map>
#include <optional>
#include <vector>

#include "core/mapping/centreline.h"
#include "core/mapping/frame_walls.h"
#include "core/mapping/section_evidence.h"
#include "core/mapping/station_map.h"
#include "core/pipeline/pipeline.h"

namespace tunnelmap {

// The options the parameter table gives (map.*, tunnel.design_*, zone gap and symmetric step).
StationMapOptions station_map_options(const Parameters& params);

class StationMapBuilder {
 public:
  StationMapBuilder(StationMapOptions options, TunnelOptions tunnel);

  // Stations along this line (arc length, cross-sections perpendicular to it) instead of the
  // first detected frame's axis; before the first frame.
  void follow(Centreline line);

  // One frame, in frame order: its detection without context (camera frame, may be a failure),
  // its compact wall samples (extract_frame_walls of its result) and its camera-to-world pose.
  // Updates `map`: missing walls inferred from the map so far (else the design), and
  // "inconsistent_with_context" when the frame disagrees with several frames before it at the
  // stations it sees. Accepted frames add their wall points to the map; frames that found no
  // cross-section, the plates they face.
  void add_frame(int index, TunnelMap& map, const FrameWalls& walls,
                 const Eigen::Isometry3d& camera_to_world);

  // Frames whose poses nothing checks (frames_nothing_checks): a plate only they saw is not
  // mapped but listed in the girder's `unchecked_plates`. Before their frames are added.
  void set_unchecked_frames(std::vector<int> frames);

  // The map of every frame added so far. `pose_groups[i]`: group of the i-th frame added.
  StationMap finish(const std::vector<int>& pose_groups) const;

  int frames() const { return static_cast<int>(scans_.size()); }

 private:
  // A plane's points within one station, seen by one frame: their mean position outward from the
  // map's centre line (left, right, top or bottom wall), along the map's directions and along
  // the frame's own wall normals (which a rotation error of the frame's pose does not tilt).
  struct Piece {
    int station;
    int wall;
    int frame;
    int points;
    double position_m;
    double own_position_m;
    double range_m;  // mean depth of its points in the frame's camera
  };
  struct WallProfile {  // per station, positions of the four walls (NaN: not measured)
    double wall_m[4];
    int frames;
  };

  using Pieces = std::map<int, std::vector<Piece>>;  // by station

  bool ensure_frame(const TunnelMap& map, const Eigen::Isometry3d& T);
  void frame_pieces(const TunnelMap& m, const FrameWalls& walls, const Eigen::Isometry3d& T,
                    int frame, Pieces& out) const;
  // Per-station wall positions of `pieces`, stations [k0, k1].
  // `own`: along the frame's own wall normals (a single frame's pieces).
  // A wall whose only zone there is its middle plate gets the step between its edge band and
  // middle plate that the pieces show elsewhere, else `known_step` (per wall; NaN unknown).
  // `seen_step`, when given, receives the step the pieces show per wall (NaN: none).
  std::vector<WallProfile> profile(const Pieces& pieces, int k0, int k1, bool own = false,
                                   const double* known_step = nullptr, double* seen_step = nullptr) const;
  // A frame's own profile: where the frame did not see both zones of a wall itself, the step
  // the earlier frames saw is the wall's (its layers are the same along the girder).
  std::vector<WallProfile> own_profile(const Pieces& own, double* seen_step = nullptr) const;
  // The frame's own measurement along the axis: split where its cross-section changes (a
  // frame that sees two sections measures each part separately), each dimension taken where
  // both walls of its pair were seen at the same station (a tilt of the wall normals then
  // cannot become a size error between walls seen at different distances). Sets m.parts and
  // the measured width/height to the part nearest the camera.
  void own_parts(TunnelMap& m, const Pieces& own, int camera_station) const;
  // The context step of add_frame: check against the map so far, then infer missing walls.
  void apply_context(TunnelMap& map, const Pieces& own, const Eigen::Isometry3d& T) const;

  StationMapOptions options_;
  TunnelOptions tunnel_;
  bool have_frame_ = false, have_origin_ = false;
  Eigen::Vector3d origin_ = Eigen::Vector3d::Zero(), axis_ = Eigen::Vector3d::UnitX(),
                  up_ = Eigen::Vector3d::UnitZ(), first_view_ = Eigen::Vector3d::UnitX();
  Centreline line_;  // stations are measured along it
  bool have_line_ = false;  // given by follow(); else the first detected frame's axis
  // A frame's own cross-section at one station: both walls of a pair measured by that frame
  // along its own wall normals, so that no error of its pose enters (NaN: pair not seen).
  struct FrameDims {
    int frame;
    double width_m, height_m;
    double range_m;  // mean depth of the frame's pieces at the station
  };
  void record_frame_dims(int frame, const Pieces& own);
  // Per wall, the edge steps that the latest frames saw in their own views, and their median
  // (NaN: none yet). The latest only: a section may build its walls of other plates.
  static constexpr std::size_t kRecentEdgeSteps = 64;
  std::array<std::vector<double>, 4> own_edge_steps_;
  double known_edge_step_[4] = {NAN, NAN, NAN, NAN};
  // The station's width and height over the frames that measured them there: the median of the
  // near views (map.near_range_m) where there are any, else of all. NaN where no frame did.
  struct Dims {
    double width_m, height_m;
    int width_frames, height_frames;
  };
  Dims station_dims(int station) const;
  // Every accepted frame's own sizes, stations counted from `first_station`.
  std::vector<FrameStationSize> frame_views(int first_station) const;

  // The plates across the axis in a frame's samples, in map coordinates. A detected frame's
  // samples lie across its own axis; a frame without a cross-section has no axis to trust, so
  // each view must also lie across the map's.
  enum class PlateCheck { AcrossOwnAxis, AcrossMapAxis };
  void add_plate_views(int frame, const FrameWalls& walls, const Eigen::Isometry3d& T, PlateCheck check);

  Pieces pieces_;                 // accepted frames' pieces
  std::vector<PlateView> plates_; // views of plates across the axis (accepted and undetected frames)
  std::vector<PlateView> range_cut_plates_;  // such views the cloud's range cut placed too near
  std::map<int, std::vector<FrameDims>> frame_dims_;  // by station, accepted frames
  std::vector<ScanInput> scans_;  // every frame's map (camera frame) and pose
  std::vector<int> unchecked_frames_;  // sorted
};

}  // namespace tunnelmap
