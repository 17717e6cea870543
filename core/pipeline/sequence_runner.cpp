// SequenceRunner: a ring of `max_in_flight` slots. Worker i claims frame k only when frame
// k - max_in_flight has been delivered, so slot k % max_in_flight is free; the calling thread
// delivers slot by slot in frame order. Frame errors are stored in their slot, never thrown
// across threads.
#include "core/pipeline/sequence_runner.h"

#include <algorithm>
#include <thread>
#include <utility>
#include <vector>

namespace tunnelmap {

namespace {

using Clock = std::chrono::steady_clock;

void record_error(SequenceFrame& slot) {
  slot.error = std::current_exception();
  try {
    throw;
  } catch (const std::exception& e) {
    slot.error_message = e.what();
  } catch (...) {
    slot.error_message = "unknown error";
  }
}

// Loads frame `i` into `slot`; false (and the error recorded) when loading failed.
bool load_into(const FrameSource& source, std::size_t i, SequenceFrame& slot) {
  slot.index = i;
  slot.error = nullptr;
  slot.error_message.clear();
  try {
    slot.frame = source.load(i);
    slot.loaded_at = Clock::now();
    return true;
  } catch (...) {
    slot.frame = DepthFrame();
    slot.loaded_at = Clock::now();
    slot.processed_at = slot.loaded_at;
    record_error(slot);
    return false;
  }
}

void work_on(const SequenceRunner::Work& work, SequenceFrame& slot) {
  try {
    if (work) work(slot.frame, slot.result);
  } catch (...) {
    record_error(slot);
  }
  slot.processed_at = Clock::now();
}

}  // namespace

int resolve_thread_count(int requested) {
  if (requested > 0) return requested;
  return static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
}

SequenceRunner::SequenceRunner(const Pipeline& pipeline, TunnelContext* context,
                               SequenceOptions options)
    // The scratch travels with the work: each worker's copy has its own (FrameScratch copies
    // start empty), so the ring's result slots hold no buffers of their own.
    : work_([pipeline, scratch = FrameScratch()](const DepthFrame& f, FrameResult& r) mutable {
        pipeline.run(f, r, scratch, nullptr);
      }),
      options_(options) {
  if (context)
    ordered_ = [opt = tunnel_options(pipeline.params()), context](SequenceFrame& s) {
      apply_tunnel_context(s.result.map, opt, *context);
      if (s.result.map.detected) context->accept(s.result.map);
    };
}

SequenceRunner::SequenceRunner(Work work, Ordered ordered, SequenceOptions options)
    : work_(std::move(work)), ordered_(std::move(ordered)), options_(options) {}

void SequenceRunner::cancel() {
  cancelled_ = true;
  { std::lock_guard<std::mutex> lock(mutex_); }  // a waiter is either before its check or asleep
  changed_.notify_all();
}

bool SequenceRunner::deliver_one(SequenceFrame& item, const Deliver& deliver, SequenceStats& stats) {
  if (item.ok() && ordered_) {
    try {
      ordered_(item);
    } catch (...) {
      record_error(item);
    }
  }
  ++stats.delivered;
  if (!item.ok()) ++stats.failed;
  return deliver(item);
}

SequenceStats SequenceRunner::run(const FrameSource& source, const Deliver& deliver) {
  cancelled_ = false;
  const int threads = static_cast<int>(std::min<std::size_t>(
      static_cast<std::size_t>(resolve_thread_count(options_.threads)), std::max<std::size_t>(1, source.size())));
  return threads <= 1 ? run_serial(source, deliver) : run_parallel(source, deliver, threads);
}

SequenceStats SequenceRunner::run_serial(const FrameSource& source, const Deliver& deliver) {
  SequenceStats stats;
  SequenceFrame slot;
  for (std::size_t i = 0; i < source.size(); ++i) {
    if (cancelled_) break;
    if (load_into(source, i, slot)) work_on(work_, slot);
    if (cancelled_) break;
    if (!deliver_one(slot, deliver, stats)) {
      stats.stopped = true;
      break;
    }
  }
  stats.stopped = stats.stopped || cancelled_;
  return stats;
}

SequenceStats SequenceRunner::run_parallel(const FrameSource& source, const Deliver& deliver,
                                           int threads) {
  const std::size_t n = source.size();
  const std::size_t ring = static_cast<std::size_t>(
      std::max(threads, options_.max_in_flight > 0 ? options_.max_in_flight : 2 * threads));
  std::vector<SequenceFrame> slots(ring);
  std::vector<char> ready(ring, 0);
  std::size_t next_claim = 0, next_deliver = 0;  // guarded by mutex_
  bool stop = false;                             // guarded by mutex_
  std::exception_ptr fatal;                      // a worker's own failure (not a frame's)
  std::mutex load_mutex;                         // serial_loading: claim + load as one step
  SequenceStats stats;
  stats.threads = threads;

  auto worker = [&](Work work) {
    try {
      for (;;) {
        std::unique_lock<std::mutex> serial;
        if (options_.serial_loading) serial = std::unique_lock<std::mutex>(load_mutex);
        std::size_t i = 0;
        {
          std::unique_lock<std::mutex> lock(mutex_);
          changed_.wait(lock, [&] {
            return stop || cancelled_ || next_claim >= n || next_claim < next_deliver + ring;
          });
          if (stop || cancelled_ || next_claim >= n) return;
          i = next_claim++;
        }
        SequenceFrame& slot = slots[i % ring];
        const bool loaded = load_into(source, i, slot);
        if (serial) serial.unlock();
        if (loaded) work_on(work, slot);
        {
          std::lock_guard<std::mutex> lock(mutex_);
          ready[i % ring] = 1;
        }
        changed_.notify_all();
      }
    } catch (...) {  // only the threading machinery itself can get here
      std::lock_guard<std::mutex> lock(mutex_);
      if (!fatal) fatal = std::current_exception();
      stop = true;
    }
    changed_.notify_all();
  };

  // Joins the workers on every way out of this function, the callback's exceptions included.
  struct Pool {
    SequenceRunner& self;
    bool& stop;
    std::vector<std::thread> threads;
    void join() {
      {
        std::lock_guard<std::mutex> lock(self.mutex_);
        stop = true;
      }
      self.changed_.notify_all();
      for (std::thread& t : threads)
        if (t.joinable()) t.join();
    }
    ~Pool() { join(); }
  } pool{*this, stop, {}};
  // Copies made here, not in the threads: a failing copy then fails run(), not a worker.
  std::vector<Work> works(static_cast<std::size_t>(threads), work_);
  for (Work& w : works) pool.threads.emplace_back(worker, std::move(w));

  for (;;) {
    {
      std::unique_lock<std::mutex> lock(mutex_);
      changed_.wait(lock, [&] {
        return cancelled_ || fatal || next_deliver >= n || ready[next_deliver % ring];
      });
      if (cancelled_ || fatal || next_deliver >= n) break;
    }
    SequenceFrame& item = slots[next_deliver % ring];
    const bool go = deliver_one(item, deliver, stats);
    {
      std::lock_guard<std::mutex> lock(mutex_);
      ready[next_deliver % ring] = 0;
      ++next_deliver;
      if (!go) stop = true;
    }
    changed_.notify_all();
    if (!go) {
      stats.stopped = true;
      break;
    }
  }
  pool.join();
  if (fatal) std::rethrow_exception(fatal);
  stats.stopped = stats.stopped || cancelled_;
  return stats;
}

}  // namespace tunnelmap
