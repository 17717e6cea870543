#include "ui/live_view.h"

#include <QtConcurrent/QtConcurrentRun>

#include "sensors/openni/latest_frame_grabber.h"
#include "sensors/openni/live_device.h"
#include "sensors/openni/oni_recording.h"
#include "ui/depth_view_widget.h"

namespace tunnelmap::ui {

namespace {
constexpr int kTickMs = 33;  // ~30 Hz, the cameras' rate
using Clock = std::chrono::steady_clock;
}  // namespace

LiveView::LiveView(QObject* parent) : QObject(parent) {
  qRegisterMetaType<RunOutcome>();
  timer_.setInterval(kTickMs);
  connect(&timer_, &QTimer::timeout, this, &LiveView::tick);
  connect(&watcher_, &QFutureWatcher<RunOutcome>::finished, this, &LiveView::on_done);
}

LiveView::~LiveView() { stop(); }

void LiveView::start(const QString& uri) {
  stop();
  auto device = std::make_unique<openni2::LiveDevice>(uri.toStdString());
  grabber_ = std::make_unique<openni2::LatestFrameGrabber>(std::move(device));
  uri_ = uri;
  stats_ = LiveStats();
  shown_times_.clear();
  timer_.start();
}

void LiveView::stop() {
  timer_.stop();
  watcher_.waitForFinished();
  busy_ = false;
  if (recording_ && grabber_)  // unfinished: its temporary file is removed (streams stopped, see OniRecording)
    grabber_->with_streams_paused([&] { recording_.reset(); });
  recording_.reset();
  grabber_.reset();  // stops streaming and joins the reader
  engine_.reset();   // the next start has no context of this one
}

void LiveView::start_recording(const QString& path) {
  if (!grabber_) throw std::runtime_error("no live device: start the live view first");
  if (recording_) grabber_->with_streams_paused([&] { recording_.reset(); });
  recording_ = std::make_unique<openni2::OniRecording>(grabber_->device(), path.toStdString());
  recording_start_ = grabber_->stats().received;
}

int LiveView::frames_recorded() const {
  return recording_ && grabber_ ? static_cast<int>(grabber_->stats().received - recording_start_) : 0;
}

int LiveView::stop_recording() {
  if (!recording_) return 0;
  const int frames = frames_recorded();
  auto rec = std::move(recording_);
  if (grabber_) grabber_->with_streams_paused([&] { rec->finish(); });  // see OniRecording
  else rec->finish();
  return frames;
}

void LiveView::tick() {
  if (!grabber_ || busy_) return;  // the worker is busy: the grabber keeps only the newest frame
  std::optional<openni2::GrabbedFrame> grabbed;
  try {
    grabbed = grabber_->take_latest(0);
  } catch (const std::exception& e) {
    const QString message = QString::fromStdString(e.what());
    stop();
    emit failed(message);
    return;
  }
  if (!grabbed) return;
  busy_ = true;
  arrived_ = grabbed->arrived;
  const Parameters params = parameters ? parameters() : Parameters();
  const Method m = method ? method() : Method::Pgc;
  const int index = static_cast<int>(grabbed->sequence) - 1;
  auto processed = std::make_shared<scene::ProcessedFrame>();
  processed->frame = std::move(grabbed->frame);
  // The engine keeps the context of the frames shown so far, as `detect --device` does; a change
  // of parameters or method starts it afresh.
  if (!engine_ || engine_->settings().params != params || engine_->settings().method != m) {
    RunSettings settings;
    settings.params = params;
    settings.method = m;
    settings.live = true;
    engine_ = std::make_shared<RunEngine>(settings, nullptr);
  }
  watcher_.setFuture(QtConcurrent::run([processed, engine = engine_, params, m, index]() {
    RunOutcome out;
    out.frame_index = index;
    out.params = params;
    out.method = m;
    try {
      engine->run_next(index, processed->frame, processed->result);  // one frame at a time (busy_)
      out.geometry = std::make_shared<scene::SceneGeometry>(scene::build_geometry(processed->scene_data()));
      out.depth_image = depth_label_image(*processed);
      out.processed = processed;
    } catch (const std::exception& e) {
      out.error = QString::fromStdString(e.what());
    }
    return out;
  }));
}

void LiveView::on_done() {
  if (!busy_) return;  // stopped meanwhile
  busy_ = false;
  RunOutcome out = watcher_.result();
  const auto now = Clock::now();
  out.wall_ms = std::chrono::duration<double, std::milli>(now - arrived_).count();
  if (out.processed) {
    ++stats_.shown;
    if (out.processed->result.map.detected) ++stats_.detected;
    stats_.latency_ms = out.wall_ms;
    shown_times_.push_back(now);
    while (!shown_times_.empty() && now - shown_times_.front() > std::chrono::seconds(1)) shown_times_.pop_front();
    stats_.fps = static_cast<double>(shown_times_.size());
  }
  if (grabber_) {
    const auto g = grabber_->stats();
    stats_.received = g.received;
    stats_.dropped = g.dropped;
  }
  emit frameReady(out);
}

}  // namespace tunnelmap::ui
