// MainWindow, review workflow: review sessions (save/open the whole view as JSON), the 3D view
// exported alone at any size, layers/method/camera kept in QSettings, and the intrinsics of a
// PNG input (folder or single file) shown, editable and remembered per input.
#include <QAction>
#include <QDir>
#include <QDockWidget>
#include <QDoubleSpinBox>
#include <QFileInfo>
#include <QFormLayout>
#include <QImage>
#include <QInputDialog>
#include <QLabel>
#include <QMenu>
#include <QPushButton>
#include <QSettings>
#include <QStatusBar>
#include <QUrl>
#include <algorithm>
#include <cstring>
#include <map>

#include <vtkCamera.h>
#include <vtkImageData.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkWindowToImageFilter.h>

#include "core/io/png_folder.h"
#include "core/util/atomic_file.h"
#include "core/util/error.h"
#include "ui/cross_section_panel.h"
#include "ui/main_window.h"
#include "ui/parameter_panel.h"
#include "ui/review_session.h"
#include "ui/view3d_widget.h"

namespace tunnelmap::ui {

struct SessionState {
  std::map<QString, Intrinsics> intrinsics;  // absolute input path -> given this run
  std::optional<SessionCamera> pending_camera;  // applied once the next frame is shown
  std::optional<std::vector<scene::Measurement>> pending_measurements;  // likewise (a session's)
  QString preset_path;                          // of the session that set preset_name_
  QString panel_input;                          // input the intrinsics panel was filled for
  QDockWidget* dock = nullptr;
  std::array<QDoubleSpinBox*, 4> k{};  // fx, fy, cx, cy
  QLabel* note = nullptr;
};

namespace {

QString absolute(const QString& path) { return QFileInfo(path).absoluteFilePath(); }

// Inputs whose intrinsics come from the user (no dataset or sidecar gives them): a depth PNG or
// a plain folder of depth PNGs.
bool takes_user_intrinsics(const QString& input) {
  const QFileInfo info(input);
  if (info.isFile()) return info.suffix().compare("png", Qt::CaseInsensitive) == 0;
  if (!info.isDir() || QFileInfo::exists(info.filePath() + "/dataset.json")) return false;
  return !list_depth_pngs(info.absoluteFilePath().toStdString()).empty();
}

QString intrinsics_key(const QString& input) {
  // QSettings keys must not contain '/': the absolute path, percent-encoded.
  return "intrinsics/" + QString::fromLatin1(QUrl::toPercentEncoding(absolute(input)));
}

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

}  // namespace

ReadOptions MainWindow::read_options_for(const QString& input) const {
  ReadOptions opt;
  if (!session_ || input.isEmpty()) return opt;
  const auto it = session_->intrinsics.find(absolute(input));
  if (it != session_->intrinsics.end()) {
    opt.intrinsics = it->second;
  } else if (takes_user_intrinsics(input)) {
    // A list: QSettings' INI format reads "a,b" back as a list.
    const QString saved = QSettings().value(intrinsics_key(input)).toStringList().join(",");
    try {
      if (!saved.isEmpty()) opt.intrinsics = parse_intrinsics(saved.toStdString());
    } catch (const std::exception&) {
      // A stale or hand-edited entry: the default intrinsics.
    }
  }
  return opt;
}

void MainWindow::use_intrinsics(const QString& input, const Intrinsics& K) {
  session_->intrinsics[absolute(input)] = K;
}

bool MainWindow::set_intrinsics(const Intrinsics& K) {
  if (!source_ || !takes_user_intrinsics(input_path_)) {
    show_error(tr("%1: intrinsics are set only for a depth PNG or a folder of depth PNGs").arg(input_path_));
    return false;
  }
  ReadOptions opt = read_options_for(input_path_);
  opt.intrinsics = K;
  std::shared_ptr<const FrameSource> source;
  try {
    source = tunnelmap::open_input(input_path_.toStdString(), opt);
    source->load(frame_index_);
  } catch (const std::exception& e) {
    show_error(QString::fromStdString(e.what()));
    return false;
  }
  use_intrinsics(input_path_, K);
  QStringList saved;
  for (double v : {K.fx, K.fy, K.cx, K.cy}) saved << QString::number(v, 'g', 12);
  QSettings().setValue(intrinsics_key(input_path_), saved);
  source_ = source;
  runner_.set_source(source_);  // drops cached results: every stage re-runs
  request_run(true);
  return true;
}

bool MainWindow::save_session(const QString& path) {
  try {
    if (input_path_.isEmpty()) throw InputError(path.toStdString(), "nothing to save: no input is open");
    ReviewSession s;
    s.input = absolute(input_path_).toStdString();
    s.preset_name = preset_name_.toStdString();
    if (session_->preset_path.size() && QFileInfo(session_->preset_path).completeBaseName() == preset_name_)
      s.preset_path = session_->preset_path.toStdString();
    s.params = params_->parameters();
    s.method = method_;
    s.camera = camera_of(view3d_->scene().renderer());
    s.layers.emplace();
    for (scene::Layer l : scene::all_layers())
      if (view3d_->scene().layer_visible(l)) s.layers->push_back(scene::layer_name(l));
    s.frame = frame_index_ + 1;
    for (const scene::Measurement& m : view3d_->scene().measurements()) {
      if (m.picks.empty()) continue;
      s.measurements.emplace_back();
      for (const Eigen::Vector3d& p : m.picks) s.measurements.back().push_back({p.x(), p.y(), p.z()});
    }
    if (takes_user_intrinsics(input_path_)) s.intrinsics = read_options_for(input_path_).intrinsics;
    s.preset_params = preset_params_;
    s.mapped = mapped_tunnel().has_value();
    if (current_ && current_->result.map.detected) s.cross_section_station_m = cross_section_->station();
    write_session_file(path.toStdString(), s);
  } catch (const std::exception& e) {
    show_error(QString::fromStdString(e.what()));
    return false;
  }
  statusBar()->showMessage(tr("Saved review session %1").arg(path), 5000);
  return true;
}

bool MainWindow::open_session(const QString& path) {
  ReviewSession s;
  const std::string file = path.toStdString();
  try {
    s = read_session_file(file);
    // Check the input and the frame before anything changes: a bad session keeps the state.
    ReadOptions opt = read_options_for(QString::fromStdString(s.input));
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
  } catch (const std::exception& e) {
    show_error(QString::fromStdString(e.what()));
    return false;
  }
  const QString input = QString::fromStdString(s.input);
  if (s.intrinsics) use_intrinsics(input, *s.intrinsics);
  if (!open_input(input)) return false;  // error shown; open_input keeps the state on failure
  session_->preset_path = QString::fromStdString(s.preset_path);
  preset_name_ = QString::fromStdString(s.preset_name);
  preset_params_ = s.preset_params.value_or(s.params);  // what "(modified)" is relative to
  if (!s.preset_params && !s.preset_path.empty()) {
    try {
      Parameters p;
      p.load_json_file(s.preset_path);
      preset_params_ = p;
    } catch (const std::exception&) {
      // The preset moved since: the session's own values are the reference.
    }
  }
  params_->set_parameters(s.params, tr("Open session %1").arg(QFileInfo(path).fileName()));
  set_method(s.method);
  for (scene::Layer l : scene::all_layers()) {
    if (!s.layers) break;
    const bool on = std::find(s.layers->begin(), s.layers->end(), scene::layer_name(l)) != s.layers->end();
    for (QAction* a : findChildren<QAction*>())
      if (a->isCheckable() && a->text() == tr(scene::layer_title(l))) a->setChecked(on);
    view3d_->set_layer_visible(l, on);
  }
  review_map_pending_station(s.frame - 1, s.cross_section_station_m);
  select_frame(s.frame - 1);
  session_->pending_camera = s.camera;
  std::vector<scene::Measurement> measurements;  // each as saved, one or two points
  for (const auto& saved : s.measurements) {
    measurements.emplace_back();
    for (const auto& p : saved) measurements.back().add(Eigen::Vector3d(p[0], p[1], p[2]));
  }
  session_->pending_measurements = measurements;
  if (s.camera) apply_camera(view3d_->scene().renderer(), *s.camera);  // again after the frame
  update_preset_status();
  if (s.mapped) map_tunnel();  // with the session's parameters, as it was made
  statusBar()->showMessage(tr("Opened review session %1").arg(path), 5000);
  return true;
}

bool MainWindow::export_view3d(const QString& path, int width, int height) {
  constexpr int kMaxSide = 8192;
  try {
    if (width < 16 || height < 16 || width > kMaxSide || height > kMaxSide)
      throw InputError(path.toStdString(), QString("size %1x%2 out of range (16..%3 per side)")
                                               .arg(width).arg(height).arg(kMaxSide).toStdString());
    // The scene's renderer moves into an off-screen window of the requested size for one
    // render, then back: same actors, camera and layers, no copy of the scene.
    vtkRenderer* renderer = view3d_->scene().renderer();
    vtkRenderWindow* shown = view3d_->renderWindow();
    view3d_->makeCurrent();
    shown->RemoveRenderer(renderer);
    QImage image;
    {
      auto off = vtkSmartPointer<vtkRenderWindow>::New();
      off->SetOffScreenRendering(1);
      off->SetMultiSamples(0);
      off->SetSize(width, height);
      off->AddRenderer(renderer);
      off->Render();
      auto grab = vtkSmartPointer<vtkWindowToImageFilter>::New();
      grab->SetInput(off);
      grab->SetInputBufferTypeToRGB();
      grab->ReadFrontBufferOff();
      grab->Update();
      vtkImageData* img = grab->GetOutput();
      int dims[3];
      img->GetDimensions(dims);
      if (dims[0] == width && dims[1] == height) {
        image = QImage(width, height, QImage::Format_RGB888);
        const auto* px = static_cast<const unsigned char*>(img->GetScalarPointer());
        for (int y = 0; y < height; ++y)  // VTK rows run bottom-up
          std::memcpy(image.scanLine(height - 1 - y), px + std::size_t(y) * width * 3, std::size_t(width) * 3);
      }
      off->RemoveRenderer(renderer);
      off->Finalize();
    }
    view3d_->makeCurrent();
    shown->AddRenderer(renderer);
    shown->Render();
    view3d_->update();
    if (image.isNull())
      throw InputError(path.toStdString(), "the off-screen render did not give the requested size");
    write_path_atomically(path.toStdString(), [&](const std::string& tmp) {
      if (!image.save(QString::fromStdString(tmp), "PNG"))
        throw InputError(path.toStdString(), "cannot write PNG");
    });
  } catch (const std::exception& e) {
    show_error(QString::fromStdString(e.what()));
    return false;
  }
  statusBar()->showMessage(tr("3D view exported: %1 (%2x%3)").arg(path).arg(width).arg(height), 5000);
  return true;
}

void MainWindow::save_view_settings() {
  QSettings s;
  QStringList layers;
  for (scene::Layer l : scene::all_layers())
    if (view3d_->scene().layer_visible(l)) layers << scene::layer_name(l);
  s.setValue("view/layers", layers);
  s.setValue("view/method", method_name(method_));
  s.setValue("view/camera", QByteArray::fromStdString(session_to_json([&] {
                                                        ReviewSession r;
                                                        r.input = "-";
                                                        r.camera = camera_of(view3d_->scene().renderer());
                                                        return r;
                                                      }())["camera"].dump()));
}

void MainWindow::restore_view_settings() {
  QSettings s;
  if (s.contains("view/layers")) {
    const QStringList layers = s.value("view/layers").toStringList();
    for (scene::Layer l : scene::all_layers()) {
      const bool on = layers.contains(scene::layer_name(l));
      for (QAction* a : findChildren<QAction*>())
        if (a->isCheckable() && a->text() == tr(scene::layer_title(l))) a->setChecked(on);
      view3d_->set_layer_visible(l, on);
    }
  }
  try {
    if (s.contains("view/method")) set_method(parse_method(s.value("view/method").toString().toStdString()));
    const QByteArray camera = s.value("view/camera").toByteArray();
    if (!camera.isEmpty()) {
      nlohmann::json j = {{"format", "tunnelmap-session/1"}, {"input", "-"}};
      j["camera"] = nlohmann::json::parse(camera.toStdString());
      session_->pending_camera = session_from_json(j, "settings").camera;  // after the first frame
    }
  } catch (const std::exception&) {
    // Stale settings from another version: the defaults.
  }
}

void MainWindow::build_session_actions(QMenu* file) {
  session_ = std::make_shared<SessionState>();
  file->addSeparator();
  file->addAction(tr("Open re&view session…"), this, [this] {
    const QString p = ask_open_path(tr("Open review session"), tr("Review session (*.json)"));
    if (!p.isEmpty()) open_session(p);
  })->setObjectName("openSession");
  file->addAction(tr("Sa&ve review session…"), this, [this] {
    const QString p = ask_save_path(tr("Save review session"), tr("Review session (*.json)"), "json");
    if (!p.isEmpty()) save_session(p);
  })->setObjectName("saveSession");
  file->addAction(tr("Export &3D view…"), this, [this] {
    bool ok = suppress_dialogs;  // never asked: the default size
    const QString size = suppress_dialogs ? QString("1920x1080")
                                          : QInputDialog::getText(this, tr("Export 3D view"), tr("Size (WIDTHxHEIGHT):"),
                                                                  QLineEdit::Normal, "1920x1080", &ok);
    const QStringList wh = size.split('x');
    if (!ok) return;
    if (wh.size() != 2 || wh[0].toInt() <= 0 || wh[1].toInt() <= 0)
      return show_error(tr("Export 3D view: size '%1' is not WIDTHxHEIGHT").arg(size));
    const QString p = ask_save_path(tr("Export 3D view"), tr("PNG (*.png)"), "png");
    if (!p.isEmpty()) export_view3d(p, wh[0].toInt(), wh[1].toInt());
  })->setObjectName("exportView3d");

  // Intrinsics panel: fx, fy, cx, cy of the shown frame; Apply re-reads the input with them.
  session_->dock = new QDockWidget(tr("Camera intrinsics"), this);
  session_->dock->setObjectName("intrinsicsDock");
  auto* box = new QWidget(session_->dock);
  auto* form = new QFormLayout(box);
  const char* names[] = {"fx", "fy", "cx", "cy"};
  for (int i = 0; i < 4; ++i) {
    auto* spin = new QDoubleSpinBox(box);
    spin->setObjectName(QString("intrinsics_") + names[i]);
    spin->setRange(i < 2 ? 1.0 : -1e5, 1e5);
    spin->setDecimals(2);
    spin->setSuffix(" px");
    form->addRow(QString(names[i]) + ":", spin);
    session_->k[i] = spin;
  }
  auto* apply = new QPushButton(tr("Apply"), box);
  apply->setObjectName("applyIntrinsics");
  form->addRow(apply);
  session_->note = new QLabel(box);
  session_->note->setWordWrap(true);
  form->addRow(session_->note);
  session_->dock->setWidget(box);
  addDockWidget(Qt::LeftDockWidgetArea, session_->dock);
  session_->dock->hide();
  connect(apply, &QPushButton::clicked, this, [this] {
    Intrinsics K;
    K.fx = session_->k[0]->value(), K.fy = session_->k[1]->value();
    K.cx = session_->k[2]->value(), K.cy = session_->k[3]->value();
    set_intrinsics(K);
  });
  QAction* toggle = session_->dock->toggleViewAction();
  toggle->setObjectName("showIntrinsics");
  file->addAction(toggle);

  connect(this, &MainWindow::frameShown, this, [this] {
    // Once the requested frame is shown (a measurement belongs to its frame).
    if ((session_->pending_camera || session_->pending_measurements) && last_.frame_index == frame_index_) {
      if (session_->pending_camera) apply_camera(view3d_->scene().renderer(), *session_->pending_camera);
      if (session_->pending_measurements) view3d_->scene().set_measurements(*session_->pending_measurements);
      session_->pending_camera.reset();
      session_->pending_measurements.reset();
      view3d_->renderWindow()->Render();
      view3d_->update();
    }
    if (!current()) return;
    const Intrinsics& K = current()->frame.intrinsics;
    const double values[] = {K.fx, K.fy, K.cx, K.cy};
    for (int i = 0; i < 4; ++i) session_->k[i]->setValue(values[i]);
    const bool editable = takes_user_intrinsics(input_path_);
    session_->dock->widget()->setEnabled(editable);
    session_->note->setText(editable ? tr("%1x%2 depth image; Apply re-runs and remembers them for this input")
                                           .arg(K.width).arg(K.height)
                                     : tr("Given by the input (dataset or recording)"));
    // A folder of PNGs opened: shown (a single PNG: File > Camera intrinsics).
    if (editable && QFileInfo(input_path_).isDir() && session_->panel_input != input_path_) session_->dock->show();
    session_->panel_input = input_path_;
  });
}

}  // namespace tunnelmap::ui
