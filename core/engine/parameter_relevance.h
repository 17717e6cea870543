#pragma once
// Which parameters a single-frame detection actually reads with the chosen method and growing
// order, so a front end can hide or grey the ones that would change nothing (moving them leaves
// every result byte-identical) and say why.
#include <optional>
#include <string>

#include "core/baselines/method.h"
#include "core/params/parameter_table.h"
#include "core/params/parameters.h"

namespace tunnelmap {

enum class Relevance {
  Used,           // the detection reads it
  OtherMethod,    // only another detection method reads it
  GrowingOrder,   // this method reads it, but not with the current growing order
};

struct ParameterRelevance {
  Relevance relevance = Relevance::Used;
  std::string reason;  // empty when used: why it changes nothing, and how to make it count
};

// `spec`'s effect on detecting one frame with `method` and the values in `params`. Parameters
// of the map, the SLAM and fusion are Used: their own commands read them.
ParameterRelevance parameter_relevance(const ParameterSpec& spec, const Parameters& params, Method method);

}  // namespace tunnelmap
