// Review workflow in a real window (run under xvfb-run -a): review sessions saved, changed and
// restored field by field; bad session files keep the state; the 3D view exported alone at an
// exact size; layers/method/camera restored on the next start; a plain folder of depth PNGs
// opened with editable intrinsics remembered per folder; the GUI binary's --session,
// --intrinsics and --device. TUNNELMAP_GUI_SHOT_DIR=DIR keeps the exported images.
#include <QAction>
#include <QDir>
#include <QDockWidget>
#include <QDoubleSpinBox>
#include <QFile>
#include <QImage>
#include <QLabel>
#include <QProcess>
#include <QPushButton>
#include <QSettings>
#include <QSignalSpy>
#include <QStandardPaths>
#include <QSurfaceFormat>
#include <QTemporaryDir>
#include <QVTKOpenGLNativeWidget.h>
#include <QtTest/QtTest>
#include <cmath>
#include <set>
#include <nlohmann/json.hpp>
#include <vtkCamera.h>
#include <vtkRenderer.h>

#include "core/util/build_paths.h"
#include "sensors/openni/register_openni.h"
#include "ui/cross_section_panel.h"
#include "ui/main_window.h"
#include "ui/profile_plot.h"
#include "ui/message_log.h"
#include "ui/parameter_panel.h"
#include "ui/timeline_widget.h"
#include "ui/view3d_widget.h"

using tunnelmap::scene::Layer;
using tunnelmap::ui::MainWindow;

namespace {

const QString kLab = QString(TUNNELMAP_SAMPLE_DIR) + "/lab";

// Waits until `done` holds (events processed meanwhile).
template <class F>
bool wait_until(F done, int timeout_ms = 30000) {
  return QTest::qWaitFor(done, timeout_ms);
}

std::array<double, 3> camera_position(MainWindow& w) {
  std::array<double, 3> p{};
  w.view3d()->scene().renderer()->GetActiveCamera()->GetPosition(p.data());
  return p;
}

double distance(const std::array<double, 3>& a, const std::array<double, 3>& b) {
  return std::sqrt((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) + (a[2] - b[2]) * (a[2] - b[2]));
}

// Pixels that differ from the top-left (background) colour, and distinct colours.
std::pair<double, int> content(const QImage& image) {
  const QImage img = image.convertToFormat(QImage::Format_RGB32);
  const QRgb bg = img.pixel(0, 0);
  long long differ = 0;
  std::set<QRgb> colours;
  for (int y = 0; y < img.height(); ++y)
    for (int x = 0; x < img.width(); ++x) {
      const QRgb c = img.pixel(x, y);
      if (c != bg) ++differ;
      if (colours.size() < 1000) colours.insert(c);
    }
  return {double(differ) / (double(img.width()) * img.height()), int(colours.size())};
}

void keep(const QString& path) {
  const QByteArray dir = qgetenv("TUNNELMAP_GUI_SHOT_DIR");
  if (!dir.isEmpty()) QFile::copy(path, QDir(QString::fromLocal8Bit(dir)).filePath(QFileInfo(path).fileName()));
}

}  // namespace

class GuiSessionTest : public QObject {
  Q_OBJECT

 private:
  QTemporaryDir dir_;
  QString png_folder_;

  // A shown window with `input` open and its first frame shown.
  static bool open_and_wait(MainWindow& w, const QString& input) {
    const int runs = w.shown_runs();
    if (!w.open_input(input)) return false;
    return wait_until([&] { return w.shown_runs() > runs && w.current(); });
  }

 private slots:
  void initTestCase() {
    QStandardPaths::setTestModeEnabled(true);  // QSettings in a test location
    QSettings().clear();
    QVERIFY(dir_.isValid());
    // A plain folder of depth PNGs: copies of the lab sample's frames, no dataset.json.
    png_folder_ = dir_.filePath("pngs");
    QVERIFY(QDir().mkpath(png_folder_));
    for (const QString& f : QDir(kLab + "/depth").entryList({"*.png"}, QDir::Files))
      QVERIFY(QFile::copy(kLab + "/depth/" + f, png_folder_ + "/" + f));
    QCOMPARE(QDir(png_folder_).entryList({"*.png"}).size(), 3);
  }

