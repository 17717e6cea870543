#include "core/report/girder_json.h"

#include <cmath>
#include <locale>
#include <sstream>

#include "core/report/json_numbers.h"

namespace tunnelmap {

namespace {

nlohmann::json number_or_null(double v, double unit) {
  return std::isfinite(v) ? nlohmann::json(round_to(v, unit)) : nlohmann::json(nullptr);
}

nlohmann::json rounded(const Eigen::Vector3d& v, double unit) {
  return {round_to(v.x(), unit), round_to(v.y(), unit), round_to(v.z(), unit)};
}

nlohmann::json manhole_json(const Manhole& m) {
  nlohmann::json j = {{"center", rounded(m.center, 1e-4)},
                      {"width_m", round_to(m.width_m, 1e-4)},
                      {"height_m", round_to(m.height_m, 1e-4)},
                      {"shape", m.shape},
                      {"corner_radius_m", m.shape == "rounded_rectangle"
                                              ? nlohmann::json(round_to(m.corner_radius_m, 1e-4))
                                              : nlohmann::json(nullptr)},
                      {"fit_mm", round_to(m.fit_rms_mm, 0.01)},
                      {"rim_points", m.rim_points}};
  j["clearance_m"] = {{"left", number_or_null(m.clearance_m[0], 1e-4)},
                      {"right", number_or_null(m.clearance_m[1], 1e-4)},
                      {"top", number_or_null(m.clearance_m[2], 1e-4)},
                      {"bottom", number_or_null(m.clearance_m[3], 1e-4)}};
  return j;
}

}  // namespace

void add_girder_json(const GirderStructure& g, nlohmann::json& doc) {
  nlohmann::json centreline = nlohmann::json::array(), plates = nlohmann::json::array(),
                 compartments = nlohmann::json::array();
  for (const CentrelinePoint& c : g.centreline)
    centreline.push_back({{"station_m", round_to(c.station_m, 1e-4)},
                          {"point", rounded(c.point, 1e-4)},
                          {"source", c.source}});
  for (const Diaphragm& d : g.diaphragms) {
    nlohmann::json j = {{"kind", d.kind},
                        {"station_m", round_to(d.station_m, 1e-4)},
                        {"point", rounded(d.point, 1e-4)},
                        {"normal", rounded(d.normal, 1e-5)},
                        {"seen_by_frames", d.seen_by_frames},
                        {"area_m2", round_to(d.area_m2, 1e-3)},
                        {"manhole", d.manhole ? manhole_json(*d.manhole) : nlohmann::json(nullptr)}};
    if (!d.manhole) j["manhole_reason"] = d.manhole_reason;
    plates.push_back(j);
  }
  for (const Compartment& c : g.compartments)
    compartments.push_back({{"from_m", round_to(c.from_m, 1e-4)},
                            {"to_m", round_to(c.to_m, 1e-4)},
                            {"width_m", number_or_null(c.width_m, 1e-5)},
                            {"height_m", number_or_null(c.height_m, 1e-5)},
                            {"closed", {c.closed_from, c.closed_to}},
                            {"stations_measured", c.stations_measured}});
  doc["centreline"] = centreline;
  doc["diaphragms"] = plates;
  doc["compartments"] = compartments;
}

std::string diaphragms_csv(const GirderStructure& g) {
  std::ostringstream out;
  out.imbue(std::locale::classic());
  out << "station_m,normal_x,normal_y,normal_z,seen_by_frames,area_m2,manhole_x,manhole_y,manhole_z,"
         "manhole_width_m,manhole_height_m,manhole_shape,clearance_left_m,clearance_right_m,"
         "clearance_top_m,clearance_bottom_m,manhole_reason,kind\n";
  const auto num = [&](double v, double unit) {
    if (std::isfinite(v)) out << round_to(v, unit);
  };
  for (const Diaphragm& d : g.diaphragms) {
    num(d.station_m, 1e-4);
    for (int k = 0; k < 3; ++k) out << ',', num(d.normal[k], 1e-5);
    out << ',' << d.seen_by_frames << ',';
    num(d.area_m2, 1e-3);
    if (d.manhole) {
      const Manhole& m = *d.manhole;
      for (int k = 0; k < 3; ++k) out << ',', num(m.center[k], 1e-4);
      out << ',', num(m.width_m, 1e-4);
      out << ',', num(m.height_m, 1e-4);
      out << ',' << m.shape;
      for (int k = 0; k < 4; ++k) out << ',', num(m.clearance_m[k], 1e-4);
      out << ",," << d.kind << "\n";
    } else {
      // The reason may hold commas: quoted as CSV wants.
      out << ",,,,,,,,,,\"" << d.manhole_reason << "\"," << d.kind << "\n";
    }
  }
  return out.str();
}

}  // namespace tunnelmap
