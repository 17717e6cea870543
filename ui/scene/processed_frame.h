#pragma once
// One frame read from an input and run through the pipeline: what the scene draws. Shared by
// the GUI and tunnelmap-render so both process inputs the same way.
#include <memory>
#include <string>

#include "core/io/frame_source.h"
#include "core/pipeline/pipeline.h"
#include "ui/scene/scene_data.h"

namespace tunnelmap::scene {

struct ProcessedFrame {
  DepthFrame frame;
  FrameResult result;

  SceneData scene_data() const {
    SceneData d;
    d.frame = &frame;
    d.cloud = &result.cloud;
    d.planes = &result.planes;
    d.map = &result.map;
    return d;
  }
};

// A pipeline configured for `source` (its dataset's world up, when it has one).
Pipeline make_pipeline(const FrameSource& source, const Parameters& params);

// Loads frame `index` of `source` and runs the whole pipeline on it. InputError on bad data.
ProcessedFrame process_frame(const FrameSource& source, std::size_t index, const Pipeline& pipeline,
                             TunnelContext* context = nullptr);

}  // namespace tunnelmap::scene
