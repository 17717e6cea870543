// The relevance table against the real pipeline: every parameter it calls unused for a method
// and growing order leaves a frame's plane labels and tunnel byte-identical when moved to the
// end of its range; and with the pixel-grid order the per-pixel normal window does change them
// (so the comparison can see a change).
#include <gtest/gtest.h>

#include "core/engine/frame_run.h"
#include "core/engine/parameter_relevance.h"
#include "core/planes/grow_options.h"
#include "core/report/results_json.h"
#include "core/normals/normal_options.h"
#include "core/util/build_paths.h"
#include "core/baselines/baseline_options.h"

using namespace tunnelmap;

namespace {

const std::string kLabSample = std::string(TUNNELMAP_TEST_DATA_DIR) + "/sample/lab";

struct Outcome {
  std::vector<std::int32_t> labels;
  nlohmann::json tunnel;
};

Outcome detect_first_frame(const Parameters& params, Method method) {
  const auto source = open_input(kLabSample, ReadOptions());
  RunSettings settings;
  settings.params = params;
  settings.method = method;
  FrameRun run;
  run_frame(*source, 0, settings, run);
  nlohmann::json j = detection_frame_json(0, run.frame.source, run.result);
  j.erase("timings_ms");
  return {run.result.planes.labels, j};
}

// `params` with `spec` moved to the far end of its range (max, or min when it is at max), or
// nullopt when no end satisfies the table's rules with the other values.
std::optional<Parameters> moved(Parameters params, const ParameterSpec& spec) {
  for (double v : {spec.max, spec.min}) {
    if (v == params.get(spec.key)) continue;
    try {
      params.set(spec.key, v);
      return params;
    } catch (const std::exception&) {
    }
  }
  return std::nullopt;
}

// Asserts that every parameter marked unused under (`base`, `method`) changes nothing.
int expect_unused_change_nothing(const Parameters& base, Method method) {
  const Outcome reference = detect_first_frame(base, method);
  int checked = 0;
  for (const ParameterSpec& spec : parameter_table()) {
    const ParameterRelevance r = parameter_relevance(spec, base, method);
    if (r.relevance == Relevance::Used) continue;
    EXPECT_FALSE(r.reason.empty()) << spec.key;
    const std::optional<Parameters> changed = moved(base, spec);
    if (!changed) continue;
    const Outcome other = detect_first_frame(*changed, method);
    EXPECT_TRUE(other.labels == reference.labels) << spec.key << " changed the plane labels";
    EXPECT_EQ(other.tunnel, reference.tunnel) << spec.key << " changed the tunnel";
    ++checked;
  }
  return checked;
}

}  // namespace

TEST(ParameterRelevance, UnusedWithCellsChangeNothing) {
  const Parameters cells;  // the defaults grow over 8 px cells
  ASSERT_GT(cells.get(grow_keys::cell_px), 0);
  EXPECT_EQ(parameter_relevance(*find_parameter(grow_keys::grid_step.key), cells, Method::Pgc).relevance,
            Relevance::GrowingOrder);
  EXPECT_EQ(parameter_relevance(*find_parameter(normal_keys::smoothing_px.key), cells, Method::Pgc).relevance,
            Relevance::GrowingOrder);
  EXPECT_EQ(parameter_relevance(*find_parameter(grow_keys::distance_mm.key), cells, Method::Pgc).relevance,
            Relevance::Used);
  // normals (2), neighbourhood, grid step, and the two baselines' keys
  EXPECT_GE(expect_unused_change_nothing(cells, Method::Pgc), 15);
}

TEST(ParameterRelevance, UnusedOnThePixelGridChangeNothingAndTheNormalWindowCounts) {
  Parameters grid;
  grid.set(grow_keys::cell_px, 0);
  grid.set(grow_keys::grid_step, 1);
  EXPECT_EQ(parameter_relevance(*find_parameter(normal_keys::smoothing_px.key), grid, Method::Pgc).relevance,
            Relevance::Used);
  EXPECT_EQ(parameter_relevance(*find_parameter(grow_keys::edge_on_pass.key), grid, Method::Pgc).relevance,
            Relevance::GrowingOrder);
  EXPECT_GE(expect_unused_change_nothing(grid, Method::Pgc), 1);
  Parameters wider = grid;
  wider.set(normal_keys::smoothing_px, 31);
  EXPECT_FALSE(detect_first_frame(wider, Method::Pgc).labels == detect_first_frame(grid, Method::Pgc).labels);
}

TEST(ParameterRelevance, TheBaselinesReadNoGrowingParameter) {
  Parameters quick;  // few trials: the comparison, not RANSAC's quality, is under test
  quick.set(baseline_keys::ransac_iterations, 2);
  quick.set(baseline_keys::ransac_sample_step, 4);
  for (const ParameterSpec& spec : parameter_table()) {
    const bool pgc_only = spec.key.rfind("grow.", 0) == 0 || spec.key.rfind("normals.", 0) == 0;
    const Relevance r = parameter_relevance(spec, quick, Method::Ransac).relevance;
    EXPECT_EQ(r == Relevance::OtherMethod, pgc_only || spec.key.rfind("qhull.", 0) == 0) << spec.key;
  }
  EXPECT_GE(expect_unused_change_nothing(quick, Method::Ransac), 15);
}
