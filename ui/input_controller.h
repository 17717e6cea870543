#pragma once
// The open input: File > Open (depth PNG, PCD, folder, dataset, TUM, .oni), Open recording
// (ROS bags with their topic dialog, progress and Cancel), Open folder, Open recent, and drag
// and drop. A bad input is one error and keeps the input that was open; a good one replaces it
// and everything that belonged to the previous one.
#include <QObject>
#include <functional>
#include <memory>

#include "core/io/frame_source.h"
#include "core/io/read_options.h"

class QMenu;

namespace tunnelmap::ui {

class RecordingOpener;
struct WindowContext;

class InputController : public QObject {
  Q_OBJECT
 public:
  explicit InputController(WindowContext& ctx);

  void add_open_actions(QMenu* file);  // Open…, Open recording…, Open folder…, Open recent
  // All return false and show the error on failure.
  bool open_input(const QString& path);  // recordings with the topics the CLI would choose
  // File > Open, Open recording, drag and drop, recent files: a recording is indexed, its
  // topics chosen in a dialog and its frames read on a worker, with progress and Cancel
  // (true: started; the input changes when it is done).
  bool open_interactively(const QString& path);
  RecordingOpener* recording_opener() const { return recordings_; }
  std::function<ReadOptions(const QString& input)> read_options = [](const QString&) { return ReadOptions(); };

 signals:
  void inputClosing();                               // the previous input's state goes first
  void inputOpened(const QString& previous_input);   // ctx.source and ctx.input_path are the new one

 private:
  void adopt_input(const QString& path, std::shared_ptr<const FrameSource> source);
  void connect_recording_opener();
  void add_recent(const QString& path);
  void rebuild_recent_menu();

  WindowContext& ctx_;
  RecordingOpener* recordings_ = nullptr;
  QMenu* recent_menu_ = nullptr;
};

}  // namespace tunnelmap::ui
