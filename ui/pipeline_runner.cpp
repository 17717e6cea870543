#include "ui/pipeline_runner.h"

#include <QElapsedTimer>
#include <QtConcurrent/QtConcurrentRun>
#include <chrono>

#include "core/baselines/method_runner.h"
#include "core/util/error.h"
#include "ui/depth_view_widget.h"

namespace tunnelmap::ui {

namespace {
qint64 now_ns() {
  return std::chrono::duration_cast<std::chrono::nanoseconds>(
             std::chrono::steady_clock::now().time_since_epoch())
      .count();
}
}  // namespace

scene::ProcessedFrame process_with_method(const FrameSource& source, std::size_t index, Method method,
                                          const Parameters& params, TunnelContext* context) {
  if (method == Method::Pgc) return scene::process_frame(source, index, scene::make_pipeline(source, params), context);
  if (index >= source.size())
    throw InputError(source.size() ? source.describe(0) : std::string(),
                     "frame " + std::to_string(index) + " does not exist (the input has " +
                         std::to_string(source.size()) + ")");
  MethodRunner runner(method, params);
  if (const Dataset* ds = source.dataset()) runner.set_world_up(ds->up);
  scene::ProcessedFrame out;
  out.frame = source.load(index);
  runner.run(out.frame, out.result, context);
  return out;
}

std::optional<Stage> first_changed_stage(const Parameters& a, const Parameters& b) {
  std::optional<Stage> first;
  for (const auto& spec : parameter_table())
    if (a.get(spec.key) != b.get(spec.key))
      if (!first || static_cast<int>(spec.stage) < static_cast<int>(*first)) first = spec.stage;
  return first;
}

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
  Job job{frame_index, params, method, now_ns()};
  if (running_)
    pending_ = job;  // replaces an older pending request: only the newest counts
  else
    start(job);
}

void PipelineRunner::start(const Job& job) {
  running_ = true;
  ++runs_started_;
  auto source = source_;
  // Reuse the earlier stages when the frame is the same.
  std::shared_ptr<const scene::ProcessedFrame> base;
  vtkSmartPointer<vtkPolyData> base_cloud;
  Stage from = Stage::Cloud;
  // Partial re-runs are PG&C's stages; the baselines always run the whole frame.
  if (cache_ && cache_frame_ == job.frame_index && job.method == Method::Pgc && cache_method_ == Method::Pgc) {
    const auto changed = first_changed_stage(cache_params_, job.params);
    base = cache_;
    from = changed ? *changed : Stage::Tunnel;
    // The cloud layer depends on the frame and the cloud stage only.
    if (from > Stage::Normals && cache_geometry_) base_cloud = cache_geometry_->cloud;
  }
  watcher_.setFuture(QtConcurrent::run([source, base, base_cloud, from, job]() {
    RunOutcome out;
    out.frame_index = job.frame_index;
    out.params = job.params;
    out.method = job.method;
    out.from = from;
    try {
      if (!source) throw std::runtime_error("no input open");
      auto processed = std::make_shared<scene::ProcessedFrame>();
      if (base) {
        const Pipeline pipeline = scene::make_pipeline(*source, job.params);
        *processed = *base;  // copy: the GUI may still be showing `base`
        pipeline.run(processed->frame, processed->result, nullptr, from);
      } else {
        *processed = process_with_method(*source, static_cast<std::size_t>(job.frame_index), job.method, job.params);
      }
      const qint64 scene_start = now_ns();
      scene::GeometryOptions options;
      options.cloud = !base_cloud;
      auto geometry = std::make_shared<scene::SceneGeometry>(
          scene::build_geometry(processed->scene_data(), options));
      if (base_cloud) geometry->cloud = base_cloud;
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
    cache_params_ = out.params;
    cache_method_ = out.method;
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
