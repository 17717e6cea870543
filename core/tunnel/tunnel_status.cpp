#include "core/tunnel/tunnel_status.h"

#include <nlohmann/json.hpp>
#include <ostream>
#include <string>

namespace tunnelmap {

namespace {
// Indexed by TunnelStatus.
constexpr const char* kNames[kTunnelStatusCount] = {
    "not_run",
    "ok",
    "partial",
    "too_few_planes",
    "missing_wall",
    "no_parallel_pair",
    "not_rectangular",
    "out_of_template",
    "inconsistent_with_context",
    "too_few_points",
    "degenerate_hull",
    "no_detection",
};
}  // namespace

const char* status_name(TunnelStatus s) {
  const int i = static_cast<int>(s);
  return i >= 0 && i < kTunnelStatusCount ? kNames[i] : "unknown";
}

std::optional<TunnelStatus> parse_tunnel_status(std::string_view name) {
  for (int i = 0; i < kTunnelStatusCount; ++i)
    if (name == kNames[i]) return static_cast<TunnelStatus>(i);
  return std::nullopt;
}

std::ostream& operator<<(std::ostream& out, TunnelStatus s) { return out << status_name(s); }

void to_json(nlohmann::json& j, TunnelStatus s) { j = status_name(s); }

void from_json(const nlohmann::json& j, TunnelStatus& s) {
  const std::string name = j.get<std::string>();
  const std::optional<TunnelStatus> parsed = parse_tunnel_status(name);
  if (!parsed) throw nlohmann::json::other_error::create(501, "unknown tunnel status \"" + name + "\"", &j);
  s = *parsed;
}

}  // namespace tunnelmap
