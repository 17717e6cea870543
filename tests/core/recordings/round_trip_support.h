#pragma once
// Shared by the recording round-trip tests: a small simulated posed sequence, and the checks
// that a recording of it reads back as the same frames and detections.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "core/io/dataset.h"
#include "core/io/frame_source.h"
#include "core/sim/sim_dataset_writer.h"
#include "tests/support/cli_runner.h"
#include "tests/support/io_temp_dir.h"

namespace tunnelmap::testing {

// Four frames of the default simulated tunnel, posed, with colour.
struct SimulatedSequence {
  IoTempDir tmp;
  std::string dataset_dir;
  Dataset ds;
  SimulatedSequence() : dataset_dir(tmp.file("sim")) {
    SimConfig config;
    config.frames = 4;
    write_sim_dataset(dataset_dir, config);
    ds = read_dataset(dataset_dir);
  }
};


// Depth, intrinsics, pose (1e-6) and colour of every frame, read back from `bag`.
inline void expect_same_frames(const Dataset& ds, const std::string& bag) {
  const auto source = open_input(bag, ReadOptions{});
  ASSERT_EQ(source->size(), ds.frames.size());
  for (std::size_t i = 0; i < ds.frames.size(); ++i) {
    SCOPED_TRACE(i);
    const DepthFrame want = ds.load_frame(i), got = source->load(i);
    ASSERT_EQ(got.width, want.width);
    ASSERT_EQ(got.height, want.height);
    EXPECT_EQ(got.intrinsics.fx, want.intrinsics.fx);
    EXPECT_EQ(got.intrinsics.cy, want.intrinsics.cy);
    std::size_t differing = 0;
    for (std::size_t k = 0; k < want.depth.size(); ++k)
      differing += std::abs(got.depth_m(k % want.width, k / want.width) - want.depth_m(k % want.width, k / want.width)) > 1e-6f;
    EXPECT_EQ(differing, 0u);
    ASSERT_TRUE(got.pose.has_value());
    EXPECT_LT((got.pose->matrix() - want.pose->matrix()).cwiseAbs().maxCoeff(), 1e-6);
    EXPECT_EQ(got.rgb, want.rgb);  // colour paired by timestamp
  }
}

// `COMMAND INPUT --json` (detect by default) through the real CLI.
inline nlohmann::json detect_json(const IoTempDir& tmp, const std::string& input, const std::string& name,
                                  const std::string& command = "detect") {
  const std::string out = tmp.file(name + ".json");
  const CliRun r = run_cli(command + " " + input + " --quiet --json " + out);
  EXPECT_EQ(r.exit_code, 0) << r.err;
  return nlohmann::json::parse(slurp(out));
}

// The same statuses, widths and heights within 0.5 mm, and (map) poses within 1e-6.
inline void expect_same_detections(const nlohmann::json& a, const nlohmann::json& b) {
  ASSERT_EQ(a["frames"].size(), b["frames"].size());
  for (std::size_t i = 0; i < a["frames"].size(); ++i) {
    const auto& fa = a["frames"][i];
    const auto& fb = b["frames"][i];
    EXPECT_EQ(fa["status"], fb["status"]) << i;
    for (const char* key : {"width_m", "height_m"}) {
      ASSERT_EQ(fa[key].is_null(), fb[key].is_null()) << i << key;
      if (!fa[key].is_null()) EXPECT_NEAR(fa[key].get<double>(), fb[key].get<double>(), 0.0005) << i << key;
    }
    ASSERT_EQ(fa.contains("camera_to_world"), fb.contains("camera_to_world"));
    if (!fa.contains("camera_to_world")) continue;
    const auto pa = fa["camera_to_world"].flatten(), pb = fb["camera_to_world"].flatten();
    ASSERT_EQ(pa.size(), pb.size());
    for (auto it = pa.begin(); it != pa.end(); ++it)
      if (it->is_number()) EXPECT_NEAR(it->get<double>(), pb[it.key()].get<double>(), 1e-6) << i << it.key();
  }
}

}  // namespace tunnelmap::testing
