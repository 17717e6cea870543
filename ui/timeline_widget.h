#pragma once
// Frame timeline for sequences: slider, step back/forward, play/pause.
#include <QTimer>
#include <QWidget>

class QLabel;
class QSlider;
class QToolButton;

namespace tunnelmap::ui {

class TimelineWidget : public QWidget {
  Q_OBJECT
 public:
  explicit TimelineWidget(QWidget* parent = nullptr);
  void set_frame_count(int count);  // 0 or 1 disables the controls
  void set_frame(int index);        // no frameRequested signal
  int frame() const;
  void stop();
  bool playing() const { return timer_.isActive(); }

 signals:
  void frameRequested(int index);

 private:
  void step(int delta);
  QSlider* slider_;
  QLabel* label_;
  QToolButton* play_;
  QTimer timer_;
  int count_ = 0;
  bool updating_ = false;
};

}  // namespace tunnelmap::ui
