#include "bench/bench_frames.h"
#include "core/util/build_paths.h"

#include <limits>

#include "core/io/depth_png.h"
#include "core/sim/tunnel_simulator.h"

namespace tunnelmap::bench {

namespace {
DepthFrame real_frame(const std::string& file, double fx, double fy, double cx, double cy) {
  ReadOptions opt;
  Intrinsics K;
  K.fx = fx, K.fy = fy, K.cx = cx, K.cy = cy;
  opt.intrinsics = K;
  return read_depth_png(std::string(TUNNELMAP_SOURCE_DIR) + "/resources/real-frames/" + file, opt);
}

NamedFrame simulated(const std::string& name, const SimConfig& config) {
  const TunnelSimulator sim(config);
  SimFrame s = sim.render(0);
  NamedFrame nf{name, std::move(s.frame), true, {}, s.surface_id};
  const Eigen::Matrix3f to_camera = nf.frame.pose->linear().transpose().cast<float>();
  const float nan = std::numeric_limits<float>::quiet_NaN();
  nf.true_normals.assign(s.surface_id.size(), Eigen::Vector3f(nan, nan, nan));
  for (std::size_t i = 0; i < s.surface_id.size(); ++i)
    if (const SimSurface* surface = sim.surface(s.surface_id[i]))
      nf.true_normals[i] = to_camera * surface->normal_world.cast<float>();
  return nf;
}
}  // namespace

const std::vector<NamedFrame>& bench_frames() {
  static const std::vector<NamedFrame> frames = [] {
    std::vector<NamedFrame> f;
    SimConfig lab = SimConfig::from_preset("lab");
    lab.seed = 101;
    f.push_back(simulated("sim_lab", lab));
    SimConfig field = SimConfig::from_preset("field");
    field.seed = 202;
    field.distance_to_manhole_m = 3.0;
    f.push_back(simulated("sim_field_3m", field));
    // Intrinsics from resources/real-frames/SOURCES.md.
    f.push_back({"real_cape_tunnel", real_frame("cape_tunnel_depth.png", 575.927, 576.408, 315.150, 230.586), false, {}, {}});
    f.push_back({"real_pcl_office", real_frame("pcl_office_depth.png", 525, 525, 320, 240), false, {}, {}});
    f.push_back({"real_rtabmap_lab", real_frame("rtabmap_lab_depth_17.png", 525, 525, 319.5, 239.5), false, {}, {}});
    return f;
  }();
  return frames;
}

}  // namespace tunnelmap::bench
