#include "ui/device_controller.h"

#include <QAction>
#include <QActionGroup>
#include <QInputDialog>
#include <QMainWindow>
#include <QMenu>

#include "sensors/openni/device_list.h"
#include "ui/background_job.h"
#include "ui/file_dialogs.h"
#include "ui/frame_controller.h"
#include "ui/live_view.h"
#include "ui/map_summary.h"
#include "ui/parameter_panel.h"
#include "ui/window_context.h"
#include "ui/window_status.h"

namespace tunnelmap::ui {

DeviceController::DeviceController(WindowContext& ctx, FrameController* frames)
    : QObject(ctx.window), ctx_(ctx), frames_(frames), live_(new LiveView(ctx.window)) {
  live_->parameters = [this] { return ctx_.params->parameters(); };
  live_->method = [this] { return frames_->method(); };
  connect(live_, &LiveView::frameReady, this, &DeviceController::on_live_frame);
  connect(live_, &LiveView::failed, this, [this](const QString& m) {
    update_actions();
    ctx_.status->show_error(m);
  });
  frames_->live_running = [this] { return live_->running(); };
}

DeviceController::~DeviceController() { live_->stop(); }

bool DeviceController::live() const { return live_->running(); }

void DeviceController::add_menu(QMenu* device) {
  device->addAction(tr("&Refresh device list"), this, [this] { refresh_devices(); })->setObjectName("refreshDevices");
  devices_menu_ = device->addMenu(tr("&Devices"));
  device_actions_ = new QActionGroup(this);
  device->addAction(tr("&Start live view"), this, [this] { start_live_view(QString()); })->setObjectName("startLive");
  device->addAction(tr("Start live view on &URI…"), this, [this] {
    bool ok = false;
    const QString uri = QInputDialog::getText(ctx_.window, tr("Live view"), tr("OpenNI2 device URI:"),
                                              QLineEdit::Normal, "tunnelmap-sim://lab", &ok);
    if (ok && !uri.isEmpty()) start_live_view(uri);
  });
  device->addAction(tr("S&top live view"), this, &DeviceController::stop_live_view)->setObjectName("stopLive");
  device->addSeparator();
  device->addAction(tr("&Record…"), this, [this] {
    const QString p = ctx_.dialogs->ask_save_path(tr("Record OpenNI2 .oni"), tr("OpenNI recording (*.oni)"), "oni");
    if (!p.isEmpty()) start_recording(p);
  })->setObjectName("record");
  device->addAction(tr("Stop r&ecording"), this, [this] { stop_recording(); })->setObjectName("stopRecording");
  update_actions();
}

void DeviceController::on_live_frame(const RunOutcome& outcome) {
  QString text;
  if (outcome.processed) {
    const LiveStats st = live_->stats();
    text = tr("Live %1 — %2 — %3 — %4 fps, latency %5 ms, %6 received, %7 dropped")
               .arg(live_->uri())
               .arg(QString::fromUtf8(method_display_name(outcome.method)))
               .arg(map_summary(outcome.processed->result.map))
               .arg(st.fps, 0, 'f', 1)
               .arg(st.latency_ms, 0, 'f', 0)
               .arg(st.received)
               .arg(st.dropped);
    if (live_->recording()) text += tr(" — recording (%1 frames)").arg(live_->frames_recorded());
  }
  frames_->show_live_outcome(outcome, text);
}

QStringList DeviceController::refresh_devices() {
  QStringList uris;
  try {
    for (const auto& d : openni2::list_devices(false)) uris << QString::fromStdString(d.uri);
  } catch (const std::exception& e) {
    ctx_.status->show_error(QString::fromStdString(e.what()));
  }
  const QString chosen = device_actions_->checkedAction() ? device_actions_->checkedAction()->data().toString() : QString();
  devices_menu_->clear();
  for (QAction* a : device_actions_->actions()) device_actions_->removeAction(a);
  for (const QString& uri : uris) {
    QAction* a = devices_menu_->addAction(uri);
    a->setData(uri);
    a->setCheckable(true);
    a->setChecked(uri == chosen || (chosen.isEmpty() && uri == uris.first()));
    device_actions_->addAction(a);
  }
  devices_menu_->setEnabled(!uris.isEmpty());
  ctx_.status->set_text(uris.isEmpty() ? tr("No OpenNI2 device found")
                                       : tr("%1 device(s): %2").arg(uris.size()).arg(uris.join(", ")));
  return uris;
}

bool DeviceController::start_live_view(const QString& uri_in) {
  QString uri = uri_in;
  if (uri.isEmpty() && device_actions_->checkedAction()) uri = device_actions_->checkedAction()->data().toString();
  if (uri.isEmpty()) uri = "default";
  ctx_.job->cancel();  // a running sequence stops: the views show the device now
  try {
    live_->start(uri);
  } catch (const std::exception& e) {
    update_actions();
    ctx_.status->show_error(QString::fromStdString(e.what()));
    return false;
  }
  frames_->start_live();
  emit liveStarted();
  ctx_.status->set_text(tr("Live %1: waiting for the first frame…").arg(uri));
  update_actions();
  return true;
}

void DeviceController::stop_live_view() {
  if (live_->recording()) stop_recording();
  live_->stop();
  update_actions();
  frames_->stop_live();
  ctx_.status->set_text(tr("Live view stopped"));
}

bool DeviceController::start_recording(const QString& path) {
  try {
    live_->start_recording(path);
  } catch (const std::exception& e) {
    ctx_.status->show_error(QString::fromStdString(e.what()));
    return false;
  }
  update_actions();
  ctx_.status->set_text(tr("Recording to %1").arg(path));
  return true;
}

bool DeviceController::stop_recording() {
  if (!live_->recording()) return false;
  try {
    const int frames = live_->stop_recording();
    ctx_.status->set_text(tr("Recorded about %1 frame(s)").arg(frames));
  } catch (const std::exception& e) {
    update_actions();
    ctx_.status->show_error(QString::fromStdString(e.what()));
    return false;
  }
  update_actions();
  return true;
}

void DeviceController::update_actions() {
  const bool live = live_->running(), rec = live_->recording();
  auto set = [this](const char* name, bool on) {
    if (auto* a = ctx_.window->findChild<QAction*>(name)) a->setEnabled(on);
  };
  set("startLive", !live);
  set("stopLive", live);
  set("record", live && !rec);
  set("stopRecording", rec);
}

}  // namespace tunnelmap::ui