  void init() { QSettings().clear(); }

  void sessionSaveChangeOpenRestoresEverything() {
    MainWindow w;
    w.suppress_dialogs = true;
    w.resize(1280, 800);
    w.show();
    QVERIFY(QTest::qWaitForWindowExposed(&w));
    QVERIFY(open_and_wait(w, kLab));
    // The state to save: a changed parameter, Qhull, frame 2 of 3, planes and grid hidden,
    // a side view moved closer.
    tunnelmap::Parameters p = w.parameter_panel()->parameters();
    p.set("grow.angle_deg", 2.5);
    w.parameter_panel()->set_parameters(p);
    w.set_method(tunnelmap::Method::Qhull);
    QVERIFY(w.select_frame(1));
    QVERIFY(wait_until([&] { return w.last_outcome().frame_index == 1 && w.last_outcome().method == tunnelmap::Method::Qhull &&
                                    w.last_outcome().params.get("grow.angle_deg") == 2.5; }));
    w.view3d()->set_layer_visible(Layer::Planes, false);
    w.view3d()->set_layer_visible(Layer::Frustum, true);
    w.view3d()->apply_view(tunnelmap::scene::ViewPreset::Side);
    vtkCamera* cam = w.view3d()->scene().renderer()->GetActiveCamera();
    cam->Dolly(1.3);
    cam->SetViewAngle(24.0);
    const auto saved_position = camera_position(w);
    tunnelmap::scene::Measurement measured, second;  // as two pairs of clicks of the measure tool give
    measured.add(Eigen::Vector3d(-0.41, 0.2, 1.5));
    measured.add(Eigen::Vector3d(0.40, 0.25, 1.6));
    second.add(Eigen::Vector3d(0.0, -0.6, 1.4));
    second.add(Eigen::Vector3d(0.0, 0.62, 1.45));
    w.view3d()->scene().set_measurements({measured, second});
    const QString session = dir_.filePath("review.json");
    // Through File > Save review session… (the dialog replaced; the suffix is added).
    w.choose_save_path = [&](const QString&, const QString&, const QString&) { return dir_.filePath("review"); };
    w.findChild<QAction*>("saveSession")->trigger();
    QVERIFY2(QFile::exists(session), qPrintable(w.last_error()));

    // The file, as documented (docs/gui.md).
    QFile f(session);
    QVERIFY(f.open(QIODevice::ReadOnly));
    const nlohmann::json j = nlohmann::json::parse(f.readAll().toStdString());
    QCOMPARE(QString::fromStdString(j["format"]), QString("tunnelmap-session/1"));
    QCOMPARE(QString::fromStdString(j["input"]), QFileInfo(kLab).absoluteFilePath());
    QCOMPARE(QString::fromStdString(j["method"]), QString("qhull"));
    QCOMPARE(j["frame"].get<int>(), 2);  // 1-based, as the timeline shows it
    QCOMPARE(j["params"]["grow.angle_deg"].get<double>(), 2.5);
    QCOMPARE(j["camera"]["view_angle"].get<double>(), 24.0);
    QCOMPARE(j["measurements"].size(), std::size_t(2));
    QCOMPARE(j["measurements"][0]["points"][1][0].get<double>(), 0.40);
    QCOMPARE(j["measurements"][1]["points"][1][1].get<double>(), 0.62);
    QVERIFY(std::abs(j["measurements"][0]["distance_m"].get<double>() - *measured.distance_m()) < 1e-12);
    const auto layers = j["layers"].get<std::vector<std::string>>();
    QVERIFY(std::find(layers.begin(), layers.end(), "planes") == layers.end());
    QVERIFY(std::find(layers.begin(), layers.end(), "frustum") != layers.end());
    QVERIFY(std::find(layers.begin(), layers.end(), "cloud") != layers.end());

    // Change everything: another input, defaults, PG&C, all layers, along view.
    QVERIFY(open_and_wait(w, png_folder_));
    w.parameter_panel()->set_parameters(tunnelmap::Parameters());
    w.set_method(tunnelmap::Method::Pgc);
    w.view3d()->set_layer_visible(Layer::Planes, true);
    w.view3d()->set_layer_visible(Layer::Frustum, false);
    w.view3d()->apply_view(tunnelmap::scene::ViewPreset::Along);
    QVERIFY(wait_until([&] { return w.last_outcome().method == tunnelmap::Method::Pgc; }));
    w.view3d()->clear_measurement();
    QVERIFY(distance(camera_position(w), saved_position) > 0.05);

    const int errors = w.messages()->count();
    w.choose_open_path = [&](const QString&, const QString&, const QString&) { return session; };
    w.findChild<QAction*>("openSession")->trigger();  // File > Open review session…
    QCOMPARE(w.messages()->count(), errors);
    QVERIFY(wait_until([&] {
      return w.last_outcome().frame_index == 1 && w.last_outcome().method == tunnelmap::Method::Qhull &&
             w.last_outcome().params.get("grow.angle_deg") == 2.5 && w.input_path() == QFileInfo(kLab).absoluteFilePath();
    }));
    QTest::qWait(200);
    QCOMPARE(w.input_path(), QFileInfo(kLab).absoluteFilePath());
    QCOMPARE(w.parameter_panel()->parameters(), p);
    QCOMPARE(int(w.method()), int(tunnelmap::Method::Qhull));
    QCOMPARE(w.frame_index(), 1);
    QCOMPARE(w.timeline()->frame(), 1);
    QVERIFY(!w.view3d()->scene().layer_visible(Layer::Planes));
    QVERIFY(w.view3d()->scene().layer_visible(Layer::Frustum));
    QVERIFY(w.view3d()->scene().layer_visible(Layer::Cloud));
    const double moved = distance(camera_position(w), saved_position);
    QVERIFY2(moved < 1e-6, qPrintable(QString("camera %1 m from the saved position").arg(moved)));
    QCOMPARE(w.view3d()->scene().renderer()->GetActiveCamera()->GetViewAngle(), 24.0);
    // Both measurements come back, in order.
    const auto& restored = w.view3d()->scene().measurements();
    QCOMPARE(restored.size(), std::size_t(2));
    for (std::size_t k = 0; k < 2; ++k) {
      const auto& want = k == 0 ? measured : second;
      QCOMPARE(restored[k].picks.size(), std::size_t(2));
      QVERIFY((restored[k].picks[0] - want.picks[0]).norm() < 1e-12 && (restored[k].picks[1] - want.picks[1]).norm() < 1e-12);
    }
    // The View menu's layer checkboxes follow.
    for (QAction* a : w.findChildren<QAction*>())
      if (a->isCheckable() && a->text() == QObject::tr(tunnelmap::scene::layer_title(Layer::Planes)))
        QVERIFY(!a->isChecked());
  }

