#include "ui/pipeline_runner.h"

#include <QElapsedTimer>
#include <QtConcurrent/QtConcurrentRun>
#include <chrono>

#include "ui/depth_view_widget.h"

namespace tunnelmap::ui {

namespace {
qint64 now_ns() {
  return std::chrono::duration_cast<std::chrono::nanoseconds>(
             std::chrono::steady_clock::now().time_since_epoch())
      .count();
}
}  // namespace

PipelineRunner::PipelineRunner(QObject* parent) : QObject(parent) {
  qRegisterMetaType<RunOutcome>();
  connect(&watcher_, &QFutureWatcher<RunOutcome>::finished, this, &PipelineRunner::on_done);
}

PipelineRunner::~PipelineRunner() { watcher_.waitForFinished(); }

void PipelineRunner::set_source(std::shared_ptr<const FrameSource> source) {
  source_ = std::move(source);
  cache_.reset();
  cache_geometry_.reset();
  cache_frame_ = -1;
  pending_.reset();
}

void PipelineRunner::request(int frame_index, const Parameters& params, Method method) {
  RunSettings settings;
  settings.params = params;
  settings.method = method;
  Job job{frame_index, settings, now_ns()};
  if (running_)
    pending_ = job;  // replaces an older pending request: only the newest counts
  else
    start(job);
}

void PipelineRunner::start(const Job& job) {
  running_ = true;
  ++runs_started_;
  auto source = source_;
  // The same frame again: the engine re-runs only the stages a parameter change affects.
  std::shared_ptr<const scene::ProcessedFrame> base;
  std::shared_ptr<const scene::SceneGeometry> base_geometry;
  std::optional<RunSettings> cached;
  if (cache_ && cache_frame_ == job.frame_index) {
    base = cache_;
    base_geometry = cache_geometry_;
    cached = cache_settings_;
  }
  watcher_.setFuture(QtConcurrent::run([source, base, base_geometry, cached, job]() {
    RunOutcome out;
    out.frame_index = job.frame_index;
    out.params = job.settings.params;
    out.method = job.settings.method;
    try {
      if (!source) throw std::runtime_error("no input open");
      auto processed = std::make_shared<scene::ProcessedFrame>();
      if (base) *processed = *base;  // copy: the GUI may still be showing `base`
      out.from = run_frame(*source, static_cast<std::size_t>(job.frame_index), job.settings, *processed,
                           base ? &*cached : nullptr);
      const qint64 scene_start = now_ns();
      // The cloud layer depends on the frame and the cloud stage only.
      const bool reuse_cloud = base_geometry && out.from > Stage::Normals;
      scene::GeometryOptions options;
      options.cloud = !reuse_cloud;
      auto geometry = std::make_shared<scene::SceneGeometry>(
          scene::build_geometry(processed->scene_data(), options));
      if (reuse_cloud) geometry->cloud = base_geometry->cloud;
      out.depth_image = depth_label_image(*processed);
      out.geometry = geometry;
      out.scene_ms = (now_ns() - scene_start) / 1e6;
      out.processed = processed;
    } catch (const std::exception& e) {
      out.error = QString::fromStdString(e.what());
    }
    out.wall_ms = (now_ns() - job.requested_ns) / 1e6;
    return out;
  }));
}

void PipelineRunner::on_done() {
  running_ = false;
  RunOutcome out = watcher_.result();
  if (out.processed) {
    cache_ = out.processed;
    cache_geometry_ = out.geometry;
    cache_settings_.params = out.params;
    cache_settings_.method = out.method;
    cache_frame_ = out.frame_index;
  }
  if (pending_) {  // a newer request arrived: this result is stale
    Job next = *pending_;
    pending_.reset();
    start(next);
    return;
  }
  emit finished(out);
}

}  // namespace tunnelmap::ui
