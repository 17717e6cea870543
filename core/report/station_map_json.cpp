#include "core/report/station_map_json.h"

#include "core/report/girder_json.h"
#include "core/report/json_numbers.h"

#include <cmath>
#include <iomanip>
#include <locale>
#include <sstream>

namespace tunnelmap {

namespace {

const auto& vec = json_vec;

nlohmann::json number_or_null(double v, double unit) {
  return std::isfinite(v) ? nlohmann::json(round_to(v, unit)) : nlohmann::json(nullptr);
}

nlohmann::json number_or_null(const std::optional<double>& v, double unit) {
  return v ? number_or_null(*v, unit) : nlohmann::json(nullptr);
}

}  // namespace

nlohmann::json station_json(const Station& s) {
  const auto value = [](double v, DimensionSource src) {
    return src == DimensionSource::Unseen ? nlohmann::json(nullptr) : number_or_null(v, 1e-5);
  };
  return {{"station_m", round_to(s.station_m, 1e-4)},
          {"width_m", value(s.width_m, s.width_source)},
          {"height_m", value(s.height_m, s.height_source)},
          {"width_source", dimension_source_name(s.width_source)},
          {"height_source", dimension_source_name(s.height_source)},
          {"frames", s.frames},
          {"width_dev_mm", number_or_null(s.width_dev_mm, 0.01)},
          {"height_dev_mm", number_or_null(s.height_dev_mm, 0.01)},
          {"out_of_tolerance", s.out_of_tolerance}};
}

nlohmann::json section_json(const Section& s, const StationMapOptions& o, bool first) {
  nlohmann::json j = {{"from_m", round_to(s.from_m, 1e-4)},
                      {"to_m", round_to(s.to_m, 1e-4)},
                      {"width_m", number_or_null(s.width_m, 1e-5)},
                      {"height_m", number_or_null(s.height_m, 1e-5)},
                      {"frames", s.frames}};
  // The joint at from_m: "seen" (frames measured the step themselves) or "between_views" (a
  // plate hid it: placed in the middle of the stretch nothing measured); null for the first.
  j["joint"] = first ? nlohmann::json(nullptr)
                     : nlohmann::json{{"source", s.joint_seen ? "seen" : "between_views"},
                                      {"uncertainty_m", round_to(s.joint_uncertainty_m, 1e-3)}};
  j["width_dev_mm"] = o.design_width_m && std::isfinite(s.width_m)
                          ? number_or_null((s.width_m - *o.design_width_m) * 1000.0, 0.01)
                          : nlohmann::json(nullptr);
  j["height_dev_mm"] = o.design_height_m && std::isfinite(s.height_m)
                           ? number_or_null((s.height_m - *o.design_height_m) * 1000.0, 0.01)
                           : nlohmann::json(nullptr);
  return j;
}

nlohmann::json rescan_json(const RescanStretch& r) {
  return {{"from_m", round_to(r.from_m, 1e-4)},
          {"to_m", round_to(r.to_m, 1e-4)},
          {"unmeasured", station_dimension_name(r.dimension)},
          {"joint_inside", r.joint_inside},
          {"reason", r.reason}};
}

nlohmann::json station_map_document(const StationMap& m, const nlohmann::json& params,
                                    const nlohmann::json& frames, const std::string& input) {
  nlohmann::json doc;
  doc["tool"] = "tunnelmap";
  doc["version"] = TUNNELMAP_VERSION;
  doc["input"] = input;
  doc["status"] = m.status;
  if (!m.reason.empty()) doc["reason"] = m.reason;
  doc["params"] = params;
  doc["station_step_m"] = m.options.station_step_m;
  doc["design"] = m.options.design_width_m || m.options.design_height_m
                      ? nlohmann::json{{"width_m", number_or_null(m.options.design_width_m, 1e-6)},
                                       {"height_m", number_or_null(m.options.design_height_m, 1e-6)}}
                      : nlohmann::json(nullptr);
  doc["tolerance_mm"] = m.options.tolerance_mm;
  // Station s lies at origin + s * axis (world frame).
  doc["frame"] = {{"origin", vec(m.origin)}, {"axis", vec(m.axis)}, {"up", vec(m.up)}};
  nlohmann::json stations = nlohmann::json::array(), sections = nlohmann::json::array(),
                 poses = nlohmann::json::array();
  for (const Station& s : m.stations) stations.push_back(station_json(s));
  for (const Section& s : m.sections) sections.push_back(section_json(s, m.options, sections.empty()));
  int rescans = 0;
  for (const PoseGroupStatus& p : m.poses) {
    rescans += p.rescan ? 1 : 0;
    poses.push_back({{"group", p.group},
                     {"frames", p.frames},
                     {"detected_frames", p.detected_frames},
                     {"status", p.status},
                     {"rescan", p.rescan},
                     {"message", p.message}});
  }
  doc["stations"] = stations;
  doc["sections"] = sections;
  doc["poses"] = poses;
  // Stretches whose size no frame measured: where the robot should look again.
  nlohmann::json rescan = nlohmann::json::array();
  for (const RescanStretch& r : rescan_stretches(m)) rescan.push_back(rescan_json(r));
  doc["rescan"] = rescan;
  add_girder_json(m.girder, doc);
  doc["frames"] = frames;
  const double map_ms = m.timings_ms.count("map") ? m.timings_ms.at("map") : 0.0;
  doc["summary"] = {{"frames", m.frames},
                    {"frames_used", m.frames_used},
                    {"stations", m.stations.size()},
                    {"sections", m.sections.size()},
                    {"out_of_tolerance", m.out_of_tolerance().size()},
                    {"rescan_poses", rescans},
                    {"rescan_stretches", doc["rescan"].size()},
                    {"diaphragms", m.girder.diaphragms.size()},
                    {"extent_m", m.stations.empty() ? nlohmann::json(nullptr)
                                                    : nlohmann::json({round_to(m.sections.front().from_m, 1e-4),
                                                                      round_to(m.sections.back().to_m, 1e-4)})},
                    {"map_ms", round_to(map_ms, 1e-3)}};
  return doc;
}

std::string station_map_csv(const StationMap& m) {
  std::ostringstream out;
  out.imbue(std::locale::classic());
  out << "station_m,width_m,height_m,width_source,height_source,frames,width_dev_mm,height_dev_mm,"
         "out_of_tolerance\n";
  for (const Station& s : m.stations) {
    const nlohmann::json j = station_json(s);
    bool first = true;
    for (const char* key : {"station_m", "width_m", "height_m", "width_source", "height_source",
                            "frames", "width_dev_mm", "height_dev_mm", "out_of_tolerance"}) {
      const nlohmann::json& v = j[key];
      if (!first) out << ',';
      first = false;
      if (v.is_null()) continue;
      if (v.is_string()) out << v.get<std::string>();
      else if (v.is_boolean()) out << (v.get<bool>() ? 1 : 0);
      else out << v.dump();
    }
    out << '\n';
  }
  return out.str();
}

}  // namespace tunnelmap