  // A session keeps the review as well as the view: the tunnel map (Map tunnel runs again on
  // open), the cross-section's station and the preset's "(modified)" mark, even after the
  // preset file is gone.
  void sessionKeepsTheMapTheCutAndThePresetState() {
    MainWindow w;
    w.suppress_dialogs = true;
    w.show();
    QVERIFY(QTest::qWaitForWindowExposed(&w));
    QVERIFY(open_and_wait(w, kLab));
    const QString preset = dir_.filePath("mine.json");
    QVERIFY(QFile::copy(QString(TUNNELMAP_SOURCE_DIR) + "/resources/presets/lab.json", preset));
    QVERIFY(w.load_preset(preset));
    tunnelmap::Parameters p = w.parameter_panel()->parameters();
    p.set("grow.angle_deg", 3.5);
    w.parameter_panel()->set_parameters(p);
    auto* preset_label = w.findChild<QLabel*>("presetLabel");
    QVERIFY2(preset_label->text().contains("mine (modified)"), qPrintable(preset_label->text()));
    QSignalSpy mapped(&w, &MainWindow::tunnelMapped);
    w.map_tunnel();
    QVERIFY(mapped.wait(120000));
    QVERIFY(mapped.at(0).at(0).toBool());
    const std::size_t stations = w.profile()->map().stations.size();
    QVERIFY(stations > 5);
    QVERIFY(wait_until([&] { return w.current() != nullptr; }));
    w.cross_section()->set_station(1.7);
    const double cut = w.cross_section()->station();
    const QString session = dir_.filePath("mapped.json");
    QVERIFY(w.save_session(session));
    QFile f(session);
    QVERIFY(f.open(QIODevice::ReadOnly));
    const nlohmann::json j = nlohmann::json::parse(f.readAll().toStdString());
    QCOMPARE(j["review"]["map"].get<bool>(), true);
    QCOMPARE(j["review"]["cross_section_station_m"].get<double>(), cut);
    QCOMPARE(j["preset"]["params"]["grow.angle_deg"].get<double>(),
             tunnelmap::Parameters().get("grow.angle_deg"));  // the preset's own value, not the edit

    QVERIFY(QFile::remove(preset));
    QVERIFY(open_and_wait(w, png_folder_));
    QVERIFY(w.profile()->map().stations.empty());
    QVERIFY(w.open_session(session));
    QVERIFY(mapped.wait(120000));
    QVERIFY(mapped.at(1).at(0).toBool());
    QCOMPARE(w.profile()->map().stations.size(), stations);
    QVERIFY(wait_until([&] { return std::abs(w.cross_section()->station() - cut) < 1e-9; }));
    QVERIFY2(preset_label->text().contains("mine (modified)"), qPrintable(preset_label->text()));
  }

