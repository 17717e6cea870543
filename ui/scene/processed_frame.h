#pragma once
// One frame read from an input and run through the engine (core/engine/frame_run.h): what the
// scene draws. Shared by the GUI and tunnelmap-render so both process inputs the same way.
#include "core/engine/frame_run.h"
#include "ui/scene/scene_data.h"

namespace tunnelmap::scene {

struct ProcessedFrame : FrameRun {
  SceneData scene_data() const {
    SceneData d;
    d.frame = &frame;
    d.cloud = &result.cloud;
    d.planes = &result.planes;
    d.map = &result.map;
    return d;
  }
};

}  // namespace tunnelmap::scene
