#include "ui/timeline_widget.h"

#include <QHBoxLayout>
#include <QLabel>
#include <QProxyStyle>
#include <QSlider>
#include <QToolButton>

namespace tunnelmap::ui {

namespace {
// The left button sets the slider to the clicked position (the platform style pages by 10).
class JumpToClickStyle : public QProxyStyle {
 public:
  int styleHint(StyleHint hint, const QStyleOption* option, const QWidget* widget,
                QStyleHintReturn* ret) const override {
    if (hint == QStyle::SH_Slider_AbsoluteSetButtons) return Qt::LeftButton;
    return QProxyStyle::styleHint(hint, option, widget, ret);
  }
};
}  // namespace

TimelineWidget::TimelineWidget(QWidget* parent) : QWidget(parent) {
  auto* layout = new QHBoxLayout(this);
  layout->setContentsMargins(4, 0, 4, 0);
  auto* back = new QToolButton(this);
  back->setText("◀");
  back->setToolTip(tr("Previous frame"));
  play_ = new QToolButton(this);
  play_->setText("▶");
  play_->setCheckable(true);
  play_->setToolTip(tr("Play / pause"));
  auto* fwd = new QToolButton(this);
  fwd->setText("▶|");
  fwd->setToolTip(tr("Next frame"));
  slider_ = new QSlider(Qt::Horizontal, this);
  slider_->setObjectName("timelineSlider");
  auto* style = new JumpToClickStyle;
  style->setParent(slider_);
  slider_->setStyle(style);
  slider_->setToolTip(tr("Click a frame to show it. Keys: ←/→ previous/next frame, PgUp/PgDn 10 frames, Home/End first/last"));
  label_ = new QLabel(this);
  layout->addWidget(back);
  layout->addWidget(play_);
  layout->addWidget(fwd);
  layout->addWidget(slider_, 1);
  layout->addWidget(label_);
  timer_.setInterval(200);
  connect(back, &QToolButton::clicked, this, [this] { step(-1); });
  connect(fwd, &QToolButton::clicked, this, [this] { step(1); });
  connect(play_, &QToolButton::toggled, this, [this](bool on) { on ? timer_.start() : timer_.stop(); });
  connect(&timer_, &QTimer::timeout, this, [this] {
    if (frame() + 1 >= count_) return stop();
    step(1);
  });
  connect(slider_, &QSlider::valueChanged, this, [this](int v) {
    label_->setText(tr("%1 / %2").arg(v + 1).arg(count_));
    if (!updating_) emit frameRequested(v);
  });
  set_frame_count(0);
}

void TimelineWidget::set_frame_count(int count) {
  count_ = count;
  stop();
  updating_ = true;
  slider_->setRange(0, std::max(0, count - 1));
  slider_->setValue(0);
  updating_ = false;
  label_->setText(count > 0 ? tr("1 / %1").arg(count) : tr("no input"));
  setEnabled(count > 1);
}

void TimelineWidget::set_frame(int index) {
  updating_ = true;
  slider_->setValue(index);
  updating_ = false;
}

int TimelineWidget::frame() const { return slider_->value(); }

QString TimelineWidget::label_text() const { return label_->text(); }

void TimelineWidget::stop() {
  timer_.stop();
  play_->setChecked(false);
}

void TimelineWidget::step(int delta) {
  const int next = std::clamp(frame() + delta, 0, std::max(0, count_ - 1));
  if (next != frame()) slider_->setValue(next);
}

}  // namespace tunnelmap::ui
