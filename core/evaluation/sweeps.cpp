#include "core/evaluation/sweeps.h"

#include <algorithm>
#include <cstdio>

#include "core/util/error.h"

namespace tunnelmap {

std::vector<SweepSpec> default_sweeps(const std::vector<std::string>& names) {
  const std::vector<SweepSpec> all{
      {"noise_scale", "lab", {0.5, 1.0, 2.0, 3.0}},
      {"dropout_scale", "lab", {0.5, 1.0, 2.0, 4.0}},
      {"roll_deg", "lab", {0.0, 5.0, 10.0, 20.0}},
      {"pitch_deg", "lab", {-10.0, 0.0, 10.0, 20.0}},
      {"distance_to_manhole_m", "field", {1.2, 1.8, 3.0, 5.0}},
      {"plate_thickness_mm", "lab", {0.0, 4.0, 8.0, 12.0, 16.0}},
  };
  if (names.empty()) return all;
  std::vector<SweepSpec> out;
  for (const std::string& n : names) {
    const auto it = std::find_if(all.begin(), all.end(), [&](const SweepSpec& s) { return s.name == n; });
    if (it == all.end())
      throw ParameterError("unknown sweep '" + n + "' (expected noise_scale, dropout_scale, roll_deg, "
                           "pitch_deg, distance_to_manhole_m or plate_thickness_mm)");
    out.push_back(*it);
  }
  return out;
}

void apply_sweep_value(const std::string& name, double v, SimConfig& c) {
  if (name == "noise_scale") c.noise_scale = v;
  else if (name == "dropout_scale") c.dropout_scale = v;
  else if (name == "roll_deg") c.roll_deg = v;
  else if (name == "pitch_deg") c.pitch_deg = v;
  else if (name == "distance_to_manhole_m") {
    c.distance_to_manhole_m = v;
    c.manhole_distances_m.clear();
  } else if (name == "plate_thickness_mm") c.plate_thickness_m = {v / 1000, v / 1000, v / 1000, v / 1000};
  else throw ParameterError("unknown sweep '" + name + "'");
}

std::vector<CellResult> run_sweeps(const std::vector<SweepSpec>& sweeps, const ProtocolOptions& o) {
  std::vector<CellResult> all;
  for (const SweepSpec& s : sweeps) {
    const Parameters params = preset_parameters(o, s.preset);
    for (double v : s.values) {
      SimConfig c = SimConfig::from_preset(s.preset);
      apply_sweep_value(s.name, v, c);
      char cell[96];
      std::snprintf(cell, sizeof cell, "%s=%g", s.name.c_str(), v);
      const std::string cell_name = cell;
      auto part = run_simulated(c, s.name, [cell_name](int) { return cell_name; }, v, params, o);
      all.insert(all.end(), part.begin(), part.end());
    }
  }
  return all;
}

}  // namespace tunnelmap
