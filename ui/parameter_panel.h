#pragma once
// The parameter panel: one ParameterRow per entry of the core parameter table, grouped by the
// key's prefix ("cloud", "normals", "grow", "tunnel", "zones", ...), plus reset-all and presets.
// Every completed change (slider released, spin box step, ↺, Reset all, preset) is one step on
// an undo stack (Edit > Undo / Redo); a slider drag is one step, not one per pixel.
// Rows that only another method reads are hidden; rows the growing order does not read are
// greyed, with the reason as their tooltip (parameter_relevance, the same rule core tests).
#include <QMap>
#include <QWidget>
#include <functional>

#include "core/baselines/method.h"
#include "core/params/parameters.h"

class QGroupBox;
class QUndoStack;

namespace tunnelmap::ui {

class ParameterRow;

class ParameterPanel : public QWidget {
  Q_OBJECT
 public:
  explicit ParameterPanel(QWidget* parent = nullptr);

  const Parameters& parameters() const { return params_; }
  // Updates every row, emits parametersChanged once; an undoable step named `what` when the
  // values change (presets, Reset all).
  void set_parameters(const Parameters& p, const QString& what = QString());
  // The values at start-up (saved settings): no undo step, the history starts empty.
  void set_initial_parameters(const Parameters& p);
  ParameterRow* row(const QString& key) const { return rows_.value(key); }
  // The detection method the rows are shown for.
  void set_method(Method method);
  QUndoStack* undo_stack() const { return undo_; }
  // Asked before Reset all; false keeps the values. Default: a question box.
  std::function<bool()> confirm_reset;

 signals:
  // `immediate`: the edit is complete (slider released, spin box committed, reset, preset):
  // run now; otherwise the caller debounces.
  void parametersChanged(bool immediate);
  void loadPresetRequested();
  void savePresetRequested();

 private:
  friend class ParameterChange;
  void apply(const Parameters& p);  // rows + values + parametersChanged(true), no undo step
  void commit(const QString& what);  // pushes committed_ -> params_ if they differ
  void update_relevance();           // rows shown, greyed or hidden for the method and values

  Parameters params_;
  Parameters committed_;  // the values of the last undo step
  QUndoStack* undo_;
  QMap<QString, ParameterRow*> rows_;
  QMap<QString, QGroupBox*> groups_;  // by key prefix
  Method method_ = Method::Pgc;
};

}  // namespace tunnelmap::ui
