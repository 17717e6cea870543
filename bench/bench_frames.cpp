#include "bench/bench_frames.h"

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
}  // namespace

const std::vector<NamedFrame>& bench_frames() {
  static const std::vector<NamedFrame> frames = [] {
    std::vector<NamedFrame> f;
    SimConfig lab = SimConfig::from_preset("lab");
    lab.seed = 101;
    f.push_back({"sim_lab", TunnelSimulator(lab).render(0).frame, true});
    SimConfig field = SimConfig::from_preset("field");
    field.seed = 202;
    field.distance_to_manhole_m = 3.0;
    f.push_back({"sim_field_3m", TunnelSimulator(field).render(0).frame, true});
    // Intrinsics from resources/real-frames/SOURCES.md.
    f.push_back({"real_cape_tunnel", real_frame("cape_tunnel_depth.png", 575.927, 576.408, 315.150, 230.586), false});
    f.push_back({"real_pcl_office", real_frame("pcl_office_depth.png", 525, 525, 320, 240), false});
    f.push_back({"real_rtabmap_lab", real_frame("rtabmap_lab_depth_17.png", 525, 525, 319.5, 239.5), false});
    return f;
  }();
  return frames;
}

}  // namespace tunnelmap::bench
