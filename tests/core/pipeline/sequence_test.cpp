// SequenceRunner: parallel results equal the serial pipeline's (same JSON numbers, the tunnel
// context applied in frame order), frame errors are delivered in order without stopping the
// others, and early stops, cancellation and exceptions never hang or terminate the process.
#include <gtest/gtest.h>

#include <atomic>
#include <mutex>
#include <stdexcept>

#include "core/pipeline/sequence_runner.h"
#include "core/report/results_json.h"
#include "core/sim/tunnel_simulator.h"
#include "core/util/build_paths.h"
#include "core/util/error.h"

using namespace tunnelmap;

namespace {

// Frames held in memory; load() hands out copies like a file reader would. Frames listed in
// `bad` fail to load with an InputError.
class MemorySource : public FrameSource {
 public:
  explicit MemorySource(std::vector<DepthFrame> frames, std::vector<std::size_t> bad = {})
      : frames_(std::move(frames)), bad_(std::move(bad)) {}
  std::size_t size() const override { return frames_.size(); }
  DepthFrame load(std::size_t i) const override {
    {
      std::lock_guard<std::mutex> lock(mutex_);
      load_order.push_back(i);
    }
    for (std::size_t b : bad_)
      if (b == i) throw InputError("frame" + std::to_string(i) + ".png", "not a PNG file");
    return frames_[i];
  }
  std::string describe(std::size_t i) const override { return "frame " + std::to_string(i); }

  mutable std::vector<std::size_t> load_order;

 private:
  std::vector<DepthFrame> frames_;
  std::vector<std::size_t> bad_;
  mutable std::mutex mutex_;
};

// Two tunnels in one sequence: lab frames (0.82 m wide) with frames of a 0.90 m tunnel mixed in.
// The context of the first detected frames rejects the others, so every result depends on the
// order the context is applied in.
const std::vector<DepthFrame>& mixed_sequence() {
  static const std::vector<DepthFrame> frames = [] {
    SimConfig lab = SimConfig::from_preset("lab");
    lab.seed = 21;
    SimConfig wide = lab;
    wide.width_m = 0.90;
    wide.seed = 22;
    const TunnelSimulator a(lab), b(wide);
    std::vector<DepthFrame> f;
    for (int i : {0, 12, 25}) f.push_back(a.render(i).frame);
    f.insert(f.begin() + 1, b.render(3).frame);
    f.push_back(b.render(15).frame);
    f.push_back(a.render(7).frame);
    for (std::size_t i = 0; i < f.size(); ++i) f[i].source = "sim/" + std::to_string(i) + ".png";
    return f;
  }();
  return frames;
}

Pipeline lab_pipeline() {
  Parameters params;
  params.load_json_file(std::string(TUNNELMAP_SOURCE_DIR) + "/resources/presets/lab.json");
  Pipeline p(params);
  p.set_world_up(Eigen::Vector3d::UnitZ());
  return p;
}

// The frame's JSON without its timings: every number the CLI writes that must not depend on
// the thread count.
nlohmann::json result_json(std::size_t i, const DepthFrame& frame, const FrameResult& r) {
  nlohmann::json j = detection_frame_json(i, frame.source, r);
  j.erase("timings_ms");
  return j;
}

// Reference: today's serial loop, Pipeline::run with the context.
std::vector<nlohmann::json> serial_reference(const std::vector<DepthFrame>& frames) {
  const Pipeline pipeline = lab_pipeline();
  TunnelContext context;
  FrameResult r;
  std::vector<nlohmann::json> out;
  for (std::size_t i = 0; i < frames.size(); ++i) {
    pipeline.run(frames[i], r, &context);
    out.push_back(result_json(i, frames[i], r));
  }
  return out;
}

std::vector<nlohmann::json> with_runner(const std::vector<DepthFrame>& frames, int threads,
                                        int in_flight) {
  TunnelContext context;
  SequenceOptions opt;
  opt.threads = threads;
  opt.max_in_flight = in_flight;
  SequenceRunner runner(lab_pipeline(), &context, opt);
  MemorySource source(frames);
  std::vector<nlohmann::json> out;
  const SequenceStats stats = runner.run(source, [&](SequenceFrame& f) {
    EXPECT_TRUE(f.ok()) << f.error_message;
    EXPECT_EQ(f.index, out.size());
    out.push_back(result_json(f.index, f.frame, f.result));
    return true;
  });
  EXPECT_EQ(stats.delivered, frames.size());
  EXPECT_EQ(stats.failed, 0u);
  EXPECT_FALSE(stats.stopped);
  EXPECT_EQ(stats.threads, std::min<int>(threads, static_cast<int>(frames.size())));
  return out;
}

// A cheap stand-in for the pipeline: the "result" records the frame's first depth value.
SequenceRunner::Work tag_work() {
  return [](const DepthFrame& f, FrameResult& r) {
    r.map.width_m = f.depth.at(0);
    if (f.depth.at(0) == 13.0f) throw std::runtime_error("stage failed on frame 13");
    if (f.depth.at(0) == 14.0f) throw 42;  // not even a std::exception
  };
}

std::vector<DepthFrame> tiny_frames(int n) {
  std::vector<DepthFrame> frames(n);
  for (int i = 0; i < n; ++i) {
    frames[i].width = frames[i].height = 1;
    frames[i].depth = {static_cast<float>(i)};
  }
  return frames;
}

}  // namespace

