#pragma once
// TunnelMap: the fourth stage, the rectangular tunnel template fitted to the planes.
#include <Eigen/Core>
#include <array>
#include <string>
#include <vector>

#include "core/tunnel/tunnel_status.h"
#include "core/util/stage_timer.h"

namespace tunnelmap {

enum class WallClass { Left = 0, Right = 1, Top = 2, Bottom = 3, Unassigned = 4 };
const char* wall_class_name(WallClass c);  // "left", "right", "top", "bottom", "unassigned"

enum class ZoneKind { Forbidden, Traversable };

// Where a wall's position, or a width or height, comes from: measured in this frame's points,
// inferred from the sequence's context (the map along the tunnel), from the design prior, or
// not known at all. Names: "measured", "context", "design", "unseen".
enum class DimensionSource { Unseen = 0, Measured, Context, Design };
const char* dimension_source_name(DimensionSource s);

// A rectangle lying on a wall: `corners` in order, in the frame the map is expressed in.
struct ZoneRect {
  ZoneKind kind = ZoneKind::Traversable;
  std::array<Eigen::Vector3d, 4> corners;
};

struct ZoneCluster {
  double offset_m = 0.0;  // position along the wall normal (wall plane: n.x + offset = 0)
  int planes = 0;
  int points = 0;
};

struct Wall {
  WallClass cls = WallClass::Unassigned;
  bool found = false;  // part of the map: measured, or inferred (see source)
  DimensionSource source = DimensionSource::Unseen;
  Eigen::Vector3d normal = Eigen::Vector3d::Zero();  // unit, pointing into the tunnel
  double offset_m = 0.0;                               // plane: normal.dot(x) + offset_m = 0
  std::vector<ZoneCluster> clusters;                   // zone positions on this wall
  std::vector<ZoneRect> zones;                         // forbidden edge bands + middle plate
  std::array<Eigen::Vector3d, 4> boundary;             // wall rectangle over the visible extent
  // Gaussian statistics of the class's plane normals (added fields).
  int inlier_planes = 0;       // planes of this class kept by the histogram test
  int outlier_planes = 0;      // planes of this class rejected by the histogram test
  double normal_sd_deg = 0.0;  // RMS angle of the inlier normals about their mean
  double symmetric_step_m = 0.0;  // edge step borrowed from the opposite wall (0 = measured)
};

// A stretch of constant cross-section seen by one posed frame, in the station coordinates of
// the sequence's map (core/mapping/station_map.h). NaN where the frame did not measure it.
struct TunnelPart {
  double from_m = 0.0, to_m = 0.0;
  double width_m = 0.0, height_m = 0.0;
};

struct TunnelMap {
  bool detected = false;           // Ok or Partial
  TunnelStatus status = TunnelStatus::NotRun;  // names: status_name()
  std::string reason;              // human-readable detail for the status
  double width_m = 0.0;            // left-right distance (when width_source is not Unseen)
  double height_m = 0.0;           // bottom-top distance (when height_source is not Unseen)
  // "ok": both Measured. "partial": some wall out of view; a dimension it leaves open comes
  // from the context or the design, or stays Unseen.
  DimensionSource width_source = DimensionSource::Unseen;
  DimensionSource height_source = DimensionSource::Unseen;
  Eigen::Vector3d axis_point = Eigen::Vector3d::Zero();  // on the tunnel centre line
  Eigen::Vector3d axis_dir = Eigen::Vector3d::UnitZ();   // unit, along the tunnel
  Eigen::Vector3d up = -Eigen::Vector3d::UnitY();        // unit, towards the roof
  double extent_min_m = 0.0;       // visible axial extent, along axis_dir from axis_point
  double extent_max_m = 0.0;
  std::array<Wall, 4> walls;       // indexed by WallClass (Left..Bottom)
  // Posed frames: what the frame measured, split where the cross-section changes along the
  // tunnel; width_m/height_m are then those of the part nearest the camera. Empty otherwise.
  std::vector<TunnelPart> parts;
  std::vector<WallClass> plane_classes;  // per PlaneSegment (same order), after outliers
  std::vector<bool> plane_outlier;       // per PlaneSegment: rejected by the histogram test
  std::vector<WallClass> plane_candidate_classes;  // per PlaneSegment: class before outliers
  StageTimings timings_ms;

  bool has_width() const { return detected && width_source != DimensionSource::Unseen; }
  bool has_height() const { return detected && height_source != DimensionSource::Unseen; }
  bool width_measured() const { return detected && width_source == DimensionSource::Measured; }
  bool height_measured() const { return detected && height_source == DimensionSource::Measured; }
  const Wall& wall(WallClass c) const { return walls[static_cast<int>(c)]; }
  Wall& wall(WallClass c) { return walls[static_cast<int>(c)]; }
};

}  // namespace tunnelmap
