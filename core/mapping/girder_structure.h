#pragma once
// The structure a climbing robot passes through, from the plates across the tunnel that posed
// frames saw: diaphragms (any transverse plate large enough to close most of the cross-section)
// with their manhole openings, the compartments between them, and the centre line of the
// measured cross-sections. Map coordinates: station along the map's axis, lateral (left) and
// vertical (up) from its reference line (core/mapping/station_map.h).
#include <Eigen/Core>
#include <cmath>
#include <optional>
#include <string>
#include <vector>

namespace tunnelmap {

struct StationMap;

// One transverse plate as one frame saw it. `samples` and `rim` are in map coordinates
// (station, lateral, vertical); `weights` are the samples' pixel counts.
struct PlateView {
  int frame = 0;
  std::vector<Eigen::Vector3d> samples;
  std::vector<double> weights;
  std::vector<Eigen::Vector3d> rim;  // points on the edge of an opening in it
  bool checked = true;  // false: its frame's pose is one nothing checks (placed by that pose alone)
};

struct Manhole {
  Eigen::Vector3d center = Eigen::Vector3d::Zero();  // world frame
  double lateral_m = 0.0, vertical_m = 0.0;          // centre, map coordinates
  double width_m = 0.0, height_m = 0.0;
  std::string shape;          // "ellipse" or "rounded_rectangle"
  double corner_radius_m = 0.0;  // rounded rectangle only
  // From the opening's edge to the left, right, top and bottom wall (NaN: wall not measured).
  double clearance_m[4] = {NAN, NAN, NAN, NAN};
  double fit_rms_mm = 0.0;    // median distance of the rim points from the fitted outline
  int rim_points = 0;
};

struct Diaphragm {
  // "diaphragm", or "end_wall": closed across the girder where its views saw it, and nothing was
  // measured beyond it (the girder ends there for the robot).
  std::string kind = "diaphragm";
  double station_m = 0.0;
  Eigen::Vector3d point = Eigen::Vector3d::Zero();    // world: the centre line at the plate
  Eigen::Vector3d normal = Eigen::Vector3d::UnitX();  // world frame, along the axis
  int seen_by_frames = 0;
  std::vector<int> frames;  // the frames that saw it, in order
  double area_m2 = 0.0;  // plate area seen: 5 cm cells, half a cell off per side with no covered neighbour
  bool closed = false;  // its views covered the section but for less than a manhole: no opening
  std::optional<Manhole> manhole;
  std::string manhole_reason;  // why there is no manhole
};

// The stretch between two plates (or between a plate and the end of the observed extent).
struct Compartment {
  double from_m = 0.0, to_m = 0.0;
  double width_m = NAN, height_m = NAN;  // NaN: not measured in it
  bool closed_from = false, closed_to = false;  // the end is a plate
  int stations_measured = 0;
};

struct CentrelinePoint {
  double station_m = 0.0;
  Eigen::Vector3d point = Eigen::Vector3d::Zero();  // world frame
  std::string source;  // "measured" (both wall pairs at the station), "context", "reference"
};

struct GirderStructureOptions {
  double plate_gap_m = 0.12;         // views of plates closer than this along the axis are one
  double min_plate_fraction = 0.3;   // a plate closes at least this part of the cross-section
  // ... or this much, where the cross-section is unknown; or this much inside both sections
  // beside it, where the frames saw it only in part (through another plate's opening)
  double min_plate_area_m2 = 0.10;
  double cell_m = 0.05;              // area cells
  int min_rim_points = 40;
  int min_rim_directions = 7;        // of 8 around the centre, each with a few rim points
  double max_fit_mm = 12.0;          // median distance of the rim from the outline
  double view_shift_sigma_m = 0.02;  // how far a frame's pose error may move its view of a plate (0: none)
  double compartment_margin_m = 0.2; // stations this close to a plate do not measure the box
  // A plate whose views leave less than this of the box inside the sections beside it uncovered
  // is closed: smaller than any manhole a person or robot climbs through (about 0.3 x 0.4 m).
  double max_closed_gap_m2 = 0.05;
};

// A face as large as a plate that only frames whose poses nothing checks saw: a pose off by
// metres would put a plate where there is none, so it is not mapped, and said.
struct UncheckedPlate {
  double station_m = 0.0;
  std::vector<int> frames;
};

// A plate only views near the end of the depth range saw: the range cut drops its farthest
// pixels first, which places it too near, so it is not mapped, and said.
struct PlateBeyondRange {
  double station_m = 0.0;  // as those views place it: too near, by up to a few centimetres
  std::vector<int> frames;
};

struct GirderStructure {
  std::vector<Diaphragm> diaphragms;
  std::vector<UncheckedPlate> unchecked_plates;
  std::vector<PlateBeyondRange> plates_beyond_range;
  std::vector<Compartment> compartments;
  std::vector<CentrelinePoint> centreline;
};

// Whether one view's samples lie on a plane within `max_angle_deg` of square to the map's axis
// (their least spread direction within that angle of the station direction); false for fewer
// than three samples.
bool view_lies_across_axis(const PlateView& view, double max_angle_deg);

// The stations of the plates across the girder that frames saw (views grouped along the axis,
// each group at least `min_plate_area_m2` and seen by at least one view that is `checked`),
// ascending: what a section's joint may hide behind, known before the sections are.
std::vector<double> transverse_plate_stations(const std::vector<PlateView>& views,
                                              const GirderStructureOptions& options = {});

// `map` must be finished (stations, sections, frame). Plates are in station order.
// `range_cut_views`: views the cloud's range cut placed too near (plates_cut_by_range); they
// map no plate, and a plate only they saw goes to `plates_beyond_range`.
GirderStructure build_girder_structure(const StationMap& map, const std::vector<PlateView>& views,
                                       const GirderStructureOptions& options = {},
                                       const std::vector<PlateView>& range_cut_views = {});

}  // namespace tunnelmap
