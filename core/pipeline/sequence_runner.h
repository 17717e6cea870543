#pragma once
// SequenceRunner: the frames of a FrameSource through N worker threads, results delivered to a
// callback strictly in frame order. Workers load and process frames (loading, i.e. PNG decoding,
// is a large share of the cost); at most `max_in_flight` frames are loaded but not yet delivered,
// so memory stays bounded however long the sequence. Order-dependent work (the tunnel context of
// earlier scans) runs in the delivering thread, in frame order, so the results equal a serial run.
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstddef>
#include <exception>
#include <functional>
#include <mutex>
#include <string>

#include "core/io/frame_source.h"
#include "core/pipeline/pipeline.h"

namespace tunnelmap {

struct SequenceOptions {
  int threads = 0;        // worker threads; 0 = hardware concurrency; 1 = serial, in run()'s thread
  int max_in_flight = 0;  // frames loaded but not yet delivered; 0 = 2 * threads (min: threads)
  // FrameSource::load() calls one at a time and in index order (sources with a read position:
  // recordings, live devices). Dataset folders and single files may load in parallel.
  bool serial_loading = false;
};

int resolve_thread_count(int requested);  // 0 -> hardware concurrency (at least 1)

// One frame as handed to the callback. The slot is reused for later frames: copy what you keep.
struct SequenceFrame {
  std::size_t index = 0;
  DepthFrame frame;           // as loaded; empty when loading failed
  FrameResult result;         // meaningful only when ok()
  std::exception_ptr error;   // loading or processing failed (e.g. InputError): report or rethrow
  std::string error_message;  // error's what()
  std::chrono::steady_clock::time_point loaded_at, processed_at;
  bool ok() const { return !error; }
};

struct SequenceStats {
  std::size_t delivered = 0;  // frames handed to the callback, errors included
  std::size_t failed = 0;     // of which with an error
  bool stopped = false;       // the callback returned false or cancel() was called
  int threads = 1;            // worker threads used
};

class SequenceRunner {
 public:
  // Context-free work on one frame, run in a worker; every worker gets its own copy (so a
  // captured Pipeline and a captured FrameScratch are never shared between threads).
  using Work = std::function<void(const DepthFrame&, FrameResult&)>;
  // Order-dependent step, run in the delivering thread in frame order, for frames without error.
  // An exception thrown here becomes that frame's error.
  using Ordered = std::function<void(SequenceFrame&)>;
  // Receives every frame in order (errors included); return false to stop early. An exception
  // thrown here stops the run and leaves run() after the workers have been joined.
  using Deliver = std::function<bool(SequenceFrame&)>;

  // PG&C: cloud, normals, planes and the per-frame tunnel fit in the workers, each with its own
  // copy of `pipeline` and its own FrameScratch; the context check (apply_tunnel_context) and
  // update in frame order.
  // `context` may be null (frames independent); it must outlive run().
  SequenceRunner(const Pipeline& pipeline, TunnelContext* context, SequenceOptions options = {});
  SequenceRunner(Work work, Ordered ordered, SequenceOptions options = {});

  const SequenceOptions& options() const { return options_; }

  // Processes every frame of `source` (not re-entrant: one run() at a time per runner).
  SequenceStats run(const FrameSource& source, const Deliver& deliver);

  // From any thread (or the callback): run() stops delivering and returns once the frames being
  // processed are done. Undelivered frames are dropped. Reset when the next run() starts.
  void cancel();

 private:
  struct Shared;
  SequenceStats run_serial(const FrameSource& source, const Deliver& deliver);
  SequenceStats run_parallel(const FrameSource& source, const Deliver& deliver, int threads);
  bool deliver_one(SequenceFrame& item, const Deliver& deliver, SequenceStats& stats);

  Work work_;
  Ordered ordered_;
  SequenceOptions options_;
  std::atomic<bool> cancelled_{false};
  std::mutex mutex_;  // guards the parallel run's bookkeeping; cancel() wakes waiters through it
  std::condition_variable changed_;
};

}  // namespace tunnelmap
