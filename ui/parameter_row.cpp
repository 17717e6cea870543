#include "ui/parameter_row.h"

#include <QDoubleSpinBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QSlider>
#include <QToolButton>
#include <cmath>

namespace tunnelmap::ui {

ParameterRow::ParameterRow(const ParameterSpec& spec, QWidget* parent) : QWidget(parent), spec_(spec) {
  setObjectName(QString::fromStdString(spec.key));
  auto* layout = new QHBoxLayout(this);
  layout->setContentsMargins(0, 0, 0, 0);
  auto* label = new QLabel(QString::fromStdString(spec.label), this);
  label->setMinimumWidth(175);  // the longest label: every slider starts at the same x
  slider_ = new QSlider(Qt::Horizontal, this);
  slider_->setRange(0, to_slider(spec.max));
  slider_->setObjectName("slider");
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
  reset_ = new QToolButton(this);
  reset_->setText(QStringLiteral("↺"));
  reset_->setToolTip(tr("Reset to default (%1)").arg(spec.default_value));
  layout->addWidget(label);
  layout->addWidget(slider_, 1);
  layout->addWidget(spin_);
  layout->addWidget(reset_);
  const QString tip = QString::fromStdString(spec.description) +
                      tr("\nRange %1 – %2 %3, default %4. Stage: %5.")
                          .arg(spec.min)
                          .arg(spec.max)
                          .arg(QString::fromStdString(spec.unit))
                          .arg(spec.default_value)
                          .arg(stage_name(spec.stage));
  for (QWidget* w : {static_cast<QWidget*>(label), static_cast<QWidget*>(slider_),
                     static_cast<QWidget*>(spin_)})
    w->setToolTip(tip);

  set_value(spec.default_value);
  connect(slider_, &QSlider::valueChanged, this, [this](int s) {
    if (updating_) return;
    double v = from_slider(s);
    set_value(v);
    emit valueEdited(QString::fromStdString(spec_.key), value());
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

int ParameterRow::to_slider(double v) const {
  return static_cast<int>(std::lround((v - spec_.min) / spec_.step));
}

double ParameterRow::from_slider(int s) const {
  return std::min(spec_.max, spec_.min + s * spec_.step);
}

double ParameterRow::value() const {
  double v = spin_->value();
  if (spec_.integer) v = std::round(v);
  return v;
}

void ParameterRow::set_value(double v) {
  updating_ = true;
  v = std::clamp(v, spec_.min, spec_.max);
  if (spec_.integer) v = std::round(v);
  spin_->setValue(v);
  slider_->setValue(to_slider(v));
  updating_ = false;
  update_reset_state();
}

void ParameterRow::update_reset_state() {
  const bool is_default = std::fabs(value() - spec_.default_value) < spec_.step * 1e-3;
  reset_->setEnabled(!is_default);
  QFont f = spin_->font();
  f.setBold(!is_default);
  spin_->setFont(f);
}

}  // namespace tunnelmap::ui