  void badSessionFileKeepsState() {
    MainWindow w;
    w.suppress_dialogs = true;
    w.resize(1280, 800);
    w.show();
    QVERIFY(QTest::qWaitForWindowExposed(&w));
    QVERIFY(open_and_wait(w, png_folder_));
    QVERIFY(w.select_frame(2));
    QVERIFY(wait_until([&] { return w.last_outcome().frame_index == 2; }));
    const tunnelmap::Parameters params = w.parameter_panel()->parameters();
    const auto position = camera_position(w);
    const QString lab = QFileInfo(kLab).absoluteFilePath();
    const struct {
      const char* name;
      QByteArray text;
      const char* problem;
    } cases[] = {
        {"broken.json", "{\"format\": \"tunnelmap-session/1\", ", "not valid JSON"},
        {"format.json", "{\"format\": \"tunnelmap-results/1\", \"input\": \"x\"}", "unsupported session format"},
        {"param.json", "{\"format\": \"tunnelmap-session/1\", \"input\": \"" + lab.toUtf8() +
                           "\", \"params\": {\"grow.angle_deg\": -40}}", "grow.angle_deg"},
        {"method.json", "{\"format\": \"tunnelmap-session/1\", \"input\": \"" + lab.toUtf8() +
                            "\", \"method\": \"magic\"}", "unknown method"},
        {"layer.json", "{\"format\": \"tunnelmap-session/1\", \"input\": \"" + lab.toUtf8() +
                           "\", \"layers\": [\"cloud\", \"clouds\"]}", "layers"},
        {"input.json", "{\"format\": \"tunnelmap-session/1\", \"input\": \"/nonexistent/frames\"}", "input"},
        {"measure.json", "{\"format\": \"tunnelmap-session/1\", \"input\": \"" + lab.toUtf8() +
                             "\", \"measurements\": [{\"points\": [[0, 0]]}]}", "measurements"},
        {"frame.json", "{\"format\": \"tunnelmap-session/1\", \"input\": \"" + lab.toUtf8() + "\", \"frame\": 4}",
         "past the input's 3 frame(s)"},
    };
    int messages = w.messages()->count();
    for (const auto& c : cases) {
      const QString path = dir_.filePath(c.name);
      QFile f(path);
      QVERIFY(f.open(QIODevice::WriteOnly | QIODevice::Truncate));
      f.write(c.text);
      f.close();
      QVERIFY2(!w.open_session(path), c.name);
      QVERIFY2(w.last_error().startsWith(path + ": "), qPrintable(w.last_error()));
      QVERIFY2(w.last_error().contains(c.problem), qPrintable(w.last_error()));
      QVERIFY2(!w.last_error().contains('\n'), qPrintable(w.last_error()));
      QCOMPARE(w.messages()->count(), ++messages);  // one line each
      QCOMPARE(w.status_text(), w.last_error());
    }
    QVERIFY(!w.open_session(dir_.filePath("missing.json")));
    QVERIFY(w.last_error().contains("missing.json"));
    // Nothing the user had changed.
    QTest::qWait(300);
    QCOMPARE(w.input_path(), png_folder_);
    QCOMPARE(w.frame_index(), 2);
    QCOMPARE(w.parameter_panel()->parameters(), params);
    QCOMPARE(int(w.method()), int(tunnelmap::Method::Pgc));
    QVERIFY(distance(camera_position(w), position) < 1e-9);
  }

