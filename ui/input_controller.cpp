#include "ui/input_controller.h"

#include <QFileDialog>
#include <QFileInfo>
#include <QMainWindow>
#include <QMenu>
#include <QPushButton>
#include <QSettings>

#include "core/recordings/recording.h"
#include "core/util/error.h"
#include "ui/background_job.h"
#include "ui/file_dialogs.h"
#include "ui/recording_opener.h"
#include "ui/window_context.h"
#include "ui/window_status.h"

namespace tunnelmap::ui {

namespace {
constexpr int kMaxRecent = 8;
}  // namespace

InputController::InputController(WindowContext& ctx) : QObject(ctx.window), ctx_(ctx) {
  connect_recording_opener();
}

void InputController::add_open_actions(QMenu* file) {
  file->addAction(tr("&Open…"), this, [this] {
    const QString path = ctx_.dialogs->ask_open_path(tr("Open depth PNG, PCD, recording or dataset.json"),
                                                     tr("Inputs (*.png *.pcd *.oni *.bag *.mcap *.db3 *.json);;All files (*)"));
    if (!path.isEmpty()) open_interactively(path);
  }, QKeySequence::Open)->setObjectName("open");
  file->addAction(tr("Open r&ecording…"), this, [this] {
    const QString path = ctx_.dialogs->ask_open_path(tr("Open robot recording (ROS bag)"),
                                                     tr("Recordings (*.bag *.mcap *.db3 metadata.yaml);;All files (*)"));
    // A rosbag2 folder is chosen by its metadata.yaml.
    if (!path.isEmpty()) open_interactively(QFileInfo(path).fileName() == "metadata.yaml" ? QFileInfo(path).path() : path);
  })->setObjectName("openRecording");
  file->addAction(tr("Open &folder…"), this, [this] {
    const QString dir = QFileDialog::getExistingDirectory(ctx_.window, tr("Open dataset folder"), FileDialogs::last_folder());
    if (!dir.isEmpty()) open_interactively(dir);
  });
  recent_menu_ = file->addMenu(tr("Open &recent"));
  rebuild_recent_menu();
}

bool InputController::open_input(const QString& path) {
  std::shared_ptr<const FrameSource> source;
  try {
    source = tunnelmap::open_input(path.toStdString(), read_options(path));
    if (source->size() == 0) throw InputError(path.toStdString(), "contains no frames");
    source->load(0);  // validate now: a bad file must not replace the current input
  } catch (const std::exception& e) {
    ctx_.status->show_error(QString::fromStdString(e.what()));
    return false;
  }
  adopt_input(path, source);
  return true;
}

bool InputController::open_interactively(const QString& path) {
  if (!recordings::is_recording_path(path.toStdString())) return open_input(path);
  if (!recordings_->open(path, read_options(path))) {
    ctx_.status->show_error(tr("%1: another recording is still being opened").arg(path));
    return false;
  }
  return true;
}

void InputController::adopt_input(const QString& path, std::shared_ptr<const FrameSource> source) {
  ctx_.job->cancel();
  emit inputClosing();
  const QString previous = ctx_.input_path;
  ctx_.source = std::move(source);
  ctx_.input_path = path;
  emit inputOpened(previous);
  add_recent(path);
  QSettings().setValue("files/lastFolder", QFileInfo(path).absolutePath());
  ctx_.status->set_text(tr("Opened %1 (%2 frame(s))").arg(path).arg(ctx_.source->size()));
}

// The opener's progress and Cancel in the status bar, its result adopted as the input.
void InputController::connect_recording_opener() {
  recordings_ = new RecordingOpener(ctx_.window);
  WindowStatus* status = ctx_.status;
  connect(status->cancel_button(), &QPushButton::clicked, recordings_, &RecordingOpener::cancel);
  connect(recordings_, &RecordingOpener::progress, this, [status](int done, int total, const QString& what) {
    status->set_progress(done, total);
    status->set_text(total > 0 ? tr("%1 %2 of %3 frame(s)").arg(what).arg(done).arg(total) : what);
  });
  connect(recordings_, &RecordingOpener::opened, this,
          [this, status](const QString& path, std::shared_ptr<const FrameSource> source) {
            status->hide_progress();
            adopt_input(path, std::move(source));
          });
  connect(recordings_, &RecordingOpener::failed, this, [status](const QString& message) {
    status->hide_progress();
    status->show_error(message);
  });
  connect(recordings_, &RecordingOpener::cancelled, this, [status](const QString& message) {
    status->hide_progress();
    status->set_text(message);
  });
}

void InputController::add_recent(const QString& path) {
  QSettings s;
  QStringList list = s.value("files/recent").toStringList();
  const QString abs = QFileInfo(path).absoluteFilePath();
  list.removeAll(abs);
  list.prepend(abs);
  while (list.size() > kMaxRecent) list.removeLast();
  s.setValue("files/recent", list);
  rebuild_recent_menu();
}

void InputController::rebuild_recent_menu() {
  if (!recent_menu_) return;
  recent_menu_->clear();
  for (const QString& p : QSettings().value("files/recent").toStringList())
    recent_menu_->addAction(p, this, [this, p] { open_interactively(p); });
  recent_menu_->setEnabled(!recent_menu_->isEmpty());
}

}  // namespace tunnelmap::ui