TEST(SequenceRunner, ParallelResultsEqualTheSerialPipelineIncludingTheContext) {
  const std::vector<DepthFrame>& frames = mixed_sequence();
  const std::vector<nlohmann::json> reference = serial_reference(frames);
  // The sequence really exercises the context: lab frames detected, the wide tunnel rejected.
  ASSERT_EQ(reference.size(), 6u);
  for (std::size_t i : {0u, 2u, 3u, 5u}) EXPECT_TRUE(reference[i]["detected"].get<bool>()) << reference[i];
  for (std::size_t i : {1u, 4u}) EXPECT_EQ(reference[i]["status"], "inconsistent_with_context") << i;
  EXPECT_NEAR(reference[0]["width_m"].get<double>(), 0.82, 0.01);

  for (auto [threads, in_flight] : {std::pair{1, 0}, {2, 0}, {3, 3}, {2, 2}}) {
    const std::vector<nlohmann::json> got = with_runner(frames, threads, in_flight);
    ASSERT_EQ(got.size(), reference.size());
    for (std::size_t i = 0; i < got.size(); ++i)
      EXPECT_EQ(got[i].dump(), reference[i].dump()) << threads << " threads, frame " << i;
  }
}

TEST(SequenceRunner, ApplyingTheContextAfterwardsEqualsDetectingWithIt) {
  // The split the runner relies on, for a consistent and an inconsistent map.
  const std::vector<DepthFrame>& frames = mixed_sequence();
  const Pipeline pipeline = lab_pipeline();
  TunnelContext context;
  const FrameResult first = pipeline.run(frames[0], &context);
  ASSERT_TRUE(first.map.detected);
  for (std::size_t i : {1u, 2u}) {
    TunnelContext copy = context;
    const FrameResult with = pipeline.run(frames[i], &copy);
    FrameResult split = pipeline.run(frames[i], nullptr);
    EXPECT_TRUE(split.map.detected);
    apply_tunnel_context(split.map, tunnel_options(pipeline.params()), context);
    EXPECT_EQ(result_json(i, frames[i], split).dump(), result_json(i, frames[i], with).dump());
  }
}

TEST(SequenceRunner, BadFrameIsReportedInOrderAndTheOthersStillRun) {
  for (int threads : {1, 2, 4}) {
    MemorySource source(tiny_frames(20), {5, 6});
    SequenceOptions opt;
    opt.threads = threads;
    SequenceRunner runner(tag_work(), nullptr, opt);
    std::vector<std::size_t> order;
    std::vector<std::string> errors(20);
    const SequenceStats stats = runner.run(source, [&](SequenceFrame& f) {
      order.push_back(f.index);
      if (f.ok())
        EXPECT_EQ(f.result.map.width_m, static_cast<double>(f.index));
      else
        errors[f.index] = f.error_message;
      return true;
    });
    ASSERT_EQ(order.size(), 20u) << threads;
    for (std::size_t i = 0; i < order.size(); ++i) EXPECT_EQ(order[i], i);
    EXPECT_EQ(stats.delivered, 20u);
    EXPECT_EQ(stats.failed, 4u);
    EXPECT_EQ(errors[5], "frame5.png: not a PNG file");
    EXPECT_EQ(errors[6], "frame6.png: not a PNG file");
    EXPECT_EQ(errors[13], "stage failed on frame 13");
    EXPECT_EQ(errors[14], "unknown error");
    for (std::size_t i : {0u, 4u, 7u, 12u, 15u, 19u}) EXPECT_EQ(errors[i], "") << i;
  }
}

