#pragma once
// The window's status bar and Messages dock, shared by every controller: one status line, a
// progress bar with its Cancel button for the background job, and the error log. Every error
// becomes one line here and one entry in the Messages dock, never a dialog.
#include <QObject>
#include <QString>
#include <functional>

class QDockWidget;
class QLabel;
class QMainWindow;
class QProgressBar;
class QPushButton;
class QToolButton;

namespace tunnelmap::ui {

class MessageLog;

class WindowStatus : public QObject {
  Q_OBJECT
 public:
  explicit WindowStatus(QMainWindow* window);
  // Progress, Cancel and the message button, right of the permanent widgets added before.
  void add_permanent_widgets();

  void set_text(const QString& text);
  QString text() const;
  void flash(const QString& text, int ms = 5000);  // a transient note over the status line
  void show_error(const QString& message);         // status line + Messages dock + errorShown
  QString last_error() const { return last_error_; }
  void note(const QString& message);               // Messages dock only (not an error)
  // Runs `work`; its exception becomes the error (false). On success, `done` (if not empty)
  // becomes the status line.
  bool run_or_show_error(const std::function<void()>& work, const QString& done = {});
  MessageLog* messages() const { return messages_; }

  // The progress of the one background job (or of a recording being opened), with Cancel.
  void show_progress(int maximum);  // at 0
  void set_progress(int value);
  void set_progress(int value, int maximum);  // shown, with a maximum that may change
  void hide_progress();
  QPushButton* cancel_button() const { return cancel_button_; }

 signals:
  void errorShown(const QString& message);

 private:
  void build_messages_dock(QMainWindow* window);

  QMainWindow* window_;
  QLabel* label_;
  QProgressBar* progress_;
  QPushButton* cancel_button_;
  MessageLog* messages_ = nullptr;
  QDockWidget* messages_dock_ = nullptr;
  QToolButton* messages_button_ = nullptr;
  QString last_error_;
};

}  // namespace tunnelmap::ui
