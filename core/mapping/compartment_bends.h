#pragma once
// The girder's turn tied from one compartment to the next. A girder's alignment is straights,
// circular arcs and the transition curves between them (clothoids): its curvature is constant
// or changes evenly over many compartments, so its direction is, piece by piece, a quadratic
// in the station. Its walls may curve, or run straight and kink, at the plates or anywhere
// between (a chorded girder's splices); either way the mean direction of a compartment's walls
// is the girder's direction near the compartment's middle. So of four neighbouring
// compartments, the second one's mean wall direction lies on the quadratic through the other
// three's. Three compartments say more (an even turn: the middle one's direction between the
// outer two's) but are wrong along a transition: on a 150 m curve reached over 57 m, they put
// the middle compartment 0.05 degrees off where the girder turns, five times the tie's default
// tolerance. So the even turn is tied only where the map, tied to the quadratic, shows none of
// that: over a straight or a circular arc. Ties of bands either side of one plate cannot say
// as much: a chorded girder may turn at the plate itself.
#include <vector>

#include "core/solvers/pose_graph.h"

namespace tunnelmap {

// One band of one kind of wall surface (a wall and its zone) and its plane landmark.
struct WallBand {
  int kind = 0;
  double from_m = 0.0, to_m = 0.0;  // along the walk (core/mapping/wall_band_grid.h)
  int plane = 0;
};

// Per kind, each compartment's whole bands, at their mean station (a band with a plate inside is
// two surfaces, not a plane, and takes no part: the wall band grid cuts a band at its first
// plate only); every four neighbouring compartments that have bands are tied to within
// `sigma_rad` (the second one's mean direction against the quadratic through the others').
// Compartments lie between the plates at `plate_stations_m` (along the walk, as the bands);
// the stretches before the first and past the last plate are open-ended and take no part.
std::vector<PlaneBend> compartment_bends(const std::vector<WallBand>& bands, std::vector<double> plate_stations_m,
                                         double sigma_rad);

// An even turn of three neighbouring compartments: the middle one's mean direction between the
// outer two's, in proportion to the distances between them. `compartment` is the middle one's
// place along the girder (the number of plates before it).
struct EvenTurn {
  int compartment = 0;
  PlaneBend tie;
};

// Per kind, in order along the girder: every three neighbouring compartments' even turn, within
// `sigma_rad`.
std::vector<std::vector<EvenTurn>> compartment_even_turns(const std::vector<WallBand>& bands,
                                                          std::vector<double> plate_stations_m, double sigma_rad);

// The even turns whose neighbourhood (the turns of one kind whose middle compartment lies at
// most two compartments from this one's) departs from an even turn at `planes` (bend_departure,
// core/solvers/pose_graph.h) by less than the tie's tolerance on average: where the girder's
// curvature does not change. Along a transition curve the departures share one sign and add
// up; the odometry's wander, once the quadratic ties hold it, leaves departures of a few
// thousandths of a degree that change sign. The neighbourhood is counted in compartments, not
// in turns: the turns either side of a compartment whose walls no frame saw lie four
// compartments apart or more, so it never reaches across one.
std::vector<PlaneBend> even_turns_where_the_map_turns_evenly(const std::vector<std::vector<EvenTurn>>& turns,
                                                             const std::vector<GraphPlane>& planes);

}  // namespace tunnelmap
