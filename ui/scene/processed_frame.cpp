#include "ui/scene/processed_frame.h"

#include "core/util/error.h"

namespace tunnelmap::scene {

Pipeline make_pipeline(const FrameSource& source, const Parameters& params) {
  Pipeline pipeline(params);
  if (const Dataset* ds = source.dataset()) pipeline.set_world_up(ds->up);
  return pipeline;
}

ProcessedFrame process_frame(const FrameSource& source, std::size_t index, const Pipeline& pipeline,
                             TunnelContext* context) {
  if (index >= source.size())
    throw InputError(source.size() ? source.describe(0) : std::string(),
                     "frame " + std::to_string(index) + " does not exist (the input has " +
                         std::to_string(source.size()) + ")");
  ProcessedFrame out;
  out.frame = source.load(index);
  pipeline.run(out.frame, out.result, context);
  return out;
}

}  // namespace tunnelmap::scene
