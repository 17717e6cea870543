// MainWindow, Device menu: OpenNI2 device list, live view on the newest frame, recording.
#include <QAction>
#include <QActionGroup>
#include <QLabel>
#include <QMenu>

#include "sensors/openni/device_list.h"
#include "ui/live_view.h"
#include "ui/main_window.h"
#include "ui/timeline_widget.h"
#include "ui/map_summary.h"
#include "ui/results_panel.h"

namespace tunnelmap::ui {

void MainWindow::on_live_frame(const RunOutcome& outcome) {
  last_ = outcome;
  if (!outcome.processed) return status_label_->setText(outcome.error);  // keep streaming
  show_views(outcome);
  const LiveStats st = live_->stats();
  const auto& m = current_->result.map;
  QString text = tr("Live %1 — %2 — %3 — %4 fps, latency %5 ms, %6 received, %7 dropped")
                     .arg(live_->uri())
                     .arg(QString::fromUtf8(method_display_name(outcome.method)))
                     .arg(map_summary(m))
                     .arg(st.fps, 0, 'f', 1)
                     .arg(st.latency_ms, 0, 'f', 0)
                     .arg(st.received)
                     .arg(st.dropped);
  if (live_->recording()) text += tr(" — recording (%1 frames)").arg(live_->frames_recorded());
  status_label_->setText(text);
  ++shown_runs_;
  emit frameShown();
}

QStringList MainWindow::refresh_devices() {
  QStringList uris;
  try {
    for (const auto& d : openni2::list_devices(false)) uris << QString::fromStdString(d.uri);
  } catch (const std::exception& e) {
    show_error(QString::fromStdString(e.what()));
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
  status_label_->setText(uris.isEmpty() ? tr("No OpenNI2 device found") : tr("%1 device(s): %2").arg(uris.size()).arg(uris.join(", ")));
  return uris;
}

bool MainWindow::start_live_view(const QString& uri_in) {
  QString uri = uri_in;
  if (uri.isEmpty() && device_actions_->checkedAction()) uri = device_actions_->checkedAction()->data().toString();
  if (uri.isEmpty()) uri = "default";
  cancel_.store(true);  // a running sequence stops: the views show the device now
  try {
    live_->start(uri);
  } catch (const std::exception& e) {
    update_device_actions();
    show_error(QString::fromStdString(e.what()));
    return false;
  }
  reset_camera_ = true;
  results_->clear();
  timeline_->set_frame_count(0);  // the camera's frames are not the open input's
  forget_review_state();
  status_label_->setText(tr("Live %1: waiting for the first frame…").arg(uri));
  update_device_actions();
  return true;
}

void MainWindow::stop_live_view() {
  if (live_->recording()) stop_recording();
  live_->stop();
  update_device_actions();
  if (source_) timeline_->set_frame_count(static_cast<int>(source_->size()));
  status_label_->setText(tr("Live view stopped"));
}

bool MainWindow::start_recording(const QString& path) {
  try {
    live_->start_recording(path);
  } catch (const std::exception& e) {
    show_error(QString::fromStdString(e.what()));
    return false;
  }
  update_device_actions();
  status_label_->setText(tr("Recording to %1").arg(path));
  return true;
}

bool MainWindow::stop_recording() {
  if (!live_->recording()) return false;
  try {
    const int frames = live_->stop_recording();
    status_label_->setText(tr("Recorded about %1 frame(s)").arg(frames));
  } catch (const std::exception& e) {
    update_device_actions();
    show_error(QString::fromStdString(e.what()));
    return false;
  }
  update_device_actions();
  return true;
}

void MainWindow::update_device_actions() {
  const bool live = live_->running(), rec = live_->recording();
  auto set = [this](const char* name, bool on) {
    if (auto* a = findChild<QAction*>(name)) a->setEnabled(on);
  };
  set("startLive", !live);
  set("stopLive", live);
  set("record", live && !rec);
  set("stopRecording", rec);
}

}  // namespace tunnelmap::ui
