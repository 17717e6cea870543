#include "ui/review_session.h"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "core/util/atomic_file.h"
#include "core/util/error.h"
#include "ui/scene/scene_layers.h"

namespace tunnelmap::ui {

namespace {
constexpr const char* kFormat = "tunnelmap-session/1";

using Json = nlohmann::json;

std::array<double, 3> read_vec3(const Json& j, const char* key, const std::string& file) {
  const Json& v = j.at(key);
  if (!v.is_array() || v.size() != 3) throw InputError(file, std::string("camera.") + key + " must be 3 numbers");
  std::array<double, 3> out{};
  for (int i = 0; i < 3; ++i) {
    if (!v[i].is_number() || !std::isfinite(v[i].get<double>()))
      throw InputError(file, std::string("camera.") + key + " must be 3 finite numbers");
    out[i] = v[i].get<double>();
  }
  return out;
}

std::string read_string(const Json& j, const char* key, const std::string& file, bool required) {
  if (!j.contains(key)) {
    if (required) throw InputError(file, std::string("missing \"") + key + "\"");
    return {};
  }
  if (!j[key].is_string()) throw InputError(file, std::string("\"") + key + "\" must be a string");
  return j[key].get<std::string>();
}
}  // namespace

Intrinsics parse_intrinsics(const std::string& text) {
  std::vector<double> v;
  std::stringstream ss(text);
  std::string item;
  const std::string bad = "--intrinsics expects 4 comma-separated numbers FX,FY,CX,CY, got '" + text + "'";
  while (std::getline(ss, item, ',')) {
    std::size_t used = 0;
    double x = 0;
    try {
      x = std::stod(item, &used);
    } catch (...) {
      used = 0;
    }
    if (used == 0 || used != item.size() || !std::isfinite(x)) throw ParameterError(bad);
    v.push_back(x);
  }
  if (v.size() != 4) throw ParameterError(bad);
  if (v[0] <= 0 || v[1] <= 0 || v[0] > 1e5 || v[1] > 1e5)
    throw ParameterError("--intrinsics: focal lengths must be positive pixels");
  Intrinsics K;
  K.fx = v[0], K.fy = v[1], K.cx = v[2], K.cy = v[3];
  return K;
}

Json session_to_json(const ReviewSession& s) {
  Json j;
  j["format"] = kFormat;
  j["input"] = s.input;
  j["preset"] = {{"name", s.preset_name}, {"path", s.preset_path}};
  if (s.preset_params) j["preset"]["params"] = s.preset_params->to_json();
  j["review"] = {{"map", s.mapped}, {"cross_section_station_m", nullptr}};
  if (s.cross_section_station_m) j["review"]["cross_section_station_m"] = *s.cross_section_station_m;
  j["params"] = s.params.to_json();
  j["method"] = method_name(s.method);
  if (s.camera)
    j["camera"] = {{"position", s.camera->position},
                   {"focal_point", s.camera->focal_point},
                   {"view_up", s.camera->view_up},
                   {"view_angle", s.camera->view_angle}};
  if (s.layers) j["layers"] = *s.layers;
  j["frame"] = s.frame;
  if (s.intrinsics)
    j["intrinsics"] = {{"fx", s.intrinsics->fx}, {"fy", s.intrinsics->fy},
                       {"cx", s.intrinsics->cx}, {"cy", s.intrinsics->cy}};
  j["measurements"] = Json::array();
  for (const auto& m : s.measurements) {
    Json entry = {{"points", m}};
    if (m.size() == 2) {
      double d2 = 0;
      for (int i = 0; i < 3; ++i) d2 += (m[0][i] - m[1][i]) * (m[0][i] - m[1][i]);
      entry["distance_m"] = std::sqrt(d2);
    }
    j["measurements"].push_back(entry);
  }
  return j;
}

namespace {

Parameters read_parameters(const Json& j, const std::string& what, const std::string& file) {
  if (!j.is_object()) throw InputError(file, "\"" + what + "\" must be an object {KEY: VALUE}");
  Parameters p;
  try {
    p.apply_json(j, file);
  } catch (const InputError&) {
    throw;
  } catch (const std::exception& e) {
    throw InputError(file, e.what());
  }
  return p;
}

// "review": whether the tunnel was mapped, and the cut's station.
void read_review(const Json& j, const std::string& file, ReviewSession& s) {
  const std::string bad = "\"review\" must be {\"map\": true|false, \"cross_section_station_m\": number|null}";
  if (!j.is_object()) throw InputError(file, bad);
  if (j.contains("map")) {
    if (!j["map"].is_boolean()) throw InputError(file, bad);
    s.mapped = j["map"].get<bool>();
  }
  if (j.contains("cross_section_station_m") && !j["cross_section_station_m"].is_null()) {
    const Json& v = j["cross_section_station_m"];
    if (!v.is_number() || !std::isfinite(v.get<double>()) || v.get<double>() < 0) throw InputError(file, bad);
    s.cross_section_station_m = v.get<double>();
  }
}

}  // namespace

ReviewSession session_from_json(const Json& j, const std::string& file) {
  if (!j.is_object()) throw InputError(file, "not a review session (expected a JSON object)");
  const std::string format = read_string(j, "format", file, true);
  if (format != kFormat)
    throw InputError(file, "unsupported session format '" + format + "' (expected " + kFormat + ")");
  ReviewSession s;
  s.input = read_string(j, "input", file, true);
  if (s.input.empty()) throw InputError(file, "\"input\" is empty");
  if (std::filesystem::path(s.input).is_relative())
    s.input = (std::filesystem::absolute(file).parent_path() / s.input).lexically_normal().string();
  s.preset_name = "defaults";
  if (j.contains("preset")) {
    const Json& p = j["preset"];
    if (!p.is_object()) throw InputError(file, "\"preset\" must be an object {name, path}");
    const std::string name = read_string(p, "name", file, false);
    if (!name.empty()) s.preset_name = name;
    s.preset_path = read_string(p, "path", file, false);
    if (p.contains("params")) s.preset_params = read_parameters(p["params"], "preset.params", file);
  }
  if (j.contains("params")) s.params = read_parameters(j["params"], "params", file);
  if (j.contains("review")) read_review(j["review"], file, s);
  if (j.contains("method")) {
    try {
      s.method = parse_method(read_string(j, "method", file, true));
    } catch (const ParameterError& e) {
      throw InputError(file, e.what());
    }
  }
  if (j.contains("camera")) {
    const Json& c = j["camera"];
    if (!c.is_object()) throw InputError(file, "\"camera\" must be an object");
    SessionCamera cam;
    try {
      cam.position = read_vec3(c, "position", file);
      cam.focal_point = read_vec3(c, "focal_point", file);
      cam.view_up = read_vec3(c, "view_up", file);
      const Json& a = c.at("view_angle");
      if (!a.is_number() || !(a.get<double>() > 0 && a.get<double>() < 180))
        throw InputError(file, "camera.view_angle must be a number of degrees in (0, 180)");
      cam.view_angle = a.get<double>();
    } catch (const Json::out_of_range& e) {
      throw InputError(file, "camera needs position, focal_point, view_up and view_angle");
    }
    s.camera = cam;
  }
  if (j.contains("layers")) {
    if (!j["layers"].is_array()) throw InputError(file, "\"layers\" must be a list of layer names");
    s.layers.emplace();
    for (const Json& l : j["layers"]) {
      if (!l.is_string()) throw InputError(file, "\"layers\" must be a list of layer names");
      try {
        scene::parse_layers(l.get<std::string>());
      } catch (const std::exception& e) {
        throw InputError(file, std::string("layers: ") + e.what());
      }
      s.layers->push_back(l.get<std::string>());
    }
  }
  if (j.contains("frame")) {
    if (!j["frame"].is_number_integer() || j["frame"].get<long long>() < 1 || j["frame"].get<long long>() > 100000000)
      throw InputError(file, "\"frame\" must be a frame number from 1");
    s.frame = j["frame"].get<int>();
  }
  if (j.contains("intrinsics")) {
    const Json& k = j["intrinsics"];
    const bool ok = k.is_object() && k.contains("fx") && k.contains("fy") && k.contains("cx") && k.contains("cy") &&
                    k["fx"].is_number() && k["fy"].is_number() && k["cx"].is_number() && k["cy"].is_number();
    if (!ok) throw InputError(file, "\"intrinsics\" must be {fx, fy, cx, cy} in pixels");
    Intrinsics K;
    K.fx = k["fx"], K.fy = k["fy"], K.cx = k["cx"], K.cy = k["cy"];
    if (!(K.fx > 0 && K.fy > 0 && std::isfinite(K.cx) && std::isfinite(K.cy)))
      throw InputError(file, "intrinsics: focal lengths must be positive pixels");
    s.intrinsics = K;
  }
  if (j.contains("measurements")) {
    const std::string bad = "\"measurements\" must be a list of {\"points\": [[x,y,z], [x,y,z]]}";
    if (!j["measurements"].is_array()) throw InputError(file, bad);
    for (const Json& m : j["measurements"]) {
      if (!m.is_object() || !m.contains("points") || !m["points"].is_array() || m["points"].empty() ||
          m["points"].size() > 2)
        throw InputError(file, bad);
      std::vector<std::array<double, 3>> points;
      for (const Json& p : m["points"]) {
        if (!p.is_array() || p.size() != 3) throw InputError(file, bad);
        std::array<double, 3> v{};
        for (int i = 0; i < 3; ++i) {
          if (!p[i].is_number() || !std::isfinite(p[i].get<double>())) throw InputError(file, bad);
          v[i] = p[i].get<double>();
        }
        points.push_back(v);
      }
      s.measurements.push_back(points);
    }
  }
  return s;
}

ReviewSession read_session_file(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw InputError(path, "cannot open review session");
  Json j;
  try {
    in >> j;
  } catch (const Json::parse_error& e) {
    throw InputError(path, std::string("not valid JSON: ") + e.what());
  }
  return session_from_json(j, path);
}

void write_session_file(const std::string& path, const ReviewSession& s) {
  const std::string text = session_to_json(s).dump(2) + "\n";
  write_file_atomically(path, [&](std::ostream& out) { out << text; });
}

}  // namespace tunnelmap::ui
