#pragma once
// One frame viewed on its own (the GUI's current frame, `render`'s frame): loaded, run through
// the method, and re-run after a parameter change only from the first stage the change affects.
// A posed frame is placed by its pose as a sequence's only frame would be (its own parts along
// the tunnel, as `detect` on that frame gives them); the context of other frames comes from
// RunEngine.
#include <cstddef>

#include "core/engine/run_settings.h"
#include "core/pipeline/pipeline.h"

namespace tunnelmap {

struct FrameRun {
  DepthFrame frame;
  FrameResult result;
};

// Frame `index` of `source` into `run`. `cached`: `run` already holds this frame's result made
// with those settings, so only the stages from the first changed one re-run (PG&C; a baseline
// re-runs the whole frame). Returns the first stage that ran. InputError for a frame that does
// not exist or cannot be read.
Stage run_frame(const FrameSource& source, std::size_t index, const RunSettings& settings, FrameRun& run,
                const RunSettings* cached = nullptr);

}  // namespace tunnelmap
