// FrameScratch: the stages' buffers are owned by the caller, not hidden per thread. A result must
// not depend on what the scratch held before (frames of other sizes and scenes), copies of a
// result carry no buffers, and threads running one const Pipeline, each into its own result,
// get exactly the serial results.
#include <gtest/gtest.h>

#include <cstring>
#include <string>
#include <thread>
#include <vector>

#include "core/io/depth_png.h"
#include "core/pipeline/pipeline.h"
#include "core/report/results_json.h"
#include "core/sim/tunnel_simulator.h"
#include "core/util/build_paths.h"

using namespace tunnelmap;

namespace {

// The top-left w x h pixels of `f` (same camera centre in pixels, so the same rays).
DepthFrame crop(const DepthFrame& f, int w, int h) {
  DepthFrame c = f;
  c.width = w, c.height = h;
  c.intrinsics.width = w, c.intrinsics.height = h;
  c.depth.resize(static_cast<std::size_t>(w) * h);
  for (int v = 0; v < h; ++v)
    for (int u = 0; u < w; ++u)
      c.depth[static_cast<std::size_t>(v) * w + u] = f.depth[static_cast<std::size_t>(v) * f.width + u];
  c.rgb.clear();
  return c;
}

// A lab tunnel, a cropped (smaller) lab frame and a real office frame: different sizes, plane
// counts and wall sets, so every buffer is resized and refilled between them.
const std::vector<DepthFrame>& frames() {
  static const std::vector<DepthFrame> f = [] {
    SimConfig lab = SimConfig::from_preset("lab");
    lab.seed = 31;
    const TunnelSimulator sim(lab);
    ReadOptions opt;
    Intrinsics K;  // resources/real-frames/SOURCES.md
    K.fx = 525.0, K.fy = 525.0, K.cx = 320.0, K.cy = 240.0;
    opt.intrinsics = K;
    const std::string office = std::string(TUNNELMAP_TEST_DATA_DIR) + "/real-frames/pcl_office_depth.png";
    std::vector<DepthFrame> out{sim.render(0).frame, crop(sim.render(9).frame, 400, 300),
                                read_depth_png(office, opt)};
    for (std::size_t i = 0; i < out.size(); ++i) out[i].source = "frame" + std::to_string(i);
    return out;
  }();
  return f;
}

// `cell_px` -1 keeps the preset's growing order.
Pipeline lab_pipeline(int cell_px = -1) {
  Parameters params;
  params.load_json_file(std::string(TUNNELMAP_SOURCE_DIR) + "/resources/presets/lab.json");
  if (cell_px >= 0) params.set("grow.cell_px", cell_px);
  Pipeline p(params);
  p.set_world_up(Eigen::Vector3d::UnitZ());
  return p;
}

// Everything a run produces except timings: the CLI's numbers, the label image, the contours.
void expect_same_result(const FrameResult& got, const FrameResult& want, const std::string& what) {
  nlohmann::json a = detection_frame_json(0, "f", got), b = detection_frame_json(0, "f", want);
  a.erase("timings_ms"), b.erase("timings_ms");
  EXPECT_EQ(a.dump(), b.dump()) << what;
  EXPECT_TRUE(got.planes.labels == want.planes.labels) << what;
  ASSERT_EQ(got.planes.planes.size(), want.planes.planes.size()) << what;
  for (std::size_t i = 0; i < got.planes.planes.size(); ++i) {
    EXPECT_EQ(got.planes.planes[i].points, want.planes.planes[i].points) << what << " plane " << i;
    EXPECT_TRUE(got.planes.planes[i].contour == want.planes.planes[i].contour) << what << " plane " << i;
  }
  // Bit for bit (NaN where no normal, so compared as bytes); the cell order computes none.
  ASSERT_EQ(got.cloud.normals.size(), want.cloud.normals.size()) << what;
  if (!got.cloud.normals.empty()) {
    EXPECT_EQ(std::memcmp(got.cloud.normals.data(), want.cloud.normals.data(),
                          got.cloud.normals.size() * sizeof(Eigen::Vector3f)),
              0)
        << what;
  }
}

// Both growing orders: the cells (the default) and the pixel grid, whose per-pixel normals are
// compared bit for bit too.
void expect_results_independent_of_the_scratch(int cell_px) {
  const Pipeline pipeline = lab_pipeline(cell_px);
  std::vector<FrameResult> fresh;  // each with scratch of its own, used once
  for (const DepthFrame& f : frames()) fresh.push_back(pipeline.run(f));
  // The frames really differ: sizes, and a detected tunnel against a scene that is none.
  ASSERT_EQ(fresh[1].cloud.width, 400);
  EXPECT_TRUE(fresh[0].map.detected);
  EXPECT_FALSE(fresh[2].map.detected);
  EXPECT_GT(fresh[2].planes.planes.size(), 2 * fresh[0].planes.planes.size());

  FrameResult reused;  // one result and its scratch through every frame, larger and smaller
  for (std::size_t i : {0u, 1u, 2u, 1u, 0u, 2u}) {
    pipeline.run(frames()[i], reused);
    expect_same_result(reused, fresh[i], "frame " + std::to_string(i));
  }
  // A caller-held scratch (as a SequenceRunner worker keeps) shared by results of other frames.
  FrameScratch scratch;
  std::vector<FrameResult> slots(2);
  for (std::size_t i : {2u, 0u, 1u}) {
    pipeline.run(frames()[i], slots[i % 2], scratch);
    expect_same_result(slots[i % 2], fresh[i], "caller scratch, frame " + std::to_string(i));
  }
}

}  // namespace

