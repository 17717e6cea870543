#include "ui/recording_opener.h"

#include <QDialog>
#include <QtConcurrent/QtConcurrentRun>

#include "core/recordings/recording_dataset.h"
#include "core/util/error.h"
#include "ui/recording_dialog.h"

namespace tunnelmap::ui {

using namespace recordings;

namespace {
struct Cancelled {};  // thrown through the extraction by the progress callback
}  // namespace

RecordingOpener::RecordingOpener(QWidget* window) : QObject(window), window_(window) {
  choose_topics = [](RecordingDialog& dialog) { return dialog.exec() == QDialog::Accepted; };
}

RecordingOpener::~RecordingOpener() {
  cancel_.store(true);
  worker_.waitForFinished();
}

bool RecordingOpener::open(const QString& path, const ReadOptions& base) {
  if (busy_) return false;
  busy_ = true;
  cancel_.store(false);
  emit progress(0, 0, tr("Indexing %1…").arg(path));
  worker_ = QtConcurrent::run([this, path, base] {
    try {
      std::shared_ptr<Recording> rec = open_recording(path.toStdString());
      const Roles roles = classify_topics(*rec);
      QMetaObject::invokeMethod(this, [=] { on_indexed(path, base, rec, roles); });
    } catch (const std::exception& e) {
      const QString message = QString::fromStdString(e.what());
      QMetaObject::invokeMethod(this, [this, message] {
        finish();
        emit failed(message);
      });
    }
  });
  return true;
}

void RecordingOpener::on_indexed(const QString& path, const ReadOptions& base, std::shared_ptr<Recording> rec,
                                 const Roles& roles) {
  try {  // nothing to choose without a depth topic: the CLI's one-line reason, no dialog
    recordings::choose_topics(*rec, roles, RecordingOptions{});
  } catch (const InputError& e) {
    finish();
    emit failed(QString::fromStdString(e.what()));
    return;
  } catch (const std::exception&) {
    // Several candidates for a role: the user chooses below.
  }
  RecordingDialog dialog(path, *rec, roles, window_);
  if (cancel_.load() || !choose_topics(dialog)) {
    finish();
    emit cancelled(tr("Not opened: %1").arg(path));
    return;
  }
  ReadOptions opt = base;
  opt.recording = dialog.options();
  extract(path, opt, rec, dialog.depth_frames() / std::max(1, opt.recording.every));
}

void RecordingOpener::extract(const QString& path, const ReadOptions& opt, std::shared_ptr<Recording> rec, int total) {
  const QString what = tr("Reading %1…").arg(path);
  emit progress(0, total, what);
  worker_ = QtConcurrent::run([this, path, opt, rec, total, what] {
    try {
      std::shared_ptr<const FrameSource> source =
          extract_recording(*rec, path.toStdString(), opt, [&](std::size_t frames) {
            if (cancel_.load()) throw Cancelled{};
            const int done = static_cast<int>(frames);
            QMetaObject::invokeMethod(this, [=] { emit progress(done, std::max(total, done), what); });
          });
      source->load(0);  // validate now: a bad recording must not replace the current input
      QMetaObject::invokeMethod(this, [this, path, source] {
        finish();
        emit opened(path, source);
      });
    } catch (const Cancelled&) {
      QMetaObject::invokeMethod(this, [this, path] {
        finish();
        emit cancelled(tr("Cancelled: %1 not opened").arg(path));
      });
    } catch (const std::exception& e) {
      const QString message = QString::fromStdString(e.what());
      QMetaObject::invokeMethod(this, [this, message] {
        finish();
        emit failed(message);
      });
    }
  });
}

void RecordingOpener::finish() { busy_ = false; }

}  // namespace tunnelmap::ui