TEST(SequenceRunner, ErrorCanBeRethrownAsTheFramesInputError) {
  MemorySource source(tiny_frames(8), {3});
  SequenceOptions opt;
  opt.threads = 2;
  SequenceRunner runner(tag_work(), nullptr, opt);
  std::size_t seen = 0;
  try {
    runner.run(source, [&](SequenceFrame& f) {
      if (!f.ok()) std::rethrow_exception(f.error);
      ++seen;
      return true;
    });
    FAIL() << "no exception";
  } catch (const InputError& e) {
    EXPECT_STREQ(e.what(), "frame3.png: not a PNG file");
  }
  EXPECT_EQ(seen, 3u);  // frames 0-2 delivered first, nothing after the bad one
}

TEST(SequenceRunner, CallbackStopsEarlyAndCancelStops) {
  for (int threads : {1, 2}) {
    MemorySource source(tiny_frames(50));
    SequenceOptions opt;
    opt.threads = threads;
    SequenceRunner runner(tag_work(), nullptr, opt);
    std::size_t seen = 0;
    SequenceStats stats = runner.run(source, [&](SequenceFrame& f) { return ++seen < 4; });
    EXPECT_EQ(seen, 4u);
    EXPECT_EQ(stats.delivered, 4u);
    EXPECT_TRUE(stats.stopped);
    EXPECT_LE(source.load_order.size(), 4u + 2 * threads);  // bounded read-ahead

    seen = 0;
    stats = runner.run(source, [&](SequenceFrame& f) {
      if (++seen == 7) runner.cancel();
      return true;
    });
    EXPECT_EQ(stats.delivered, 7u);
    EXPECT_TRUE(stats.stopped);

    // The next run starts afresh.
    stats = runner.run(source, [&](SequenceFrame&) { return true; });
    EXPECT_EQ(stats.delivered, 50u);
    EXPECT_FALSE(stats.stopped);
  }
}

TEST(SequenceRunner, CallbackExceptionLeavesRunAfterJoiningTheWorkers) {
  MemorySource source(tiny_frames(30));
  SequenceOptions opt;
  opt.threads = 3;
  SequenceRunner runner(tag_work(), nullptr, opt);
  EXPECT_THROW(runner.run(source, [](SequenceFrame& f) -> bool {
    if (f.index == 9) throw std::logic_error("callback failed");
    return true;
  }),
               std::logic_error);
  // Still usable: the workers of the failed run are gone.
  EXPECT_EQ(runner.run(source, [](SequenceFrame&) { return true; }).delivered, 30u);
}

TEST(SequenceRunner, InFlightFramesAreBoundedAndSerialLoadingIsInOrder) {
  std::atomic<std::size_t> delivered{0};
  std::size_t worst = 0;
  class CountingSource : public MemorySource {
   public:
    CountingSource(std::atomic<std::size_t>& delivered, std::size_t& worst)
        : MemorySource(tiny_frames(40)), delivered_(delivered), worst_(worst) {}
    DepthFrame load(std::size_t i) const override {
      DepthFrame f = MemorySource::load(i);
      std::lock_guard<std::mutex> lock(m_);
      worst_ = std::max(worst_, i + 1 - delivered_.load());
      return f;
    }
    std::atomic<std::size_t>& delivered_;
    std::size_t& worst_;
    mutable std::mutex m_;
  } source(delivered, worst);
  SequenceOptions opt;
  opt.threads = 3;
  opt.max_in_flight = 4;
  opt.serial_loading = true;
  SequenceRunner runner(tag_work(), nullptr, opt);
  runner.run(source, [&](SequenceFrame& f) {
    ++delivered;
    return true;
  });
  EXPECT_EQ(delivered.load(), 40u);
  EXPECT_LE(worst, 4u);
  ASSERT_EQ(source.load_order.size(), 40u);
  for (std::size_t i = 0; i < 40; ++i) EXPECT_EQ(source.load_order[i], i);
}

TEST(SequenceRunner, OrderedStepSeesFramesInOrderAndItsErrorsBecomeTheFrames) {
  MemorySource source(tiny_frames(12));
  std::vector<std::size_t> ordered_seen;
  SequenceOptions opt;
  opt.threads = 2;
  SequenceRunner runner(tag_work(), [&](SequenceFrame& f) {
    ordered_seen.push_back(f.index);
    if (f.index == 4) throw InputError("ctx", "rejected");
  }, opt);
  std::vector<std::string> errors;
  runner.run(source, [&](SequenceFrame& f) {
    errors.push_back(f.error_message);
    return true;
  });
  ASSERT_EQ(ordered_seen.size(), 12u);
  for (std::size_t i = 0; i < 12; ++i) EXPECT_EQ(ordered_seen[i], i);
  EXPECT_EQ(errors[4], "ctx: rejected");
  EXPECT_EQ(errors[3], "");
}
