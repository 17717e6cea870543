#include "core/engine/frame_run.h"

#include "core/engine/frame_context.h"
#include "core/util/error.h"

namespace tunnelmap {

namespace {
// The stage to re-run from when `run` holds the result of `cached` on the same frame.
Stage rerun_from(const RunSettings& settings, const RunSettings& cached) {
  if (settings.method != Method::Pgc || cached.method != Method::Pgc) return Stage::Cloud;
  if (settings.camera_up != cached.camera_up) return Stage::Cloud;
  // Nothing changed: the tunnel stage is the cheapest complete re-run.
  return first_changed_stage(cached.params, settings.params).value_or(Stage::Tunnel);
}
// A posed frame as a sequence of that frame alone gets it (`detect` on it): placed along the
// tunnel by its pose, with its own parts (the sections it sees), and no other frame's context.
// The convex-hull baseline checks its context inside its fit; alone, it has none.
void place_by_pose(const FrameSource& source, std::size_t index, const RunSettings& settings, FrameRun& run) {
  if (!run.frame.pose || settings.method == Method::Qhull) return;
  FrameContext alone(settings.params, world_up(source));
  alone.apply(static_cast<int>(index), run.result, run.frame.pose, run.frame.gravity);
}

}  // namespace

Stage run_frame(const FrameSource& source, std::size_t index, const RunSettings& settings, FrameRun& run,
                const RunSettings* cached) {
  if (cached) {
    const Stage from = rerun_from(settings, *cached);
    if (from != Stage::Cloud) {
      make_pipeline(source, settings).run(run.frame, run.result, nullptr, from);
      place_by_pose(source, index, settings, run);
      return from;
    }
  }
  if (index >= source.size())
    throw InputError(source.size() ? source.describe(0) : std::string(),
                     "frame " + std::to_string(index) + " does not exist (the input has " +
                         std::to_string(source.size()) + ")");
  run.frame = source.load(index);
  make_method_runner(source, settings).run(run.frame, run.result, nullptr);
  place_by_pose(source, index, settings, run);
  return Stage::Cloud;
}

}  // namespace tunnelmap
