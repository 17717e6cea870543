#include "core/pipeline/pipeline.h"

#include <algorithm>
#include <chrono>
#include <string>

#include "core/util/error.h"

namespace tunnelmap {

CloudOptions cloud_options(const Parameters& p) {
  CloudOptions o;
  o.min_range_m = p.get("cloud.min_range_m");
  o.max_range_m = p.get("cloud.max_range_m");
  return o;
}

NormalOptions normal_options(const Parameters& p) {
  NormalOptions o;
  o.smoothing_px = p.get_int("normals.smoothing_px");
  o.max_depth_change = p.get("normals.max_depth_change");
  return o;
}

GrowOptions grow_options(const Parameters& p) {
  GrowOptions o;
  o.angle_deg = p.get("grow.angle_deg");
  o.distance_m = p.get("grow.distance_mm") / 1000.0;
  o.candidate_distance_m = p.get("grow.candidate_distance_mm") / 1000.0;
  o.neighbourhood_n = p.get_int("grow.neighbourhood_n");
  o.min_points = p.get_int("grow.min_points");
  o.min_area_m2 = p.get("grow.min_area_m2");
  o.refit_normal = p.get_int("grow.refit_normal") != 0;
  o.grid_step = p.get_int("grow.grid_step");
  o.edge_on_pass = p.get_int("grow.edge_on_pass") != 0;
  return o;
}

TunnelOptions tunnel_options(const Parameters& p) {
  TunnelOptions o;
  o.class_angle_deg = p.get("tunnel.class_angle_deg");
  o.outlier_bin_deg = p.get("tunnel.outlier_bin_deg");
  o.outlier_max_deg = p.get("tunnel.outlier_max_deg");
  o.zone_cluster_m = p.get("tunnel.zone_cluster_mm") / 1000.0;
  o.min_cluster_points = p.get_int("tunnel.min_cluster_points");
  o.zone_support_ref_m = p.get("tunnel.zone_support_ref_m");
  o.zone_gap_ref_m = p.get("tunnel.zone_gap_ref_m");
  o.context_tolerance_m = p.get("tunnel.context_tolerance_mm") / 1000.0;
  o.max_pair_angle_deg = p.get("tunnel.max_pair_angle_deg");
  o.width_min_m = p.get("tunnel.width_min_m");
  o.width_max_m = p.get("tunnel.width_max_m");
  o.height_min_m = p.get("tunnel.height_min_m");
  o.height_max_m = p.get("tunnel.height_max_m");
  o.forbidden_band_m = p.get("zones.forbidden_band_m");
  o.max_symmetric_step_m = p.get("tunnel.symmetric_step_max_mm") / 1000.0;
  o.design_width_m = p.get("tunnel.design_width_m");
  o.design_height_m = p.get("tunnel.design_height_m");
  return o;
}

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

void Pipeline::run(const DepthFrame& frame, FrameResult& result, TunnelContext* context,
                   Stage from) const {
  check_frame_size(frame, normals_);
  const auto start = std::chrono::steady_clock::now();
  if (from <= Stage::Cloud) {
    reset_timings(result.cloud.timings_ms);
    StageTimer t(result.cloud.timings_ms, "cloud");
    build_cloud(frame, cloud_, result.cloud);
  }
  if (from <= Stage::Normals) {
    result.cloud.timings_ms["normals"] = 0.0;
    estimate_normals(normals_, result.cloud);
  }
  if (from <= Stage::Planes) extract_planes(result.cloud, grow_, result.planes);
  // In place: the map's vectors and strings keep their buffers (no allocation per frame).
  detect_tunnel(result.planes, resolve_up(frame, world_up_, camera_up_), tunnel_, context, result.map);
  if (context && result.map.detected) context->accept(result.map);

  StageTimings& t = result.timings_ms;  // the same five keys every run: no allocation
  t["cloud"] = result.cloud.timings_ms.count("cloud") ? result.cloud.timings_ms.at("cloud") : 0.0;
  t["normals"] = result.cloud.timings_ms.count("normals") ? result.cloud.timings_ms.at("normals") : 0.0;
  t["planes"] = result.planes.timings_ms.count("planes") ? result.planes.timings_ms.at("planes") : 0.0;
  t["tunnel"] = result.map.timings_ms.count("tunnel") ? result.map.timings_ms.at("tunnel") : 0.0;
  t["total"] = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace tunnelmap
