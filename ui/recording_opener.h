#pragma once
// File > Open recording: indexes a robot recording on a worker thread, asks for its topics
// (RecordingDialog), then extracts the chosen sequence on a worker thread, reporting progress
// and honouring Cancel. The window adopts the source when `opened` is emitted; on failure or
// cancel the input that was open stays.
#include <QFuture>
#include <QObject>
#include <QString>
#include <atomic>
#include <functional>
#include <map>
#include <memory>
#include <string>

#include "core/io/frame_source.h"
#include "core/io/read_options.h"
#include "core/recordings/recording.h"
#include "core/recordings/topic_roles.h"

class QWidget;

namespace tunnelmap::ui {

class RecordingDialog;

class RecordingOpener : public QObject {
  Q_OBJECT
 public:
  explicit RecordingOpener(QWidget* window);
  ~RecordingOpener() override;  // cancels and waits for the worker

  // Starts opening `path` with `base` (intrinsics, up); false when one is already opening.
  bool open(const QString& path, const ReadOptions& base);
  void cancel() { cancel_.store(true); }
  bool busy() const { return busy_; }

  // The topic choice: true to open. The default shows the dialog modally; tests set their own.
  std::function<bool(RecordingDialog&)> choose_topics;

 signals:
  void progress(int done, int total, const QString& what);  // total 0: no count yet
  void opened(const QString& path, std::shared_ptr<const tunnelmap::FrameSource> source);
  void failed(const QString& message);
  void cancelled(const QString& message);

 private:
  using Roles = std::map<std::string, recordings::TopicRole>;
  void on_indexed(const QString& path, const ReadOptions& base, std::shared_ptr<recordings::Recording> rec,
                  const Roles& roles);
  void extract(const QString& path, const ReadOptions& opt, std::shared_ptr<recordings::Recording> rec, int total);
  void finish();

  QWidget* window_;
  QFuture<void> worker_;
  std::atomic<bool> cancel_{false};
  bool busy_ = false;
};

}  // namespace tunnelmap::ui
