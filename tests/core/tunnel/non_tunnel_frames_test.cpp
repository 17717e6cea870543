// Honest on scenes that are not tunnels: the real third-party frames (rooms, an office, boxes on
// a floor, a vaulted pedestrian tunnel; resources/real-frames/SOURCES.md and the shared copy's)
// never become a tunnel with the lab and field presets, with or without a design, and a design
// never makes a tunnel by itself: it fills a dimension the frame did not measure.
#include <gtest/gtest.h>

#include <filesystem>

#include "core/engine/frame_run.h"
#include "core/io/frame_source.h"
#include "core/tunnel/tunnel_options.h"
#include "core/util/build_paths.h"

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

TunnelMap map_of(const RealFrame& f, const Parameters& params) {
  ReadOptions opt;
  opt.intrinsics = f.intrinsics;
  const auto source = open_input(f.path, opt);
  RunSettings settings;
  settings.params = params;
  FrameRun run;
  run_frame(*source, 0, settings, run);
  return run.result.map;
}

Parameters with_design(Parameters p, double width_m, double height_m) {
  p.set(tunnel_keys::design_width_m, width_m);
  p.set(tunnel_keys::design_height_m, height_m);
  return p;
}

Parameters preset(const std::string& name) {
  Parameters p;
  p.load_json_file(std::string(TUNNELMAP_SOURCE_DIR) + "/resources/presets/" + name + ".json");
  return p;
}

std::string name_of(const RealFrame& f) { return fs::path(f.path).filename().string(); }

// The tunnel presets, with and without a design: no real frame is a tunnel, not even a partial one.
TEST(NonTunnelFrames, NeverBecomeATunnelWithTheTunnelPresetsWithOrWithoutADesign) {
  const std::vector<RealFrame> frames = real_frames();
  ASSERT_GE(frames.size(), 3u);
  const std::pair<const char*, Parameters> settings[] = {
      {"lab", preset("lab")},
      {"lab + design 0.82 x 1.30 m", with_design(preset("lab"), 0.82, 1.30)},
      {"field", preset("field")},
      {"field + design 1.20 x 1.80 m", with_design(preset("field"), 1.20, 1.80)},
  };
  for (const RealFrame& f : frames)
    for (const auto& [name, params] : settings) {
      const TunnelMap m = map_of(f, params);
      EXPECT_FALSE(m.detected) << name_of(f) << " with " << name << ": " << m.status << " " << m.reason;
    }
}

// At the defaults no real frame is an `ok` tunnel, and a design changes nothing: it fills a
// dimension a detected frame did not measure, it never makes a tunnel of a frame that is none.
// (Two of the frames are `partial` at the defaults, each from a small patch parallel to the
// floor: docs/tunnel-detection.md, "Scenes that are not tunnels".)
TEST(NonTunnelFrames, ADesignNeverMakesATunnelOfARealFrameAtTheDefaults) {
  const std::vector<RealFrame> frames = real_frames();
  for (const RealFrame& f : frames) {
    const TunnelMap plain = map_of(f, Parameters());
    const TunnelMap designed = map_of(f, with_design(Parameters(), 0.82, 1.30));
    EXPECT_NE(plain.status, TunnelStatus::Ok) << name_of(f);
    EXPECT_EQ(designed.status, plain.status) << name_of(f) << ": " << designed.reason;
    EXPECT_EQ(designed.detected, plain.detected) << name_of(f);
    if (!designed.detected) continue;
    // Whatever the status, a detected frame measured at least one dimension itself.
    EXPECT_TRUE(designed.width_measured() || designed.height_measured()) << name_of(f);
    EXPECT_EQ(designed.width_measured(), plain.width_measured()) << name_of(f);
    EXPECT_EQ(designed.height_measured(), plain.height_measured()) << name_of(f);
  }
}

}  // namespace
