#pragma once
// The bands a wall is cut into along the girder, one plane landmark each: `band_m` long, and
// cut in two at a plate that lies inside one. Either side of a plate the wall is another
// surface: a chorded girder's walls kink at its diaphragms (1.5 degrees at every plate of a
// 150 m curve with plates 4 m apart), and one plane fitted across the kink is pulled towards
// whichever side the frame saw more of. On a curved girder with exact poses, bands across the
// plates made the corrections look needed (core/solvers/correction_evidence.h) where none was.
//
// A band's index is 2 * cell + side: cell = floor(station / band_m); side 1 from the plate in
// the cell on, else 0. A piece shorter than half a band joins the band beside it on its side of
// the plate, when that cell holds no plate: a plane fitted to a few centimetres of wall has
// hardly a direction. A cell is cut at its first plate only, so bands are meant to be shorter
// than the plates' spacing (1 m against 3-5 m).
//
// The plates are those the walk knows when a frame is cut. A wall seen before its plate was
// (rare: a plate is seen from farther than the walls beside it) keeps the index it had, and its
// plane spans the plate.
#include <vector>

namespace tunnelmap {

class WallBandGrid {
 public:
  // `plate_stations_m`: along the walk, in any order.
  WallBandGrid(double band_m, std::vector<double> plate_stations_m);

  long band(double station_m) const;
  double from_m(long band) const;
  double to_m(long band) const;
  double centre_m(long band) const { return 0.5 * (from_m(band) + to_m(band)); }
  // A plate lies between the middles of bands `a` and `b`.
  bool plate_between(long a, long b) const;

 private:
  static long cell_of(long band);
  double plate_in_cell(long cell) const;  // the first plate in [cell, cell + 1) * band_m; NaN if none
  bool joins_neighbour(long cell, double plate, bool past) const;

  double band_m_;
  std::vector<double> plates_m_;  // sorted
};

}  // namespace tunnelmap
