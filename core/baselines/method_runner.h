#pragma once
// MethodRunner: one frame through the selected method, with the same FrameResult as the PG&C
// pipeline (cloud, planes, map, timings) so that CLI, GUI and evaluation treat all three alike.
#include <optional>

#include "core/baselines/baseline_options.h"
#include "core/baselines/method.h"
#include "core/baselines/qhull_tunnel.h"
#include "core/baselines/ransac_lse.h"
#include "core/pipeline/pipeline.h"

namespace tunnelmap {

class MethodRunner {
 public:
  // Without `baselines`, the baselines' options come from `params` (ransac.*, qhull.*).
  explicit MethodRunner(Method method, Parameters params = Parameters(),
                        std::optional<BaselineOptions> baselines = std::nullopt);

  Method method() const { return method_; }
  const Parameters& params() const { return pipeline_.params(); }
  BaselineOptions& baselines() { return baselines_; }
  void set_world_up(const Eigen::Vector3d& up);
  void set_camera_up(const std::optional<Eigen::Vector3d>& up);

  // Timings: "cloud", "normals" (0 for the baselines), "planes", "tunnel", "total". A detected
  // map is accepted into `context` (may be null) exactly like Pipeline::run does.
  void run(const DepthFrame& frame, FrameResult& result, TunnelContext* context = nullptr) const;

 private:
  Method method_;
  Pipeline pipeline_;
  BaselineOptions baselines_;
  Eigen::Vector3d world_up_ = Eigen::Vector3d::UnitZ();
  std::optional<Eigen::Vector3d> camera_up_;
};

}  // namespace tunnelmap
