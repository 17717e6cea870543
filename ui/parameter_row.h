#pragma once
// One parameter of the table: label, slider, spin box (with unit), reset button; the
// description is the tooltip. The slider works in steps of ParameterSpec::step.
#include <QWidget>

#include "core/params/parameter_table.h"

class QDoubleSpinBox;
class QSlider;
class QToolButton;

namespace tunnelmap::ui {

class ParameterRow : public QWidget {
  Q_OBJECT
 public:
  ParameterRow(const ParameterSpec& spec, QWidget* parent = nullptr);

  const ParameterSpec& spec() const { return spec_; }
  double value() const;
  void set_value(double v);  // no valueEdited signal
  QSlider* slider() const { return slider_; }
  QDoubleSpinBox* spin_box() const { return spin_; }

 signals:
  void valueEdited(const QString& key, double value);
  void editFinished(const QString& key);  // slider released or spin box committed

 private:
  int to_slider(double v) const;
  double from_slider(int s) const;
  void update_reset_state();

  ParameterSpec spec_;
  QSlider* slider_;
  QDoubleSpinBox* spin_;
  QToolButton* reset_;
  bool updating_ = false;
};

}  // namespace tunnelmap::ui
