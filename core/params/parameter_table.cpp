#include "core/params/parameter_table.h"

#include "core/baselines/baseline_options.h"
#include "core/fusion/fusion_options.h"
#include "core/io/input_options.h"
#include "core/mapping/map_options.h"
#include "core/mapping/slam_options.h"
#include "core/normals/cloud_options.h"
#include "core/normals/normal_options.h"
#include "core/planes/grow_options.h"
#include "core/tunnel/tunnel_options.h"

namespace tunnelmap {

const char* stage_name(Stage s) {
  switch (s) {
    case Stage::Cloud: return "cloud";
    case Stage::Normals: return "normals";
    case Stage::Planes: return "planes";
    case Stage::Tunnel: return "tunnel";
    case Stage::Fusion: return "fusion";
    case Stage::Map: return "map";
    case Stage::Baselines: return "baselines";
  }
  return "?";
}

namespace {

// The modules in the order `params`, presets and the GUI panel show them (the readers, the
// pipeline's order, then the whole-tunnel map, fusion and the baselines).
const std::vector<ParameterGroup>& groups() {
  static const std::vector<ParameterGroup> all = {input_parameter_group(), cloud_parameter_group(), normal_parameter_group(), grow_parameter_group(),
                                                  tunnel_parameter_group(), map_parameter_group(),    slam_parameter_group(),
                                                  fusion_parameter_group(),
                                                  baseline_parameter_group()};
  return all;
}

}  // namespace

const std::vector<ParameterSpec>& parameter_table() {
  static const std::vector<ParameterSpec> table = [] {
    std::vector<ParameterSpec> t;
    for (const ParameterGroup& g : groups()) t.insert(t.end(), g.specs.begin(), g.specs.end());
    return t;
  }();
  return table;
}

const std::vector<ParameterRule>& parameter_rules() {
  static const std::vector<ParameterRule> rules = [] {
    std::vector<ParameterRule> r;
    for (const ParameterGroup& g : groups()) r.insert(r.end(), g.rules.begin(), g.rules.end());
    return r;
  }();
  return rules;
}

const ParameterSpec* find_parameter(const std::string& key) {
  for (const auto& spec : parameter_table())
    if (spec.key == key) return &spec;
  return nullptr;
}

}  // namespace tunnelmap
