#pragma once
// The plates a walk has seen, told apart by their position along the girder as the odometry
// measures it (arc length of the walk). Each plate's position is tracked like a
// one-dimensional Kalman filter: a view brings its patch's noise, and the odometry's drift since
// the plate was last seen takes certainty away. A view within four standard deviations of where
// a plate is expected is that plate.
//
// The view's own noise counts as well as the drift: a plate first seen through a manhole from
// 5 m is known to a centimetre or two, and its near views, a few centimetres from that, must
// still be that plate. A second landmark of it would leave the compartment behind it held
// along the girder by the odometry alone.
#include <vector>

namespace tunnelmap {

struct PlateTrackOptions {
  double drift_m_per_sqrt_m = 0.01;  // the odometry's position drift
  double min_reach_m = 0.05;         // plates nearer than this along the girder are one
  double gate_m = 0.3;               // a view farther than this from every plate is a new plate
};

class PlateTracks {
 public:
  explicit PlateTracks(PlateTrackOptions options = PlateTrackOptions()) : options_(options) {}

  // The plate a view belongs to (adding a new one when none is within reach), with `plane`
  // called for a new plate's landmark. `station_m`, `sigma_m`: the view's position along the
  // walk and its noise; `camera_station_m`: where the camera stood.
  template <typename NewPlane>
  int view(double station_m, double sigma_m, double camera_station_m, NewPlane plane) {
    const int known = nearest(station_m, sigma_m, camera_station_m);
    if (known >= 0) return update(known, station_m, sigma_m, camera_station_m);
    tracks_.push_back({station_m, sigma_m * sigma_m, camera_station_m, plane()});
    return tracks_.back().plane;
  }

  // A tracked plate lies within [from_m, to_m] of the walk.
  bool any_within(double from_m, double to_m) const;
  // The station of the tracked plate within [from_m, to_m] nearest to `near_m`; NaN if none.
  double nearest_within(double from_m, double to_m, double near_m) const;
  int size() const { return static_cast<int>(tracks_.size()); }
  double station_m(int index) const { return tracks_.at(static_cast<std::size_t>(index)).station_m; }

 private:
  struct Track {
    double station_m;    // along the walk (odometry)
    double variance_m2;  // of station_m, when last seen
    double seen_from_m;  // the camera's station when it was last seen
    int plane;
  };
  double expected_variance(const Track& t, double camera_station_m) const;
  double reach_m(const Track& t, double sigma_m, double camera_station_m) const;
  int nearest(double station_m, double sigma_m, double camera_station_m) const;
  int update(int index, double station_m, double sigma_m, double camera_station_m);

  PlateTrackOptions options_;
  std::vector<Track> tracks_;
};

}  // namespace tunnelmap
