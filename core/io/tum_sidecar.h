#pragma once
// tunnelmap.json beside a TUM sequence: what the TUM layout cannot say and TunnelMap's exports
// keep — the depth camera's intrinsics, the world up, the dataset's "ground_truth" (tunnel
// size, true surfaces of simulated sequences) and each frame's gravity. Optional; see
// docs/dataset-format.md.
#include <Eigen/Core>
#include <map>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>

#include "core/frame/intrinsics.h"

namespace tunnelmap {

constexpr const char* kTumSidecarName = "tunnelmap.json";
constexpr const char* kTumSidecarFormat = "tunnelmap-tum-extras/1";

struct TumSidecar {
  std::optional<Intrinsics> intrinsics;
  std::optional<Eigen::Vector3d> up;  // unit
  nlohmann::json ground_truth;        // object, or null when absent
  // Where things fall in the camera frame (unit), by the depth image as depth.txt lists it.
  std::map<std::string, Eigen::Vector3d> gravity;
};

// InputError naming the file and the key on any problem (same rules as dataset.json).
TumSidecar read_tum_sidecar(const std::string& path);

nlohmann::json tum_sidecar_json(const TumSidecar& s);

}  // namespace tunnelmap
