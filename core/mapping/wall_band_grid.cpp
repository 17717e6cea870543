#include "core/mapping/wall_band_grid.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

namespace tunnelmap {

WallBandGrid::WallBandGrid(double band_m, std::vector<double> plate_stations_m)
    : band_m_(band_m), plates_m_(std::move(plate_stations_m)) {
  std::sort(plates_m_.begin(), plates_m_.end());
}

long WallBandGrid::cell_of(long band) { return band >= 0 ? band / 2 : -((-band + 1) / 2); }

double WallBandGrid::plate_in_cell(long cell) const {
  const double lo = static_cast<double>(cell) * band_m_, hi = lo + band_m_;
  const auto it = std::lower_bound(plates_m_.begin(), plates_m_.end(), lo);
  return it != plates_m_.end() && *it < hi ? *it : std::numeric_limits<double>::quiet_NaN();
}

// The piece of cell `cell` on one side of its plate is short (under half a band) and joins the
// whole band of the neighbouring cell on that side, when that cell holds no plate.
bool WallBandGrid::joins_neighbour(long cell, double plate, bool past) const {
  const double length = past ? static_cast<double>(cell + 1) * band_m_ - plate : plate - static_cast<double>(cell) * band_m_;
  return length < 0.5 * band_m_ && std::isnan(plate_in_cell(past ? cell + 1 : cell - 1));
}

long WallBandGrid::band(double station_m) const {
  const auto cell = static_cast<long>(std::floor(station_m / band_m_));
  const double plate = plate_in_cell(cell);
  if (std::isnan(plate)) return 2 * cell;
  const bool past = station_m >= plate;
  if (joins_neighbour(cell, plate, past)) return 2 * (past ? cell + 1 : cell - 1);
  return 2 * cell + (past ? 1 : 0);
}

double WallBandGrid::from_m(long band) const {
  const long cell = cell_of(band);
  const double plate = plate_in_cell(cell);
  if (band % 2 != 0) return plate;
  if (!std::isnan(plate)) return static_cast<double>(cell) * band_m_;
  const double before = plate_in_cell(cell - 1);  // its short piece past the plate joins this band
  return !std::isnan(before) && joins_neighbour(cell - 1, before, true) ? before : static_cast<double>(cell) * band_m_;
}

double WallBandGrid::to_m(long band) const {
  const long cell = cell_of(band);
  const double plate = plate_in_cell(cell);
  if (band % 2 != 0 || std::isnan(plate)) {
    const double after = plate_in_cell(cell + 1);  // its short piece before the plate joins this band
    const bool joined = band % 2 == 0 && !std::isnan(after) && joins_neighbour(cell + 1, after, false);
    return joined ? after : static_cast<double>(cell + 1) * band_m_;
  }
  return plate;
}

bool WallBandGrid::plate_between(long a, long b) const {
  const double lo = std::min(centre_m(a), centre_m(b)), hi = std::max(centre_m(a), centre_m(b));
  const auto it = std::upper_bound(plates_m_.begin(), plates_m_.end(), lo);
  return it != plates_m_.end() && *it < hi;
}

}  // namespace tunnelmap
