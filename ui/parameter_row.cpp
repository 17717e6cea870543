#include "ui/parameter_row.h"

#include <QAbstractScrollArea>
#include <QCoreApplication>
#include <QDoubleSpinBox>
#include <QScrollBar>
#include <QHBoxLayout>
#include <QLabel>
#include <QSlider>
#include <QEvent>
#include <QToolButton>
#include <algorithm>
#include <array>
#include <cmath>

namespace tunnelmap::ui {

ParameterRow::ParameterRow(const ParameterSpec& spec, QWidget* parent)
    : QWidget(parent), spec_(spec), scale_(spec) {
  setObjectName(QString::fromStdString(spec.key));
  auto* layout = new QHBoxLayout(this);
  layout->setContentsMargins(0, 0, 0, 0);
  label_ = new QLabel(QString::fromStdString(spec.label), this);
  label_->setMinimumWidth(175);  // the longest label: every slider starts at the same x
  slider_ = new QSlider(Qt::Horizontal, this);
  slider_->setRange(0, scale_.positions());
  slider_->setPageStep(std::max(1, scale_.positions() / 20));
  slider_->setObjectName("slider");
  slider_->setFocusPolicy(Qt::StrongFocus);  // not Wheel focus: the wheel scrolls the panel
  spin_ = new QDoubleSpinBox(this);
  spin_->setObjectName("spin");
  spin_->setRange(spec.min, spec.max);
  spin_->setSingleStep(spec.step);
  int decimals = 0;
  for (double s = spec.step; decimals < 6 && std::fabs(s - std::round(s)) > 1e-9; s *= 10) ++decimals;
  spin_->setDecimals(decimals);
  QString unit = QString::fromStdString(spec.unit);
  if (unit == "m2") unit = QStringLiteral("m²");
  if (!unit.isEmpty()) spin_->setSuffix(" " + unit);
  spin_->setKeyboardTracking(false);
  spin_->setFixedWidth(96);  // same width on every row: sliders and values line up
  spin_->setFocusPolicy(Qt::StrongFocus);
  slider_->installEventFilter(this);
  spin_->installEventFilter(this);
  reset_ = new QToolButton(this);
  reset_->setText(QStringLiteral("↺"));
  reset_->setToolTip(tr("Reset to default (%1)").arg(spec.default_value));
  layout->addWidget(label_);
  layout->addWidget(slider_, 1);
  layout->addWidget(spin_);
  layout->addWidget(reset_);
  tooltip_ = QString::fromStdString(spec.description) +
                      tr("\nRange %1 – %2 %3, default %4. Stage: %5.")
                          .arg(spec.min)
                          .arg(spec.max)
                          .arg(QString::fromStdString(spec.unit))
                          .arg(spec.default_value)
                          .arg(stage_name(spec.stage));
  for (QWidget* w : described_widgets()) w->setToolTip(tooltip_);

  set_value(spec.default_value);
  connect(slider_, &QSlider::valueChanged, this, [this](int s) {
    if (updating_) return;
    show_value(scale_.from_slider(s), false);  // the slider stays where the hand put it
    emit valueEdited(QString::fromStdString(spec_.key), value());
    // A drag is one edit, finished on release; a click on the groove or a key is one by itself.
    if (!slider_->isSliderDown()) emit editFinished(QString::fromStdString(spec_.key));
  });
  connect(slider_, &QSlider::sliderReleased, this,
          [this] { emit editFinished(QString::fromStdString(spec_.key)); });
  connect(spin_, qOverload<double>(&QDoubleSpinBox::valueChanged), this, [this](double v) {
    if (updating_) return;
    set_value(v);
    emit valueEdited(QString::fromStdString(spec_.key), value());
    emit editFinished(QString::fromStdString(spec_.key));
  });
  connect(reset_, &QToolButton::clicked, this, [this] {
    set_value(spec_.default_value);
    emit valueEdited(QString::fromStdString(spec_.key), value());
    emit editFinished(QString::fromStdString(spec_.key));
  });
}

double ParameterRow::value() const {
  double v = spin_->value();
  if (spec_.integer) v = std::round(v);
  return v;
}

std::array<QWidget*, 3> ParameterRow::described_widgets() const { return {label_, slider_, spin_}; }

void ParameterRow::set_value(double v) { show_value(v, true); }

void ParameterRow::show_value(double v, bool move_slider) {
  updating_ = true;
  v = std::clamp(v, spec_.min, spec_.max);
  if (spec_.integer) v = std::round(v);
  spin_->setValue(v);
  if (move_slider) slider_->setValue(scale_.to_slider(v));
  updating_ = false;
  update_reset_state();
}

void ParameterRow::set_unused_reason(const QString& reason) {
  setEnabled(reason.isEmpty());
  const QString tip = reason.isEmpty() ? tooltip_ : tr("Not used now: %1.\n\n%2").arg(reason, tooltip_);
  for (QWidget* w : described_widgets()) w->setToolTip(tip);
}

// The wheel goes to the scroll bar of the panel the row is in, never to the slider or the spin
// box: scrolling a long panel must not edit whatever value passes under the pointer.
bool ParameterRow::eventFilter(QObject* watched, QEvent* event) {
  if (event->type() != QEvent::Wheel) return QWidget::eventFilter(watched, event);
  for (QWidget* p = parentWidget(); p; p = p->parentWidget()) {
    if (auto* area = qobject_cast<QAbstractScrollArea*>(p)) {
      QCoreApplication::sendEvent(area->verticalScrollBar(), event);
      break;
    }
  }
  return true;
}

void ParameterRow::update_reset_state() {
  const bool is_default = std::fabs(value() - spec_.default_value) < spec_.step * 1e-3;
  reset_->setEnabled(!is_default);
  QFont f = spin_->font();
  f.setBold(!is_default);
  spin_->setFont(f);
}

}  // namespace tunnelmap::ui
