#include "core/mapping/plate_tracks.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace tunnelmap {

double PlateTracks::expected_variance(const Track& t, double camera_station_m) const {
  const double drift = options_.drift_m_per_sqrt_m;
  return t.variance_m2 + drift * drift * std::abs(camera_station_m - t.seen_from_m);
}

double PlateTracks::reach_m(const Track& t, double sigma_m, double camera_station_m) const {
  const double sigma = std::sqrt(expected_variance(t, camera_station_m) + sigma_m * sigma_m);
  return std::clamp(4.0 * sigma, options_.min_reach_m, options_.gate_m);
}

int PlateTracks::nearest(double station_m, double sigma_m, double camera_station_m) const {
  int best = -1;
  double best_gap = options_.gate_m;
  for (std::size_t i = 0; i < tracks_.size(); ++i) {
    const double gap = std::abs(tracks_[i].station_m - station_m);
    if (gap <= reach_m(tracks_[i], sigma_m, camera_station_m) && gap < best_gap)
      best_gap = gap, best = static_cast<int>(i);
  }
  return best;
}

int PlateTracks::update(int index, double station_m, double sigma_m, double camera_station_m) {
  Track& t = tracks_[static_cast<std::size_t>(index)];
  const double prior = expected_variance(t, camera_station_m), noise = sigma_m * sigma_m;
  const double gain = prior + noise > 0.0 ? prior / (prior + noise) : 0.5;
  t.station_m += gain * (station_m - t.station_m);
  t.variance_m2 = gain * noise;
  t.seen_from_m = camera_station_m;
  return t.plane;
}

bool PlateTracks::any_within(double from_m, double to_m) const {
  return std::any_of(tracks_.begin(), tracks_.end(),
                     [&](const Track& t) { return t.station_m >= from_m && t.station_m <= to_m; });
}

double PlateTracks::nearest_within(double from_m, double to_m, double near_m) const {
  double best = std::numeric_limits<double>::quiet_NaN();
  for (const Track& t : tracks_)
    if (t.station_m >= from_m && t.station_m <= to_m &&
        (std::isnan(best) || std::abs(t.station_m - near_m) < std::abs(best - near_m)))
      best = t.station_m;
  return best;
}

}  // namespace tunnelmap
