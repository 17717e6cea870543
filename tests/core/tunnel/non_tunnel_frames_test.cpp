// Honest on scenes that are not tunnels: the real third-party frames (rooms, an office, boxes on
// a floor, a vaulted pedestrian tunnel; resources/real-frames/SOURCES.md and the shared copy's)
// never become an `ok` or `partial` tunnel, at the defaults, with a design set, nor with the
// lab and field presets. A design fills a dimension the frame did not measure; it never makes a
// tunnel by itself.
#include <gtest/gtest.h>

#include <filesystem>

#include "core/engine/frame_run.h"
#include "core/io/frame_source.h"
#include "core/tunnel/tunnel_options.h"

using namespace tunnelmap;

namespace {

namespace fs = std::filesystem;

struct RealFrame {
  std::string path;
  Intrinsics intrinsics;
};

Intrinsics intrinsics(double fx, double fy, double cx, double cy) {
  Intrinsics k;
  k.fx = fx, k.fy = fy, k.cx = cx, k.cy = cy;
  return k;
}

// Every real frame at hand: the bundled ones, and the shared data set's when present (CI keeps
// it beside the checkout).
std::vector<RealFrame> real_frames() {
  const std::string bundled = std::string(TUNNELMAP_SOURCE_DIR) + "/resources/real-frames/";
  std::vector<RealFrame> frames = {
      {bundled + "cape_tunnel_depth.png", intrinsics(575.927, 576.408, 315.150, 230.586)},
      {bundled + "pcl_office_depth.png", intrinsics(525, 525, 320, 240)},
      {bundled + "rtabmap_lab_depth_17.png", intrinsics(525, 525, 319.5, 239.5)},
  };
  const fs::path shared = fs::path(TUNNELMAP_SOURCE_DIR) / "../shared/data/real-frames/realsense_d435";
  if (fs::is_directory(shared))
    for (const auto& e : fs::directory_iterator(shared))
      if (e.path().extension() == ".png")
        frames.push_back({e.path().string(), intrinsics(617.25, 617.5486, 317.3921, 245.9802)});
  return frames;
}

TunnelStatus status_of(const RealFrame& f, const Parameters& params) {
  ReadOptions opt;
  opt.intrinsics = f.intrinsics;
  const auto source = open_input(f.path, opt);
  RunSettings settings;
  settings.params = params;
  FrameRun run;
  run_frame(*source, 0, settings, run);
  if (run.result.map.detected) {
    // Whatever the status, a detected frame measured at least one dimension itself.
    EXPECT_TRUE(run.result.map.width_measured() || run.result.map.height_measured()) << f.path;
  }
  return run.result.map.status;
}

Parameters with_design(Parameters p, double width_m, double height_m) {
  p.set(tunnel_keys::design_width_m, width_m);
  p.set(tunnel_keys::design_height_m, height_m);
  return p;
}

TEST(NonTunnelFrames, NeverBecomeATunnelAtTheDefaultsNorWithADesign) {
  const std::vector<RealFrame> frames = real_frames();
  ASSERT_GE(frames.size(), 3u);
  Parameters lab, field;
  lab.load_json_file(std::string(TUNNELMAP_SOURCE_DIR) + "/resources/presets/lab.json");
  field.load_json_file(std::string(TUNNELMAP_SOURCE_DIR) + "/resources/presets/field.json");
  const std::pair<const char*, Parameters> settings[] = {
      {"defaults", Parameters()},
      {"defaults + design 0.82 x 1.30 m", with_design(Parameters(), 0.82, 1.30)},
      {"lab + design 0.82 x 1.30 m", with_design(lab, 0.82, 1.30)},
      {"field + design 1.20 x 1.80 m", with_design(field, 1.20, 1.80)},
  };
  for (const RealFrame& f : frames)
    for (const auto& [name, params] : settings) {
      const TunnelStatus s = status_of(f, params);
      EXPECT_NE(s, TunnelStatus::Ok) << fs::path(f.path).filename() << " with " << name;
      EXPECT_NE(s, TunnelStatus::Partial) << fs::path(f.path).filename() << " with " << name;
    }
}

}  // namespace
