#pragma once
// StationMap: the whole tunnel as a profile along its axis. Every posed frame's wall points are
// binned by station (distance along the axis) in the world frame; each station gets the width
// and height its points measure, or, where a wall was out of view, the value the neighbouring
// stations (the sequence's context) or the design give. Stations that agree form sections of
// constant cross-section; a change several frames agree on starts a new section. See
// docs/tunnel-map.md.
#include <Eigen/Geometry>
#include <cmath>
#include <optional>
#include <string>
#include <vector>

#include "core/mapping/centreline.h"
#include "core/mapping/girder_structure.h"
#include "core/mapping/multi_scan_map.h"
#include "core/mapping/map_options.h"  // StationMapOptions
#include "core/tunnel/tunnel_map.h"
#include "core/util/stage_timer.h"

namespace tunnelmap {

struct Station {
  double station_m = 0.0;          // centre of the station's bin along the axis
  double width_m = 0.0, height_m = 0.0;  // meaningful when the source is not Unseen
  DimensionSource width_source = DimensionSource::Unseen;
  DimensionSource height_source = DimensionSource::Unseen;
  int frames = 0;                  // frames whose points measured this station
  std::optional<double> width_dev_mm, height_dev_mm;  // against the design
  bool out_of_tolerance = false;
  // Wall positions: distance from the map's centre line to each wall's outermost surface
  // (left, right, top, bottom); NaN where the wall was not measured here.
  double wall_m[4] = {NAN, NAN, NAN, NAN};
};

// A stretch of constant cross-section.
struct Section {
  double from_m = 0.0, to_m = 0.0;
  double width_m = 0.0, height_m = 0.0;
  int frames = 0;  // frames that measured any of its stations
  // Its joint with the section before (none for the first): seen whole by frames, or placed in
  // the middle of a stretch a plate hid; how far from `from_m` the joint may lie.
  bool joint_seen = true;
  double joint_uncertainty_m = 0.0;
};

struct StationMap {
  bool ok = false;
  std::string status;  // "ok", "no_poses", "no_detection"
  std::string reason;
  // World frame. The reference line's frame at station 0: `up` is perpendicular to `axis`.
  Eigen::Vector3d origin = Eigen::Vector3d::Zero();
  Eigen::Vector3d axis = Eigen::Vector3d::UnitX();
  Eigen::Vector3d up = Eigen::Vector3d::UnitZ();
  // The reference line that stations are measured along (core/mapping/centreline.h): fitted to
  // the girder's course; when straight, station s is at origin + s * axis.
  Centreline line;
  StationMapOptions options;
  std::vector<Station> stations;   // over the observed extent, in order
  std::vector<Section> sections;   // in order along the axis
  std::vector<PoseGroupStatus> poses;
  // World-frame maps (walls, zones) of the sections, in order: one per section along a straight
  // line, pieces of it along a fitted one.
  std::vector<TunnelMap> section_maps;
  GirderStructure girder;          // diaphragms, manholes, compartments, centre line
  int frames = 0, frames_used = 0;
  StageTimings timings_ms;         // "map" (total), per frame: see frame_ms

  // Stations out of tolerance (convenience for reports).
  std::vector<const Station*> out_of_tolerance() const;
  // Station of a world point (where the line's perpendicular plane passes through it).
  double station_of(const Eigen::Vector3d& world) const {
    return line.is_straight() ? axis.dot(world - origin) : line.locate(world).station_m;
  }
  // The line's frame at station s, and a point given in it (lateral to the left, vertical up).
  CentrelineFrame frame_at(double s) const {
    return line.is_straight() ? CentrelineFrame{s, origin + s * axis, axis, up} : line.frame_at(s);
  }
  Eigen::Vector3d to_world(double s, double lateral, double vertical) const {
    const CentrelineFrame f = frame_at(s);
    return f.point + lateral * f.left() + vertical * f.up;
  }
};

}  // namespace tunnelmap
