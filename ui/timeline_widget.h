#pragma once
// Frame timeline for sequences: slider, step back/forward, play/pause. Frames are numbered from 1
// on screen ("3 / 30"); indices are 0-based in code. A click on the groove jumps to the clicked
// frame (not a page step).
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
  QSlider* slider() const { return slider_; }
  QString label_text() const;

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
