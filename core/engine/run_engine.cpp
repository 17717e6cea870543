#include "core/engine/run_engine.h"

#include <utility>

namespace tunnelmap {

namespace {
// The input set-up of a live camera: no dataset, so no world up other than the default.
struct NoInput : FrameSource {
  std::size_t size() const override { return 0; }
  DepthFrame load(std::size_t) const override { return {}; }
  std::string describe(std::size_t) const override { return {}; }
};

const FrameSource& input_or_none(const FrameSource* input) {
  static const NoInput none;
  return input ? *input : static_cast<const FrameSource&>(none);
}
// The one sequence loop: loading (in parallel where the input allows), `work` in the workers,
// `in_order` and `deliver` in frame order, progress, and a stop when `cancelled` is set.
SequenceStats run_loop(const FrameSource& source, SequenceRunner::Work work, SequenceRunner::Ordered in_order,
                       const RunSettings& settings, const RunEngine::Deliver& deliver,
                       const RunEngine::Progress& progress, const std::atomic<bool>* cancelled) {
  SequenceOptions options;
  options.threads = settings.live ? 1 : settings.threads;  // a camera delivers one frame at a time
  options.serial_loading = !source.dataset();              // recordings have a read position
  SequenceRunner sequence(std::move(work), std::move(in_order), options);
  const std::size_t total = source.size();
  const auto stop = [cancelled] { return cancelled && cancelled->load(); };
  return sequence.run(source, [&](SequenceFrame& f) {
    if (stop()) return false;
    const bool go_on = deliver(f);
    if (progress) progress(f.index + 1, total);
    return go_on && !stop();
  });
}

}  // namespace

RunEngine::RunEngine(RunSettings settings, const FrameSource* input, ContextRule rule)
    : settings_(std::move(settings)),
      rule_(rule),
      runner_(make_method_runner(input_or_none(input), settings_)),
      context_(settings_.params, world_up(input_or_none(input))) {}

void RunEngine::run_next(int index, DepthFrame& frame, FrameResult& result) {
  if (rule_ == ContextRule::Sequence && runner_.method() == Method::Qhull) {
    runner_.run(frame, result, &context_.recent());
    return;
  }
  runner_.run(frame, result, nullptr);
  if (rule_ == ContextRule::Sequence) frame.pose = context_.apply(index, result, frame.pose, frame.gravity);
}

SequenceStats RunEngine::run(const FrameSource& source, const Deliver& deliver, const Progress& progress) {
  cancelled_.store(false);
  SequenceRunner::Work work;
  SequenceRunner::Ordered in_order;
  if (rule_ == ContextRule::Sequence && runner_.method() == Method::Qhull) {
    // Qhull checks the context inside its fit: it runs in frame order (loading still ahead).
    in_order = [this](SequenceFrame& f) { run_next(static_cast<int>(f.index), f.frame, f.result); };
  } else {
    // Detection in parallel without the context (each worker with its own copy of the runner);
    // the context in frame order, so the output equals a serial run.
    work = [runner = runner_](const DepthFrame& frame, FrameResult& r) { runner.run(frame, r, nullptr); };
    if (rule_ == ContextRule::Sequence)
      in_order = [this](SequenceFrame& f) {
        f.frame.pose = context_.apply(static_cast<int>(f.index), f.result, f.frame.pose, f.frame.gravity);
      };
  }
  return run_loop(source, std::move(work), std::move(in_order), settings_, deliver, progress, &cancelled_);
}

SequenceStats run_frames(const FrameSource& source, SequenceRunner::Work work, const RunSettings& settings,
                         const RunEngine::Deliver& deliver, const RunEngine::Progress& progress) {
  return run_loop(source, std::move(work), nullptr, settings, deliver, progress, nullptr);
}

PosedFrames::PosedFrames(const Dataset& dataset, std::vector<Eigen::Isometry3d> poses)
    : dataset_(dataset), poses_(std::move(poses)) {}

DepthFrame PosedFrames::load(std::size_t i) const {
  DepthFrame f = dataset_.load_frame(i);
  f.pose = poses_.at(i);
  return f;
}

std::string PosedFrames::describe(std::size_t i) const {
  return "frame " + std::to_string(i) + "/" + std::to_string(size());
}

}  // namespace tunnelmap
