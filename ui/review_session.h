#pragma once
// A review session: what the inspection window shows (input, parameters, method, camera, visible
// layers, shown frame), saved as a small JSON file ("tunnelmap-session/1", docs/gui.md) so a
// review can be reopened exactly. No Qt: plain data, read and written with nlohmann-json.
#include <array>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/baselines/method.h"
#include "core/frame/intrinsics.h"
#include "core/params/parameters.h"

namespace tunnelmap::ui {

struct SessionCamera {
  std::array<double, 3> position{0, 0, 0};
  std::array<double, 3> focal_point{0, 0, 1};
  std::array<double, 3> view_up{0, -1, 0};
  double view_angle = 30.0;
};

struct ReviewSession {
  std::string input;        // absolute path (a relative one is read relative to the session file)
  std::string preset_name;  // "defaults" when none was loaded
  std::string preset_path;  // "" when unknown
  Parameters params;
  Method method = Method::Pgc;
  std::optional<SessionCamera> camera;
  // scene::layer_name of each visible layer; none given: the layers stay as they are.
  std::optional<std::vector<std::string>> layers;
  int frame = 1;                     // 1-based, as the timeline shows it
  std::optional<Intrinsics> intrinsics;  // the user's FX,FY,CX,CY for the input, if any
  // 3D-view distance measurements, each 1 or 2 picked points (camera frame of the shown frame):
  // [{"points": [[x,y,z], [x,y,z]], "distance_m": d}] ("distance_m" written for readers only).
  std::vector<std::vector<std::array<double, 3>>> measurements;
  // "preset": {"params": {...}}: the loaded preset's own values, so the "(modified)" mark is the
  // same after reopening even if the preset file has moved or changed since.
  std::optional<Parameters> preset_params;
  // "review": {"map": true, "cross_section_station_m": 1.3}: Map tunnel had run (it runs again
  // on open, with the session's parameters) and the cut's station ahead of the shown frame.
  bool mapped = false;
  std::optional<double> cross_section_station_m;
};

nlohmann::json session_to_json(const ReviewSession& s);
// Every field checked (format, types, parameter ranges and rules, method and layer names,
// frame >= 1, finite camera); InputError naming `file` with the first problem.
ReviewSession session_from_json(const nlohmann::json& j, const std::string& file);

ReviewSession read_session_file(const std::string& path);  // InputError naming `path`
// Atomic (core/util/atomic_file.h): a failed write leaves the previous file whole.
void write_session_file(const std::string& path, const ReviewSession& s);

// "FX,FY,CX,CY" in pixels, as the CLI's --intrinsics; ParameterError when malformed.
Intrinsics parse_intrinsics(const std::string& text);

}  // namespace tunnelmap::ui
