#include "core/engine/run_settings.h"

#include "core/params/parameter_table.h"

namespace tunnelmap {

Eigen::Vector3d world_up(const FrameSource& source) {
  const Dataset* ds = source.dataset();
  return ds ? ds->up : Eigen::Vector3d::UnitZ();
}

MethodRunner make_method_runner(const FrameSource& source, const RunSettings& settings) {
  MethodRunner runner(settings.method, settings.params);
  runner.set_camera_up(settings.camera_up);
  runner.set_world_up(world_up(source));
  return runner;
}

Pipeline make_pipeline(const FrameSource& source, const RunSettings& settings) {
  Pipeline pipeline(settings.params);
  pipeline.set_camera_up(settings.camera_up);
  pipeline.set_world_up(world_up(source));
  return pipeline;
}

std::optional<Stage> first_changed_stage(const Parameters& a, const Parameters& b) {
  std::optional<Stage> first;
  for (const auto& spec : parameter_table())
    if (a.get(spec.key) != b.get(spec.key))
      if (!first || static_cast<int>(spec.stage) < static_cast<int>(*first)) first = spec.stage;
  return first;
}

}  // namespace tunnelmap
