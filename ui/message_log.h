#pragma once
// The one place errors go: a list of timestamped messages (newest last) shown in the Messages
// dock, opened from the status bar's message button. Never a dialog, so errors never pile up
// as windows and never block a batch run.
#include <QWidget>

class QListWidget;

namespace tunnelmap::ui {

class MessageLog : public QWidget {
  Q_OBJECT
 public:
  explicit MessageLog(QWidget* parent = nullptr);
  void add(const QString& message);  // "hh:mm:ss  message"
  void clear();
  int count() const;
  QString message(int i) const;  // as added, without the time

 signals:
  void changed(int count);

 private:
  QListWidget* list_;
};

}  // namespace tunnelmap::ui
