#pragma once
// One parameter of the table: label, slider, spin box (with unit), reset button; the
// description is the tooltip. The slider works in steps of ParameterSpec::step, logarithmic
// when the range spans decades (SliderScale). Every completed edit (a drag released, a click on
// the groove, a key, a spin box step, the reset) emits editFinished once: one undo step. The
// mouse wheel never edits: it scrolls the panel the row is in.
#include <QWidget>
#include <array>

#include "core/params/parameter_table.h"
#include "ui/slider_scale.h"

class QDoubleSpinBox;
class QLabel;
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
  const SliderScale& scale() const { return scale_; }
  // Greys the row out with `reason` as its tooltip ("" = in use again).
  void set_unused_reason(const QString& reason);

 signals:
  void valueEdited(const QString& key, double value);
  void editFinished(const QString& key);  // slider released or spin box committed

 protected:
  bool eventFilter(QObject* watched, QEvent* event) override;

 private:
  void show_value(double v, bool move_slider);
  std::array<QWidget*, 3> described_widgets() const;  // label, slider, spin box: the tooltip's
  void update_reset_state();

  ParameterSpec spec_;
  SliderScale scale_;
  QString tooltip_;
  QLabel* label_;
  QSlider* slider_;
  QDoubleSpinBox* spin_;
  QToolButton* reset_;
  bool updating_ = false;
};

}  // namespace tunnelmap::ui
