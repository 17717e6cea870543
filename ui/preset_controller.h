#pragma once
// Parameter presets: load and save (the parameter panel's buttons), the loaded preset's name in
// the title and the status bar with "(modified)" after an edit, the preset matching the open
// dataset's tunnel kind offered by a status-bar button, and a design cleared when the input it
// was typed for is replaced.
#include <QObject>
#include <QString>

#include "core/params/parameters.h"

class QLabel;
class QPushButton;

namespace tunnelmap::ui {

struct WindowContext;

class PresetController : public QObject {
  Q_OBJECT
 public:
  explicit PresetController(WindowContext& ctx);

  bool load_preset(const QString& path);  // its name is shown in the title and status bar
  bool save_preset(const QString& path);
  QString preset_name() const { return name_; }  // "defaults" until a preset is loaded
  const Parameters& preset_parameters() const { return params_; }
  // A session's preset: what "(modified)" is relative to from now on.
  void set_reference(const QString& name, const Parameters& params);
  void update_status();   // title and status bar: input, preset, "(modified)"
  void offer_matching_preset();
  // A design typed for `previous_input` is not the next input's: cleared as one undo step.
  void clear_design(const QString& previous_input);

 private:
  WindowContext& ctx_;
  QLabel* label_;
  QPushButton* offer_;
  QString name_ = "defaults";
  Parameters params_;  // the values the preset set (defaults: Parameters())
};

}  // namespace tunnelmap::ui
