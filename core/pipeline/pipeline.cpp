#include "core/pipeline/pipeline.h"

#include <algorithm>
#include <chrono>
#include <string>

#include "core/util/error.h"

namespace tunnelmap {

// cloud_options, normal_options, grow_options, tunnel_options: beside their declarations
// (core/normals/cloud_options.cpp, normal_options.cpp, core/planes/grow_options.cpp,
// core/tunnel/tunnel_options.cpp).

Eigen::Vector3d resolve_up(const DepthFrame& frame, const Eigen::Vector3d& world_up,
                           const std::optional<Eigen::Vector3d>& camera_up) {
  if (frame.pose) return (frame.pose->linear().transpose() * world_up).normalized();
  if (camera_up && camera_up->norm() > 0) return camera_up->normalized();
  return -Eigen::Vector3d::UnitY();  // image-up: camera y points down the image
}

void check_frame_size(const DepthFrame& frame, const NormalOptions& normals) {
  const int window = std::max(3, normals.smoothing_px);  // the side estimate_normals uses
  if (frame.width >= window && frame.height >= window) return;
  throw InputError(frame.source, "image is " + std::to_string(frame.width) + "x" + std::to_string(frame.height) +
                                     " pixels, smaller than the " + std::to_string(window) + "x" +
                                     std::to_string(window) + " normal window (normals.smoothing_px)");
}

Pipeline::Pipeline(Parameters params) : params_(std::move(params)) { derive_options(); }

void Pipeline::set_params(const Parameters& params) {
  params_ = params;
  derive_options();
}

void Pipeline::derive_options() {
  cloud_ = cloud_options(params_);
  normals_ = normal_options(params_);
  grow_ = grow_options(params_);
  tunnel_ = tunnel_options(params_);
}

void Pipeline::run(const DepthFrame& frame, FrameResult& result, FrameScratch& scratch,
                   TunnelContext* context, Stage from) const {
  check_frame_size(frame, normals_);
  const auto start = std::chrono::steady_clock::now();
  if (from <= Stage::Cloud) {
    reset_timings(result.cloud.timings_ms);
    StageTimer t(result.cloud.timings_ms, "cloud");
    build_cloud(frame, cloud_, result.cloud, scratch.cloud);
  }
  if (from <= Stage::Normals) {
    result.cloud.timings_ms["normals"] = 0.0;
    if (needs_point_normals(grow_)) estimate_normals(normals_, result.cloud, scratch.normals);
    else result.cloud.normals.clear();  // keeps its capacity; no stale normals from another frame
  }
  if (from <= Stage::Planes) extract_planes(result.cloud, grow_, result.planes, scratch.planes);
  // In place: the map's vectors and strings keep their buffers (no allocation per frame).
  detect_tunnel(result.planes, resolve_up(frame, world_up_, camera_up_), tunnel_, context, result.map,
                scratch.tunnel);
  if (context && result.map.detected) context->accept(result.map);

  StageTimings& t = result.timings_ms;  // the same five keys every run: no allocation
  t["cloud"] = result.cloud.timings_ms.count("cloud") ? result.cloud.timings_ms.at("cloud") : 0.0;
  t["normals"] = result.cloud.timings_ms.count("normals") ? result.cloud.timings_ms.at("normals") : 0.0;
  t["planes"] = result.planes.timings_ms.count("planes") ? result.planes.timings_ms.at("planes") : 0.0;
  t["tunnel"] = result.map.timings_ms.count("tunnel") ? result.map.timings_ms.at("tunnel") : 0.0;
  t["total"] = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace tunnelmap
