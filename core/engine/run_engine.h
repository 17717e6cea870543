#pragma once
// RunEngine: THE sequence loop. Every front end that runs frames in order (`detect`, `map`,
// `fuse`, `render --map`, the GUI's sequence, dataset and live runs, the bench) calls it, so all
// of them detect the same frames the same way: the input set-up (make_method_runner), detection
// on several threads (SequenceRunner), the context rule in frame order (FrameContext), progress
// and cancellation. Frames viewed one at a time go through run_frame (core/engine/frame_run.h).
#include <atomic>
#include <functional>
#include <memory>
#include <vector>

#include "core/engine/frame_context.h"
#include "core/engine/run_settings.h"
#include "core/pipeline/sequence_runner.h"

namespace tunnelmap {

class RunEngine {
 public:
  enum class ContextRule {
    Sequence,  // each frame gets the context of the frames before it (detect, the GUI)
    None,      // frames independent: the caller maps them afterwards (map, fuse: map_posed_sequence)
  };
  using Deliver = SequenceRunner::Deliver;
  using Progress = std::function<void(std::size_t done, std::size_t total)>;

  // `input` (may be null for a live camera) gives the input set-up (a dataset's world up).
  RunEngine(RunSettings settings, const FrameSource* input, ContextRule rule = ContextRule::Sequence);

  // Every frame of `source`, delivered strictly in frame order with its context applied (errors
  // included: SequenceFrame::ok()). `deliver` returns false to stop; `progress` is called after
  // each delivered frame.
  SequenceStats run(const FrameSource& source, const Deliver& deliver, const Progress& progress = {});

  // One frame that arrives on its own (a live camera), in order: detection, then the context.
  // With slam.localise the frame's pose becomes the one localisation gave it.
  void run_next(int index, DepthFrame& frame, FrameResult& result);

  // From any thread: run() stops after the frame being delivered. Reset when run() starts.
  void cancel() { cancelled_.store(true); }
  bool cancelled() const { return cancelled_.load(); }

  const RunSettings& settings() const { return settings_; }
  const MethodRunner& runner() const { return runner_; }
  const FrameContext& context() const { return context_; }

 private:
  RunSettings settings_;
  ContextRule rule_;
  MethodRunner runner_;
  FrameContext context_;
  std::atomic<bool> cancelled_{false};
};

// The same loop (loading, order, progress, errors) with the caller's own work on each frame in
// place of detection: `planes` times its stages; fusion without detection only loads (null work).
SequenceStats run_frames(const FrameSource& source, SequenceRunner::Work work, const RunSettings& settings,
                         const RunEngine::Deliver& deliver, const RunEngine::Progress& progress = {});

// A dataset's frames with the poses the caller resolved (explicit, forward kinematics, or
// preferring the joints), so the sequence loop sees each frame with the pose it is mapped with.
class PosedFrames : public FrameSource {
 public:
  PosedFrames(const Dataset& dataset, std::vector<Eigen::Isometry3d> poses);
  std::size_t size() const override { return dataset_.frames.size(); }
  DepthFrame load(std::size_t i) const override;
  std::string describe(std::size_t i) const override;
  const Dataset* dataset() const override { return &dataset_; }

 private:
  const Dataset& dataset_;
  std::vector<Eigen::Isometry3d> poses_;
};

}  // namespace tunnelmap
