#include "ui/session_controller.h"

#include <QAction>
#include <QFileInfo>
#include <QInputDialog>
#include <QMainWindow>
#include <QMenu>
#include <QSettings>
#include <algorithm>

#include <vtkCamera.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>

#include "core/util/error.h"
#include "ui/cross_section_panel.h"
#include "ui/file_dialogs.h"
#include "ui/frame_controller.h"
#include "ui/input_controller.h"
#include "ui/intrinsics_controller.h"
#include "ui/parameter_panel.h"
#include "ui/preset_controller.h"
#include "ui/review_controller.h"
#include "ui/view3d_export.h"
#include "ui/view3d_widget.h"
#include "ui/window_context.h"
#include "ui/window_status.h"

namespace tunnelmap::ui {

namespace {

SessionCamera camera_of(vtkRenderer* renderer) {
  vtkCamera* c = renderer->GetActiveCamera();
  SessionCamera s;
  c->GetPosition(s.position.data());
  c->GetFocalPoint(s.focal_point.data());
  c->GetViewUp(s.view_up.data());
  s.view_angle = c->GetViewAngle();
  return s;
}

void apply_camera(vtkRenderer* renderer, const SessionCamera& s) {
  vtkCamera* c = renderer->GetActiveCamera();
  c->SetPosition(s.position.data());
  c->SetFocalPoint(s.focal_point.data());
  c->SetViewUp(s.view_up.data());
  c->SetViewAngle(s.view_angle);
  renderer->ResetCameraClippingRange();
}

// The session's input opened with its intrinsics and its frame inside it; InputError naming
// the session file otherwise, before anything changes.
void check_session_input(const ReviewSession& s, const ReadOptions& base, const std::string& file) {
  ReadOptions opt = base;
  if (s.intrinsics) opt.intrinsics = s.intrinsics;
  std::shared_ptr<const FrameSource> probe;
  try {
    probe = tunnelmap::open_input(s.input, opt);
  } catch (const std::exception& e) {
    throw InputError(file, std::string("input: ") + e.what());
  }
  if (probe->size() == 0) throw InputError(file, "input " + s.input + " contains no frames");
  if (static_cast<std::size_t>(s.frame) > probe->size())
    throw InputError(file, "frame " + std::to_string(s.frame) + " is past the input's " +
                               std::to_string(probe->size()) + " frame(s)");
}

}  // namespace

SessionController::SessionController(WindowContext& ctx, const SessionParts& parts)
    : QObject(ctx.window), ctx_(ctx), parts_(parts) {
  connect(parts_.frames, &FrameController::frameShown, this, &SessionController::apply_pending_view);
}

void SessionController::add_actions(QMenu* file) {
  file->addSeparator();
  file->addAction(tr("Open re&view session…"), this, [this] {
    const QString p = ctx_.dialogs->ask_open_path(tr("Open review session"), tr("Review session (*.json)"));
    if (!p.isEmpty()) open_session(p);
  })->setObjectName("openSession");
  file->addAction(tr("Sa&ve review session…"), this, [this] {
    const QString p = ctx_.dialogs->ask_save_path(tr("Save review session"), tr("Review session (*.json)"), "json");
    if (!p.isEmpty()) save_session(p);
  })->setObjectName("saveSession");
  file->addAction(tr("Export &3D view…"), this, [this] {
    const bool ask = !ctx_.dialogs->suppress;  // never asked: the default size
    bool ok = !ask;
    const QString size = ask ? QInputDialog::getText(ctx_.window, tr("Export 3D view"), tr("Size (WIDTHxHEIGHT):"),
                                                     QLineEdit::Normal, "1920x1080", &ok)
                             : QString("1920x1080");
    if (!ok) return;
    const QStringList wh = size.split('x');
    if (wh.size() != 2 || wh[0].toInt() <= 0 || wh[1].toInt() <= 0)
      return ctx_.status->show_error(tr("Export 3D view: size '%1' is not WIDTHxHEIGHT").arg(size));
    const QString p = ctx_.dialogs->ask_save_path(tr("Export 3D view"), tr("PNG (*.png)"), "png");
    if (!p.isEmpty()) export_view3d(p, wh[0].toInt(), wh[1].toInt());
  })->setObjectName("exportView3d");
}

ReviewSession SessionController::current_session() const {
  const FrameController* frames = parts_.frames;
  const scene::TunnelScene& scene = ctx_.view3d->scene();
  ReviewSession s;
  s.input = QFileInfo(ctx_.input_path).absoluteFilePath().toStdString();
  const QString preset = parts_.presets->preset_name();
  s.preset_name = preset.toStdString();
  if (!preset_path_.isEmpty() && QFileInfo(preset_path_).completeBaseName() == preset)
    s.preset_path = preset_path_.toStdString();
  s.params = ctx_.params->parameters();
  s.method = frames->method();
  s.camera = camera_of(scene.renderer());
  s.layers.emplace();
  for (scene::Layer l : scene::all_layers())
    if (scene.layer_visible(l)) s.layers->push_back(scene::layer_name(l));
  s.frame = frames->frame_index() + 1;
  for (const scene::Measurement& m : scene.measurements()) {
    if (m.picks.empty()) continue;
    s.measurements.emplace_back();
    for (const Eigen::Vector3d& p : m.picks) s.measurements.back().push_back({p.x(), p.y(), p.z()});
  }
  s.intrinsics = parts_.intrinsics->user_intrinsics(ctx_.input_path);
  s.preset_params = parts_.presets->preset_parameters();
  s.mapped = parts_.review->mapped_tunnel().has_value();
  if (frames->current() && frames->current()->result.map.detected)
    s.cross_section_station_m = parts_.review->cross_section()->station();
  return s;
}

bool SessionController::save_session(const QString& path) {
  const bool saved = ctx_.status->run_or_show_error([&] {
    if (ctx_.input_path.isEmpty()) throw InputError(path.toStdString(), "nothing to save: no input is open");
    write_session_file(path.toStdString(), current_session());
  });
  if (saved) ctx_.status->flash(tr("Saved review session %1").arg(path));
  return saved;
}

bool SessionController::open_session(const QString& path) {
  ReviewSession s;
  const std::string file = path.toStdString();
  try {
    s = read_session_file(file);
    check_session_input(s, parts_.intrinsics->read_options_for(QString::fromStdString(s.input)), file);
  } catch (const std::exception& e) {
    ctx_.status->show_error(QString::fromStdString(e.what()));
    return false;
  }
  const QString input = QString::fromStdString(s.input);
  if (s.intrinsics) parts_.intrinsics->use_intrinsics(input, *s.intrinsics);
  if (!parts_.inputs->open_input(input)) return false;  // error shown; the state is kept on failure
  preset_path_ = QString::fromStdString(s.preset_path);
  Parameters reference = s.preset_params.value_or(s.params);  // what "(modified)" is relative to
  if (!s.preset_params && !s.preset_path.empty()) {
    try {
      Parameters p;
      p.load_json_file(s.preset_path);
      reference = p;
    } catch (const std::exception&) {
      // The preset moved since: the session's own values are the reference.
    }
  }
  parts_.presets->set_reference(QString::fromStdString(s.preset_name), reference);
  ctx_.params->set_parameters(s.params, tr("Open session %1").arg(QFileInfo(path).fileName()));
  parts_.frames->set_method(s.method);
  if (s.layers) apply_layers(*s.layers);
  parts_.review->cut_when_shown(s.frame - 1, s.cross_section_station_m);
  parts_.frames->select_frame(s.frame - 1);
  pending_camera_ = s.camera;
  std::vector<scene::Measurement> measurements;  // each as saved, one or two points
  for (const auto& saved : s.measurements) {
    measurements.emplace_back();
    for (const auto& p : saved) measurements.back().add(Eigen::Vector3d(p[0], p[1], p[2]));
  }
  pending_measurements_ = measurements;
  if (s.camera) apply_camera(ctx_.view3d->scene().renderer(), *s.camera);  // again after the frame
  parts_.presets->update_status();
  if (s.mapped) parts_.review->map_tunnel();  // with the session's parameters, as it was made
  ctx_.status->flash(tr("Opened review session %1").arg(path));
  return true;
}

// The View menu's layer toggles and the scene, each layer on when `on` names it.
void SessionController::apply_layers(const std::vector<std::string>& on) {
  for (scene::Layer l : scene::all_layers()) {
    const bool visible = std::find(on.begin(), on.end(), scene::layer_name(l)) != on.end();
    for (QAction* a : ctx_.window->findChildren<QAction*>())
      if (a->isCheckable() && a->text() == tr(scene::layer_title(l))) a->setChecked(visible);
    ctx_.view3d->set_layer_visible(l, visible);
  }
}

void SessionController::apply_pending_view() {
  const FrameController* frames = parts_.frames;
  // Once the requested frame is shown (a measurement belongs to its frame).
  if (!(pending_camera_ || pending_measurements_) || frames->last_outcome().frame_index != frames->frame_index()) return;
  if (pending_camera_) apply_camera(ctx_.view3d->scene().renderer(), *pending_camera_);
  if (pending_measurements_) ctx_.view3d->scene().set_measurements(*pending_measurements_);
  pending_camera_.reset();
  pending_measurements_.reset();
  ctx_.view3d->renderWindow()->Render();
  ctx_.view3d->update();
}

bool SessionController::export_view3d(const QString& path, int width, int height) {
  const bool written = ctx_.status->run_or_show_error([&] { export_view3d_png(ctx_.view3d, path, width, height); });
  if (written) ctx_.status->flash(tr("3D view exported: %1 (%2x%3)").arg(path).arg(width).arg(height));
  return written;
}

void SessionController::save_view_settings() {
  QSettings s;
  QStringList layers;
  for (scene::Layer l : scene::all_layers())
    if (ctx_.view3d->scene().layer_visible(l)) layers << scene::layer_name(l);
  s.setValue("view/layers", layers);
  s.setValue("view/method", method_name(parts_.frames->method()));
  ReviewSession view;
  view.input = "-";
  view.camera = camera_of(ctx_.view3d->scene().renderer());
  s.setValue("view/camera", QByteArray::fromStdString(session_to_json(view)["camera"].dump()));
}

void SessionController::restore_view_settings() {
  QSettings s;
  if (s.contains("view/layers")) {
    std::vector<std::string> on;
    for (const QString& l : s.value("view/layers").toStringList()) on.push_back(l.toStdString());
    apply_layers(on);
  }
  try {
    if (s.contains("view/method"))
      parts_.frames->set_method(parse_method(s.value("view/method").toString().toStdString()));
    const QByteArray camera = s.value("view/camera").toByteArray();
    if (!camera.isEmpty()) {
      nlohmann::json j = {{"format", "tunnelmap-session/1"}, {"input", "-"}};
      j["camera"] = nlohmann::json::parse(camera.toStdString());
      pending_camera_ = session_from_json(j, "settings").camera;  // after the first frame
    }
  } catch (const std::exception&) {
    // Stale settings from another version: the defaults.
  }
}

}  // namespace tunnelmap::ui
