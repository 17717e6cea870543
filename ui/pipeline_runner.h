#pragma once
// PipelineRunner: runs the engine's frame run (core/engine/frame_run.h) off the GUI thread.
// Requests are debounced by the caller; here only the newest request matters: while one run is in flight, newer requests replace the
// pending one and the in-flight result is dropped as stale (Pipeline::run has no cancellation
// point, so a stale run finishes but is never shown). A parameter change re-runs only the stages
// from the earliest one any changed parameter affects (the engine decides). The worker also
// builds the scene geometry and the depth image; the point-cloud polydata of the previous run
// is reused (same object, so VTK keeps its GPU buffers) when only later stages re-ran.
#include <QFutureWatcher>
#include <QImage>
#include <QObject>
#include <memory>
#include <optional>

#include "core/baselines/method.h"
#include "core/engine/run_settings.h"
#include "core/io/frame_source.h"
#include "ui/scene/processed_frame.h"
#include "ui/scene/scene_geometry.h"

namespace tunnelmap::ui {

struct RunOutcome {
  int frame_index = -1;
  std::shared_ptr<const scene::ProcessedFrame> processed;  // null on error
  // What the views show, built on the worker too so the GUI thread only swaps and renders.
  std::shared_ptr<const scene::SceneGeometry> geometry;
  QImage depth_image;
  Parameters params;
  Method method = Method::Pgc;
  Stage from = Stage::Cloud;
  double wall_ms = 0.0;   // request to result, including queueing
  double scene_ms = 0.0;  // of which building the scene geometry and the depth image
  QString error;
};

class PipelineRunner : public QObject {
  Q_OBJECT
 public:
  explicit PipelineRunner(QObject* parent = nullptr);
  ~PipelineRunner() override;

  void set_source(std::shared_ptr<const FrameSource> source);  // drops cached results
  void request(int frame_index, const Parameters& params, Method method = Method::Pgc);
  bool busy() const { return running_; }
  int runs_started() const { return runs_started_; }

 signals:
  void finished(const tunnelmap::ui::RunOutcome& outcome);

 private:
  struct Job {
    int frame_index;
    RunSettings settings;
    qint64 requested_ns;
  };
  void start(const Job& job);
  void on_done();

  std::shared_ptr<const FrameSource> source_;
  std::shared_ptr<const scene::ProcessedFrame> cache_;  // last completed run
  std::shared_ptr<const scene::SceneGeometry> cache_geometry_;
  RunSettings cache_settings_;  // what made cache_
  int cache_frame_ = -1;
  std::optional<Job> pending_;
  bool running_ = false;
  int runs_started_ = 0;
  QFutureWatcher<RunOutcome> watcher_;
};

}  // namespace tunnelmap::ui

Q_DECLARE_METATYPE(tunnelmap::ui::RunOutcome)
