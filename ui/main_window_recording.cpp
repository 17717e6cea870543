// MainWindow, File > Open recording: the RecordingOpener's progress and Cancel in the status
// bar, its result adopted as the input, its errors shown like every other error.
#include <QLabel>
#include <QProgressBar>
#include <QPushButton>

#include "ui/main_window.h"
#include "ui/recording_opener.h"

namespace tunnelmap::ui {

void MainWindow::connect_recording_opener() {
  recordings_ = new RecordingOpener(this);
  connect(cancel_button_, &QPushButton::clicked, recordings_, &RecordingOpener::cancel);
  connect(recordings_, &RecordingOpener::progress, this, [this](int done, int total, const QString& what) {
    progress_->setRange(0, total);
    progress_->setValue(done);
    progress_->show();
    cancel_button_->show();
    status_label_->setText(total > 0 ? tr("%1 %2 of %3 frame(s)").arg(what).arg(done).arg(total) : what);
  });
  const auto idle = [this] {
    progress_->hide();
    cancel_button_->hide();
  };
  connect(recordings_, &RecordingOpener::opened, this,
          [this, idle](const QString& path, std::shared_ptr<const FrameSource> source) {
            idle();
            adopt_input(path, std::move(source));
          });
  connect(recordings_, &RecordingOpener::failed, this, [this, idle](const QString& message) {
    idle();
    show_error(message);
  });
  connect(recordings_, &RecordingOpener::cancelled, this, [this, idle](const QString& message) {
    idle();
    status_label_->setText(message);
  });
}

}  // namespace tunnelmap::ui
