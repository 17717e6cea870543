#pragma once
// The `pose_refinement` object of `map --json` and `fuse --json`: whether and how the poses were
// estimated against the structure, and the evidence that decided whether to correct them.
#include <nlohmann/json.hpp>

#include "core/mapping/pose_refinement.h"

namespace tunnelmap {

nlohmann::json pose_refinement_json(const PoseRefinement& r);

}  // namespace tunnelmap