  void exportView3dAtExactSize() {
    MainWindow w;
    w.suppress_dialogs = true;
    w.resize(1280, 800);
    w.show();
    QVERIFY(QTest::qWaitForWindowExposed(&w));
    QVERIFY(open_and_wait(w, kLab));
    const QSize view = w.view3d()->size();
    for (const QSize size : {QSize(1920, 1080), QSize(333, 517)}) {
      const QString path = dir_.filePath(QString("view3d_%1x%2.png").arg(size.width()).arg(size.height()));
      QVERIFY2(w.export_view3d(path, size.width(), size.height()), qPrintable(w.last_error()));
      const QImage image(path);
      QCOMPARE(image.size(), size);
      const auto [filled, colours] = content(image);
      qInfo("%dx%d: %.1f %% of the pixels drawn, %d colours", size.width(), size.height(), 100 * filled, colours);
      QVERIFY2(filled > 0.05, qPrintable(QString("only %1 % drawn").arg(100 * filled)));
      QVERIFY(colours > 20);
      keep(path);
    }
    // File > Export 3D view… with the dialogs replaced: the default 1920x1080.
    const QString via_menu = dir_.filePath("menu_export.png");
    w.choose_save_path = [&](const QString&, const QString&, const QString&) { return via_menu; };
    w.findChild<QAction*>("exportView3d")->trigger();
    QCOMPARE(QImage(via_menu).size(), QSize(1920, 1080));
    // The window's own view still renders afterwards, at its own size.
    QCOMPARE(w.view3d()->size(), view);
    const QImage grabbed = w.view3d()->grabFramebuffer();
    QVERIFY(content(grabbed).first > 0.05);
    // A size out of range: an error naming the file, no file.
    const QString bad = dir_.filePath("bad.png");
    QVERIFY(!w.export_view3d(bad, 0, 100));
    QVERIFY(w.last_error().startsWith(bad + ": "));
    QVERIFY(!QFile::exists(bad));
  }

