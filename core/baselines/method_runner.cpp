#include "core/baselines/method_runner.h"

#include <chrono>

namespace tunnelmap {

MethodRunner::MethodRunner(Method method, Parameters params, std::optional<BaselineOptions> baselines)
    : method_(method),
      pipeline_(std::move(params)),
      baselines_(baselines ? *baselines : baseline_options(pipeline_.params())) {}

void MethodRunner::set_world_up(const Eigen::Vector3d& up) {
  world_up_ = up.normalized();
  pipeline_.set_world_up(up);
}

void MethodRunner::set_camera_up(const std::optional<Eigen::Vector3d>& up) {
  camera_up_ = up;
  pipeline_.set_camera_up(up);
}

void MethodRunner::run(const DepthFrame& frame, FrameResult& result, TunnelContext* context) const {
  if (method_ == Method::Pgc) {
    pipeline_.run(frame, result, context);
    return;
  }
  const Parameters& p = pipeline_.params();
  check_frame_size(frame, normal_options(p));  // the same frames as PG&C are refused
  const auto start = std::chrono::steady_clock::now();
  result.cloud.timings_ms.clear();
  {
    StageTimer t(result.cloud.timings_ms, "cloud");
    build_cloud(frame, cloud_options(p), result.cloud);
  }
  const Eigen::Vector3d up = resolve_up(frame, world_up_, camera_up_);
  if (method_ == Method::Ransac) {
    result.planes = ransac_lse_planes(result.cloud, baselines_.ransac).planes;
    result.map = detect_tunnel(result.planes, up, tunnel_options(p), context);
  } else {
    result.planes = PlaneSegments();
    result.planes.width = result.cloud.width;
    result.planes.height = result.cloud.height;
    result.map = qhull_tunnel(result.cloud, up, tunnel_options(p), context, baselines_.qhull).map;
  }
  if (context && result.map.detected) context->accept(result.map);
  StageTimings& t = result.timings_ms;
  t.clear();
  t["cloud"] = result.cloud.timings_ms.at("cloud");
  t["normals"] = 0.0;
  t["planes"] = result.planes.timings_ms.count("planes") ? result.planes.timings_ms.at("planes") : 0.0;
  t["tunnel"] = result.map.timings_ms.count("tunnel") ? result.map.timings_ms.at("tunnel") : 0.0;
  t["total"] = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace tunnelmap
