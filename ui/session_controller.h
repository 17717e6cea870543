#pragma once
// Review sessions (File > Open/Save review session: the input, parameters, preset, method,
// layers, camera, frame, measurements, intrinsics, map and cut, as "tunnelmap-session/1" JSON),
// File > Export 3D view, and the layers, method and camera kept in QSettings between runs.
#include <QObject>
#include <QString>
#include <optional>
#include <vector>

#include "ui/review_session.h"
#include "ui/scene/measurement.h"

class QMenu;

namespace tunnelmap::ui {

class FrameController;
class InputController;
class IntrinsicsController;
class PresetController;
class ReviewController;
struct WindowContext;

struct SessionParts {
  FrameController* frames;
  InputController* inputs;
  IntrinsicsController* intrinsics;
  PresetController* presets;
  ReviewController* review;
};

class SessionController : public QObject {
  Q_OBJECT
 public:
  SessionController(WindowContext& ctx, const SessionParts& parts);

  void add_actions(QMenu* file);
  bool save_session(const QString& path);  // atomic; an error when no input is open
  bool open_session(const QString& path);  // all of it, or one error naming the file and no change
  bool export_view3d(const QString& path, int width, int height);  // the 3D scene alone, off-screen
  void save_view_settings();     // layers, method, camera into QSettings
  void restore_view_settings();  // ... and back on the next start

 private:
  ReviewSession current_session() const;
  void apply_layers(const std::vector<std::string>& on);
  void apply_pending_view();  // once the frame a session asked for is shown

  WindowContext& ctx_;
  SessionParts parts_;
  QString preset_path_;  // of the session that set the preset's name
  std::optional<SessionCamera> pending_camera_;
  std::optional<std::vector<scene::Measurement>> pending_measurements_;
};

}  // namespace tunnelmap::ui
