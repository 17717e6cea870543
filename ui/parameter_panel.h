#pragma once
// The parameter panel: one ParameterRow per entry of the core parameter table, grouped by the
// key's prefix ("cloud", "normals", "grow", "tunnel", "zones"), plus reset-all and presets.
#include <QMap>
#include <QWidget>

#include "core/params/parameters.h"

namespace tunnelmap::ui {

class ParameterRow;

class ParameterPanel : public QWidget {
  Q_OBJECT
 public:
  explicit ParameterPanel(QWidget* parent = nullptr);

  const Parameters& parameters() const { return params_; }
  void set_parameters(const Parameters& p);  // updates every row, emits parametersChanged once
  ParameterRow* row(const QString& key) const { return rows_.value(key); }

 signals:
  // `immediate`: the edit is complete (slider released, spin box committed, reset, preset):
  // run now; otherwise the caller debounces.
  void parametersChanged(bool immediate);
  void loadPresetRequested();
  void savePresetRequested();

 private:
  Parameters params_;
  QMap<QString, ParameterRow*> rows_;
};

}  // namespace tunnelmap::ui
