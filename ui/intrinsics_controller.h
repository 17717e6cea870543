#pragma once
// The intrinsics of a PNG input (a depth PNG or a folder of them, which carry none): the
// Camera intrinsics dock shows the shown frame's fx, fy, cx, cy; Apply re-reads the input with
// new ones and remembers them per input (QSettings), and a session or --intrinsics gives them
// for the next open of an input.
#include <QObject>
#include <QString>
#include <array>
#include <map>
#include <optional>

#include "core/io/read_options.h"

class QDockWidget;
class QDoubleSpinBox;
class QLabel;
class QMenu;

namespace tunnelmap::ui {

class FrameController;
struct WindowContext;

// A depth PNG or a plain folder of depth PNGs: no dataset or sidecar gives its intrinsics.
bool takes_user_intrinsics(const QString& input);

class IntrinsicsController : public QObject {
  Q_OBJECT
 public:
  IntrinsicsController(WindowContext& ctx, FrameController* frames);

  void add_actions(QMenu* file);  // File > Camera intrinsics (the dock)
  ReadOptions read_options_for(const QString& input) const;
  void use_intrinsics(const QString& input, const Intrinsics& K);  // for the next open of `input`
  bool set_intrinsics(const Intrinsics& K);  // re-reads the open PNG input; remembered per input
  // The intrinsics the user gave `input`, when it is an input that takes them.
  std::optional<Intrinsics> user_intrinsics(const QString& input) const;

 private:
  void build_dock();
  void fill_dock();  // from the shown frame

  WindowContext& ctx_;
  FrameController* frames_;
  std::map<QString, Intrinsics> given_;  // absolute input path -> given this run
  QString panel_input_;                  // input the panel was filled for
  QDockWidget* dock_ = nullptr;
  std::array<QDoubleSpinBox*, 4> k_{};   // fx, fy, cx, cy
  QLabel* note_ = nullptr;
};

}  // namespace tunnelmap::ui
