#include "core/io/tum_sidecar.h"

#include <cmath>

#include "core/io/depth_png.h"
#include "core/io/json_file.h"
#include "core/util/error.h"

namespace tunnelmap {

using nlohmann::json;

namespace {

struct Keys {
  std::string path;
  [[noreturn]] void fail(const std::string& key, const std::string& problem) const {
    throw InputError(path, "key '" + key + "': " + problem);
  }
  double number(const json& j, const std::string& key, const std::string& name) const {
    const auto it = j.find(name);
    if (it == j.end()) fail(key + name, "missing");
    if (!it->is_number() || !std::isfinite(it->get<double>())) fail(key + name, "must be a finite number");
    return it->get<double>();
  }
};

Intrinsics parse_intrinsics(const Keys& k, const json& j) {
  if (!j.is_object()) k.fail("intrinsics", "must be an object with fx, fy, cx, cy, width, height");
  Intrinsics K;
  K.fx = k.number(j, "intrinsics.", "fx");
  K.fy = k.number(j, "intrinsics.", "fy");
  K.cx = k.number(j, "intrinsics.", "cx");
  K.cy = k.number(j, "intrinsics.", "cy");
  const double w = k.number(j, "intrinsics.", "width"), h = k.number(j, "intrinsics.", "height");
  if (!(K.fx > 0)) k.fail("intrinsics.fx", "must be > 0");
  if (!(K.fy > 0)) k.fail("intrinsics.fy", "must be > 0");
  const std::string range = "must be an integer 1.." + std::to_string(kMaxImageSide);
  if (!(w >= 1 && w <= kMaxImageSide && w == std::floor(w))) k.fail("intrinsics.width", range);
  if (!(h >= 1 && h <= kMaxImageSide && h == std::floor(h))) k.fail("intrinsics.height", range);
  K.width = static_cast<int>(w);
  K.height = static_cast<int>(h);
  return K;
}

// Any length but zero, normalised: the rule of dataset.json's per-frame "gravity".
Eigen::Vector3d parse_direction(const Keys& k, const json& v, const std::string& key) {
  if (!v.is_array() || v.size() != 3) k.fail(key, "must have 3 numbers");
  Eigen::Vector3d d;
  for (int i = 0; i < 3; ++i) {
    if (!v[i].is_number() || !std::isfinite(v[i].get<double>())) k.fail(key, "must have 3 finite numbers");
    d[i] = v[i].get<double>();
  }
  if (!(d.norm() > 1e-9)) k.fail(key, "must not be the zero vector");
  if (!std::isfinite(d.norm())) k.fail(key, "is too long (its length overflows a double)");
  return d.normalized();
}

}  // namespace

TumSidecar read_tum_sidecar(const std::string& path) {
  const Keys k{path};
  const json j = read_json_file(path);
  if (!j.is_object()) k.fail("(top level)", "must be a JSON object");
  const auto format = j.find("format");
  if (format == j.end() || !format->is_string() || *format != kTumSidecarFormat)
    k.fail("format", std::string("must be \"") + kTumSidecarFormat + "\"");
  TumSidecar s;
  if (j.contains("intrinsics")) s.intrinsics = parse_intrinsics(k, j["intrinsics"]);
  if (j.contains("up")) s.up = parse_direction(k, j["up"], "up");
  if (j.contains("gravity")) {
    const json& g = j["gravity"];
    if (!g.is_object()) k.fail("gravity", "must be an object: depth image (as depth.txt lists it) -> [x, y, z]");
    for (const auto& [depth_file, v] : g.items()) s.gravity[depth_file] = parse_direction(k, v, "gravity." + depth_file);
  }
  if (j.contains("ground_truth")) {
    s.ground_truth = j["ground_truth"];
    if (!s.ground_truth.is_object()) k.fail("ground_truth", "must be an object");
    for (const char* name : {"width_m", "height_m"})
      if (s.ground_truth.contains(name) && !s.ground_truth[name].is_number())
        k.fail(std::string("ground_truth.") + name, "must be a number");
  }
  return s;
}

json tum_sidecar_json(const TumSidecar& s) {
  json j = {{"format", kTumSidecarFormat}};
  if (s.intrinsics) {
    const Intrinsics& K = *s.intrinsics;
    j["intrinsics"] = {{"fx", K.fx}, {"fy", K.fy}, {"cx", K.cx}, {"cy", K.cy},
                       {"width", K.width}, {"height", K.height}};
  }
  if (s.up) j["up"] = {s.up->x(), s.up->y(), s.up->z()};
  if (s.ground_truth.is_object()) j["ground_truth"] = s.ground_truth;
  if (!s.gravity.empty()) {
    json g = json::object();
    for (const auto& [depth_file, v] : s.gravity) g[depth_file] = {v.x(), v.y(), v.z()};
    j["gravity"] = g;
  }
  return j;
}

}  // namespace tunnelmap
