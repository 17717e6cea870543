#pragma once
// Live view of an OpenNI2 device: a LatestFrameGrabber keeps only the newest frame; a ~30 Hz
// timer takes it when the worker is idle, so the pipeline always processes the latest frame and
// stale ones are dropped (never queued). Optional recording to .oni (OniRecording) while the view
// keeps running. The worker also builds the scene geometry, as PipelineRunner does.
#include <QFutureWatcher>
#include <QObject>
#include <QTimer>
#include <chrono>
#include <deque>
#include <functional>
#include <memory>

#include "core/baselines/method.h"
#include "core/engine/run_engine.h"
#include "core/params/parameters.h"
#include "ui/pipeline_runner.h"

namespace tunnelmap::openni2 {
class LatestFrameGrabber;
class OniRecording;
}  // namespace tunnelmap::openni2

namespace tunnelmap::ui {

struct LiveStats {
  int shown = 0, detected = 0;
  std::uint64_t received = 0, dropped = 0;  // by the grabber (dropped = replaced by a newer one)
  double fps = 0.0;                         // frames shown per second over the last second
  double latency_ms = 0.0;                  // frame arrived at the host -> result built
};

class LiveView : public QObject {
  Q_OBJECT
 public:
  explicit LiveView(QObject* parent = nullptr);
  ~LiveView() override;

  // Opens `uri` and starts streaming; InputError / runtime_error on failure.
  void start(const QString& uri);
  void stop();
  bool running() const { return grabber_ != nullptr; }
  QString uri() const { return uri_; }

  // Recording to `path` (.oni) while the view runs; finish renames it into place.
  void start_recording(const QString& path);
  int stop_recording();  // returns the depth frames received while recording
  bool recording() const { return recording_ != nullptr; }
  int frames_recorded() const;

  LiveStats stats() const { return stats_; }
  // What each processed frame runs with (read at every frame, so panel changes apply live).
  std::function<Parameters()> parameters;
  std::function<Method()> method;

 signals:
  void frameReady(const tunnelmap::ui::RunOutcome& outcome);
  void failed(const QString& message);  // device error; the view has stopped

 private:
  void tick();
  void on_done();

  QString uri_;
  std::unique_ptr<openni2::LatestFrameGrabber> grabber_;
  std::unique_ptr<openni2::OniRecording> recording_;
  std::uint64_t recording_start_ = 0;
  QTimer timer_;
  QFutureWatcher<RunOutcome> watcher_;
  bool busy_ = false;
  std::chrono::steady_clock::time_point arrived_;
  std::deque<std::chrono::steady_clock::time_point> shown_times_;
  LiveStats stats_;
  std::shared_ptr<RunEngine> engine_;  // the frames' context since start()
};

}  // namespace tunnelmap::ui
