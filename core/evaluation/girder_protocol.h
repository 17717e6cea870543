#pragma once
// The whole-girder evaluation (`tunnelmap-cli evaluate --protocol girders`): a family of random
// girders (core/evaluation/girder_family.h) is simulated, written as datasets, mapped as `map`
// maps them and scored against the truth; the report gives every girder's result and the
// distributions over the family (mean, p95, worst, failure counts), split by exact and drifted
// poses. See docs/tunnel-map.md.
#include <functional>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "core/evaluation/girder_family.h"
#include "core/evaluation/girder_scoring.h"

namespace tunnelmap {

struct GirderProtocolOptions {
  int count = 30;
  unsigned seed = 1;
  GirderRanges ranges;
  std::string presets_dir;             // lab.json and field.json
  std::vector<std::string> overrides;  // KEY=VALUE on top of each girder's preset
  std::string work_dir;                // the datasets are written (and removed) below it
  std::vector<int> only;               // the family's girders to run, by index (empty: all)
  std::string keep_dir;                // when set, each girder's dataset stays as keep_dir/girder-N
  bool refine_poses = true;
  std::function<void(const std::string&)> progress;  // one line per girder, may be empty
};

struct GirderResult {
  GirderDraw draw;
  GirderScore score;
  int frames = 0;
};

std::vector<GirderResult> run_girders(const GirderProtocolOptions& options);

// The report: {"protocol","count","seed","ranges","girders":[...],"distributions":{...}}.
nlohmann::json girders_json(const std::vector<GirderResult>& results, const GirderProtocolOptions& options);
std::string girders_markdown(const nlohmann::json& report);

}  // namespace tunnelmap