  void pngFolderIntrinsicsEditableAndRemembered() {
    {
      MainWindow w;
      w.suppress_dialogs = true;
      w.resize(1280, 800);
      w.show();
      QVERIFY(QTest::qWaitForWindowExposed(&w));
      QVERIFY(open_and_wait(w, png_folder_));
      const auto& K0 = w.current()->frame.intrinsics;
      QCOMPARE(K0.width, 640);
      QCOMPARE(K0.fx, 570.3);  // PrimeSense VGA, the default
      auto* dock = w.findChild<QDockWidget*>("intrinsicsDock");
      QVERIFY(dock && dock->isVisible() && dock->widget()->isEnabled());
      auto* fx = w.findChild<QDoubleSpinBox*>("intrinsics_fx");
      auto* fy = w.findChild<QDoubleSpinBox*>("intrinsics_fy");
      QVERIFY(fx && fy);
      QCOMPARE(fx->value(), 570.3);
      const double width_before = w.current()->result.map.width_m;
      fx->setValue(456.0);
      fy->setValue(456.0);
      QTest::mouseClick(w.findChild<QPushButton*>("applyIntrinsics"), Qt::LeftButton);
      QVERIFY(wait_until([&] { return w.current() && w.current()->frame.intrinsics.fx == 456.0; }));
      QCOMPARE(w.current()->frame.intrinsics.fy, 456.0);
      QCOMPARE(w.current()->frame.intrinsics.cx, 319.5);
      // A shorter focal length spreads the same pixels wider: the tunnel measures wider.
      const double width_after = w.current()->result.map.width_m;
      qInfo("width %.3f m at fx 570.3 -> %.3f m at fx 456", width_before, width_after);
      QVERIFY(w.current()->result.map.has_width() && width_before > 0.5);
      QVERIFY(width_after > width_before * 1.1);
    }
    {  // Another window (the next start): the folder opens with its remembered intrinsics.
      MainWindow w;
      w.suppress_dialogs = true;
      w.show();
      QVERIFY(QTest::qWaitForWindowExposed(&w));
      QVERIFY(open_and_wait(w, png_folder_));
      QCOMPARE(w.current()->frame.intrinsics.fx, 456.0);
      QCOMPARE(w.findChild<QDoubleSpinBox*>("intrinsics_fx")->value(), 456.0);
      // A dataset gives its own intrinsics: the panel is shown read-only.
      QVERIFY(open_and_wait(w, kLab));
      QVERIFY(!w.findChild<QDockWidget*>("intrinsicsDock")->widget()->isEnabled());
      QVERIFY(!w.set_intrinsics(tunnelmap::Intrinsics()));
      QVERIFY(w.last_error().startsWith(kLab));
    }
  }

  void viewSettingsRestoredOnNextStart() {
    std::array<double, 3> position{};
    {
      MainWindow w;
      w.suppress_dialogs = true;
      w.show();
      QVERIFY(QTest::qWaitForWindowExposed(&w));
      QVERIFY(open_and_wait(w, kLab));
      w.view3d()->set_layer_visible(Layer::Planes, false);
      w.view3d()->set_layer_visible(Layer::Grid, true);
      w.set_method(tunnelmap::Method::Qhull);
      w.view3d()->apply_view(tunnelmap::scene::ViewPreset::Top);
      position = camera_position(w);
      w.close();
    }
    MainWindow w;
    w.suppress_dialogs = true;
    w.show();
    QVERIFY(QTest::qWaitForWindowExposed(&w));
    QVERIFY(!w.view3d()->scene().layer_visible(Layer::Planes));
    QVERIFY(w.view3d()->scene().layer_visible(Layer::Grid));
    QCOMPARE(int(w.method()), int(tunnelmap::Method::Qhull));
    QVERIFY(open_and_wait(w, kLab));
    QVERIFY(wait_until([&] { return distance(camera_position(w), position) < 1e-6; }));
    QCOMPARE(int(w.last_outcome().method), int(tunnelmap::Method::Qhull));
    QSettings().clear();
  }