TEST(FrameScratch, ResultsDoNotDependOnWhatTheScratchHeldBefore) {
  for (const int cell_px : {8, 0}) {
    SCOPED_TRACE("grow.cell_px " + std::to_string(cell_px));
    expect_results_independent_of_the_scratch(cell_px);
  }
}

TEST(FrameScratch, CopiesOfAResultCarryNoBuffers) {
  const Pipeline pipeline = lab_pipeline(0);  // the pixel grid: the order with per-pixel normals
  FrameResult r;
  pipeline.run(frames()[0], r);
  // A VGA frame's normals stage keeps three one-byte images of 640 x 480.
  ASSERT_EQ(r.scratch.normals.edges.size(), 640u * 480u);
  ASSERT_FALSE(r.scratch.planes.coarse.points.empty());

  const FrameResult copy = r;
  EXPECT_TRUE(copy.planes.labels == r.planes.labels);  // the value is copied
  EXPECT_TRUE(copy.scratch.normals.edges.empty());      // the buffers are not
  EXPECT_TRUE(copy.scratch.planes.coarse.points.empty());
  EXPECT_EQ(r.scratch.normals.edges.size(), 640u * 480u);  // nor taken from the original

  // Assigning into a used result keeps its own buffers for its next frame.
  FrameResult target;
  pipeline.run(frames()[1], target);
  const std::uint8_t* own = target.scratch.normals.edges.data();
  target = r;
  EXPECT_EQ(target.scratch.normals.edges.data(), own);
  EXPECT_EQ(target.scratch.normals.edges.size(), 400u * 300u);

  // A one-off result returned by value holds no scratch.
  const FrameResult once = pipeline.run(frames()[0]);
  EXPECT_TRUE(once.scratch.normals.edges.empty());
  EXPECT_TRUE(once.scratch.planes.coarse.points.empty());
}

TEST(FrameScratch, CopiesOfACellOrderResultCarryNoCellGrid) {
  const Pipeline pipeline = lab_pipeline(8);
  FrameResult r;
  pipeline.run(frames()[0], r);
  ASSERT_EQ(r.scratch.planes.cells.grid.cells.size(), 80u * 60u);  // 8-pixel cells of a VGA frame
  EXPECT_TRUE(r.scratch.normals.edges.empty()) << "the cell order needs no per-pixel normals";
  const FrameResult copy = r;
  EXPECT_TRUE(copy.planes.labels == r.planes.labels);
  EXPECT_TRUE(copy.scratch.planes.cells.grid.cells.empty());
  EXPECT_EQ(r.scratch.planes.cells.grid.cells.size(), 80u * 60u);
}

TEST(FrameScratch, ThreadsSharingOneConstPipelineGetTheSerialResults) {
  const Pipeline pipeline = lab_pipeline();
  std::vector<FrameResult> serial;
  for (const DepthFrame& f : frames()) serial.push_back(pipeline.run(f));

  // Two threads, each with its own result, interleaving the frames in opposite orders.
  constexpr int kRounds = 3;
  std::vector<std::vector<FrameResult>> got(2);
  std::vector<std::thread> threads;
  for (int t = 0; t < 2; ++t)
    threads.emplace_back([&, t] {
      FrameResult r;
      for (int k = 0; k < kRounds; ++k)
        for (std::size_t j = 0; j < frames().size(); ++j) {
          const std::size_t i = t == 0 ? j : frames().size() - 1 - j;
          pipeline.run(frames()[i], r);
          got[t].push_back(r);  // a copy: its value only
        }
    });
  for (std::thread& th : threads) th.join();

  for (int t = 0; t < 2; ++t) {
    ASSERT_EQ(got[t].size(), kRounds * frames().size());
    for (std::size_t n = 0; n < got[t].size(); ++n) {
      const std::size_t j = n % frames().size();
      const std::size_t i = t == 0 ? j : frames().size() - 1 - j;
      expect_same_result(got[t][n], serial[i], "thread " + std::to_string(t) + " run " + std::to_string(n));
    }
  }
}
