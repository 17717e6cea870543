#pragma once
// Whole-girder helpers of the simulator: where the diaphragms are and what passes through
// their manhole openings (docs/simulator.md#long-girders).
#include <optional>
#include <vector>

#include "core/sim/sim_config.h"

namespace tunnelmap::sim {

// World X of the manhole plate (the plate the approach frames stand in front of): the distance
// to the manhole, else the farthest of the manhole distances; none without either.
std::optional<double> manhole_plate_x(const SimConfig& config);

// Stations of the diaphragms: diaphragm_x_m in the order given; with diaphragm_spacing_m also
// S, 2S, ... short of girder_length_m, and then the union is sorted (duplicates within 1 mm
// dropped). None stands within kMinPlateGapM of the manhole plate: that plate is the diaphragm
// there.
std::vector<double> diaphragm_stations(const SimConfig& config);

// Two transverse plates a few centimetres apart are built nowhere (the gap could be neither
// welded nor inspected); a diaphragm that would stand so near the manhole plate is left out.
constexpr double kMinPlateGapM = 0.1;

// A point of a plate, (dy, dz) from the opening's centre across and up the section, is in the
// manhole opening (strictly inside its ellipse or rounded rectangle).
bool in_opening(const SimConfig& config, double dy, double dz);

// Centre height (z above the floor) of the opening in a section of height H.
inline double opening_centre_z(const SimConfig& config, double section_height_m) {
  return config.manhole_centre_z_rel * section_height_m;
}

// Weight of the opening's centre in the camera position of a walk through the openings at
// `distance_m` from the nearest plate: 1 within 0.5 m, 0 from 1.5 m, smoothstep between.
double opening_weight(double distance_m);

// Which of a walk's stops (stations `stop_x`, ascending) look back (SimWalk::look_back): in each
// compartment that starts at a plate of `plates_x` (ascending) and ends at the next plate or
// at the last stop, the stop nearest its middle. A compartment no stop stands in has none, nor
// has one shorter than kMinLookBackRoomM (the gap between a diaphragm and a plate just behind
// it: a camera there sees the plate a hand's width away).
constexpr double kMinLookBackRoomM = 1.0;
std::vector<bool> look_back_stops(const std::vector<double>& stop_x, const std::vector<double>& plates_x);

}  // namespace tunnelmap::sim