  void guiBinarySessionIntrinsicsDevice() {
    // Settings of the child processes in a private folder.
    QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
    env.insert("XDG_CONFIG_HOME", dir_.filePath("xdg"));
    auto run = [&](const QStringList& args, QString* err = nullptr) {
      QProcess p;
      p.setProcessEnvironment(env);
      p.start(TUNNELMAP_GUI_PATH, args);
      if (!p.waitForFinished(90000)) {
        p.kill();
        p.waitForFinished();
        return -1;
      }
      if (err) *err = QString::fromLocal8Bit(p.readAllStandardError());
      return p.exitCode();
    };
    // A session of frame 3 of the lab sample, written as a user would.
    const QString session = dir_.filePath("cli_session.json");
    {
      QFile f(session);
      QVERIFY(f.open(QIODevice::WriteOnly));
      f.write("{\"format\": \"tunnelmap-session/1\", \"input\": \"" + QFileInfo(kLab).absoluteFilePath().toUtf8() +
              "\", \"method\": \"qhull\", \"frame\": 3, \"layers\": [\"cloud\", \"boundary\"]}");
    }
    const QString shot = dir_.filePath("session_shot.png");
    QString err;
    QCOMPARE(run({"--session", session, "--screenshot", shot, "--exit", "--size", "1400x860"}, &err), 0);
    QCOMPARE(QImage(shot).size(), QSize(1400, 860));
    keep(shot);
    // With a camera in the session the grab keeps it; --view replaces it.
    {
      QFile f(session);
      QVERIFY(f.open(QIODevice::WriteOnly | QIODevice::Truncate));
      f.write("{\"format\": \"tunnelmap-session/1\", \"input\": \"" + QFileInfo(kLab).absoluteFilePath().toUtf8() +
              "\", \"camera\": {\"position\": [2.5, -1.5, -0.5], \"focal_point\": [0, 0, 2], "
              "\"view_up\": [0, -1, 0], \"view_angle\": 30}}");
    }
    const QString oblique = dir_.filePath("session_oblique.png"), along = dir_.filePath("session_along.png");
    QCOMPARE(run({"--session", session, "--screenshot", oblique, "--exit", "--size", "1400x860"}), 0);
    QCOMPARE(run({"--session", session, "--screenshot", along, "--exit", "--size", "1400x860", "--view", "along"}), 0);
    const QImage a = QImage(oblique).convertToFormat(QImage::Format_RGB32);
    const QImage b = QImage(along).convertToFormat(QImage::Format_RGB32);
    QCOMPARE(a.size(), b.size());
    long long differ = 0;
    for (int y = 0; y < a.height(); y += 2)
      for (int x = 0; x < a.width(); x += 2) differ += a.pixel(x, y) != b.pixel(x, y);
    const double fraction = 4.0 * differ / (double(a.width()) * a.height());
    qInfo("session camera vs --view along: %.1f %% of the window differs", 100 * fraction);
    QVERIFY(fraction > 0.05);
    keep(oblique);
    // A bad session: exit 3, one line naming the file, no screenshot.
    const QString bad = dir_.filePath("cli_bad.json");
    {
      QFile f(bad);
      QVERIFY(f.open(QIODevice::WriteOnly));
      f.write("{\"format\": \"tunnelmap-session/1\"}");
    }
    const QString no_shot = dir_.filePath("no_shot.png");
    QCOMPARE(run({"--session", bad, "--screenshot", no_shot, "--exit"}, &err), 3);
    QVERIFY2(err.contains(bad + ": missing \"input\""), qPrintable(err));
    QVERIFY(!QFile::exists(no_shot));
    // --intrinsics on a PNG folder; malformed ones are refused.
    const QString k_shot = dir_.filePath("intrinsics_shot.png");
    QCOMPARE(run({png_folder_, "--intrinsics", "500,500,320,240", "--screenshot", k_shot, "--exit"}, &err), 0);
    QVERIFY(QFile::exists(k_shot));
    QCOMPARE(run({png_folder_, "--intrinsics", "500,500,320", "--screenshot", no_shot, "--exit"}, &err), 3);
    QVERIFY2(err.contains("--intrinsics expects 4"), qPrintable(err));
    QVERIFY(!QFile::exists(no_shot));
    // --device starts the live view on the simulated camera (found through the RUNPATH).
    const QString live_shot = dir_.filePath("live_shot.png");
    QCOMPARE(run({"--device", "tunnelmap-sim://lab?frames=3", "--screenshot", live_shot, "--exit"}, &err), 0);
    QVERIFY2(QFile::exists(live_shot), qPrintable(err));
    keep(live_shot);
  }
};

int main(int argc, char** argv) {
  QSurfaceFormat::setDefaultFormat(QVTKOpenGLNativeWidget::defaultFormat());
  QApplication app(argc, argv);
  QApplication::setOrganizationName("TunnelMapSessionTest");
  tunnelmap::openni2::register_openni_inputs();
  GuiSessionTest test;
  return QTest::qExec(&test, argc, argv);
}

#include "gui_session_test.moc"
