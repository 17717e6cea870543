#pragma once
// Outcome of tunnel detection for one frame. Its names are written to JSON, CSV, PLY comments
// and printed lines; users' scripts match them, so a name never changes once released.
#include <iosfwd>
#include <nlohmann/json_fwd.hpp>
#include <optional>
#include <string_view>

namespace tunnelmap {

enum class TunnelStatus {
  NotRun = 0,               // "not_run": no detection ran yet
  Ok,                       // "ok": all four walls measured
  Partial,                  // "partial": detected with some wall out of view
  TooFewPlanes,             // "too_few_planes"
  MissingWall,              // "missing_wall"
  NoParallelPair,           // "no_parallel_pair"
  NotRectangular,           // "not_rectangular"
  OutOfTemplate,            // "out_of_template": width or height outside the template window
  InconsistentWithContext,  // "inconsistent_with_context": far from the earlier frames' map
  TooFewPoints,             // "too_few_points" (convex-hull baseline)
  DegenerateHull,           // "degenerate_hull" (convex-hull baseline)
  NoDetection,              // "no_detection": a merged map with no detected frame
};
inline constexpr int kTunnelStatusCount = static_cast<int>(TunnelStatus::NoDetection) + 1;

// The stable name; never null.
const char* status_name(TunnelStatus s);
// The status of a name status_name gives; nullopt for any other text.
std::optional<TunnelStatus> parse_tunnel_status(std::string_view name);
// Prints the name (test messages, log lines).
std::ostream& operator<<(std::ostream& out, TunnelStatus s);
// JSON holds the name (without these nlohmann would silently write the number); reading an
// unknown name throws nlohmann::json::other_error.
void to_json(nlohmann::json& j, TunnelStatus s);
void from_json(const nlohmann::json& j, TunnelStatus& s);

}  // namespace tunnelmap
