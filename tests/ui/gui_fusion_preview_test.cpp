// Processing > Fuse sequence shows the mesh growing (run under xvfb-run -a): while a simulated
// posed walk is integrated, the 3D view gets preview meshes of the frames fused so far (fewer
// triangles than the final one, shown before the fusion ends), and the final mesh is the same
// as a fusion without previews. Prints both fusions' wall times (the previews' cost).
// TUNNELMAP_GUI_SHOT_DIR=DIR keeps screenshots mid-fusion and at the end;
// TUNNELMAP_GUI_FUSE_FRAMES=N fuses a longer walk (default 6 frames), TUNNELMAP_GUI_FUSE_PRESET
// another simulator preset (default lab).
#include <QDir>
#include <QElapsedTimer>
#include <QSignalSpy>
#include <QStandardPaths>
#include <QSurfaceFormat>
#include <QTemporaryDir>
#include <QVTKOpenGLNativeWidget.h>
#include <QtTest/QtTest>
#include <cstdlib>

#include "core/sim/sim_config.h"
#include "core/sim/sim_dataset_writer.h"
#include "ui/fusion_controller.h"
#include "ui/fusion_preview.h"
#include "ui/main_window.h"
#include "ui/parameter_panel.h"
#include "ui/view3d_widget.h"

using tunnelmap::ui::MainWindow;
using tunnelmap::scene::Layer;

class GuiFusionPreviewTest : public QObject {
  Q_OBJECT

  QTemporaryDir dir_;
  QString walk_;

  struct Fused {
    bool ok = false;
    long long triangles = 0;
    double wall_s = 0.0;
    QString status;
  };

  // Fuses the open walk; `on_preview` runs on each preview shown.
  static Fused fuse(MainWindow& w, const std::function<void(long long)>& on_preview = {}) {
    QSignalSpy done(&w, &MainWindow::fusionFinished);
    QMetaObject::Connection c;
    using tunnelmap::ui::FusionPreview;
    if (on_preview) c = QObject::connect(w.fusion()->preview(), &FusionPreview::previewShown, on_preview);
    QElapsedTimer t;
    t.start();
    w.fuse_sequence();
    Fused f;
    f.ok = done.wait(300000) && done.takeFirst().at(0).toBool();
    f.wall_s = t.nsecsElapsed() / 1e9;
    QObject::disconnect(c);
    f.triangles = w.fused_triangles();
    f.status = w.status_text();
    return f;
  }

 private slots:
  void initTestCase() {
    QStandardPaths::setTestModeEnabled(true);
    QSettings().clear();
    QVERIFY(dir_.isValid());
    walk_ = dir_.filePath("walk");
    const char* preset = std::getenv("TUNNELMAP_GUI_FUSE_PRESET");
    tunnelmap::SimConfig cfg = tunnelmap::SimConfig::from_preset(preset ? preset : "lab");
    const char* frames = std::getenv("TUNNELMAP_GUI_FUSE_FRAMES");
    cfg.frames = frames ? std::atoi(frames) : 6;
    tunnelmap::write_sim_dataset(walk_.toStdString(), cfg);
  }

  void fusionShowsTheMeshGrowingAndEndsWithTheSameMesh() {
    MainWindow w;
    w.suppress_dialogs = true;
    w.resize(1400, 900);
    w.show();
    QVERIFY(QTest::qWaitForWindowExposed(&w));
    QVERIFY(w.open_input(walk_));
    QSignalSpy shown(&w, &MainWindow::frameShown);
    QVERIFY(shown.wait(20000));
    const char* shots = std::getenv("TUNNELMAP_GUI_SHOT_DIR");
    auto* preview = w.fusion()->preview();

    // Without previews first: a cold file cache then slows that one, not the previews.
    preview->set_interval_ms(-1);
    const Fused without = fuse(w);
    QVERIFY2(without.ok, qPrintable(w.last_error()));
    QVERIFY(preview->shown_triangles().isEmpty());

    // Each preview is in the view's mesh layer while the fusion still runs.
    preview->set_interval_ms(tunnelmap::ui::kPreviewIntervalMs);
    QSignalSpy finished(&w, &MainWindow::fusionFinished);
    QVector<long long> in_view;
    QString growing_status;
    const Fused with = fuse(w, [&](long long triangles) {
      in_view.push_back(w.view3d()->scene().layer_size(Layer::Mesh));
      QCOMPARE(in_view.back(), triangles);
      QCOMPARE(finished.count(), 0);
      growing_status = w.status_text();
      if (shots) w.save_screenshot(QDir(shots).filePath(QString("fusion_growing_%1.png").arg(in_view.size())));
    });
    QVERIFY2(with.ok, qPrintable(w.last_error()));
    if (shots) QVERIFY(w.save_screenshot(QDir(shots).filePath("fusion_done.png")));
    const QVector<long long> previews = preview->shown_triangles();
    qInfo("previews: %s; final %lld triangles; %s", qPrintable([&] {
            QStringList l;
            for (long long t : previews) l << QString::number(t);
            return l.join(", ");
          }()), with.triangles, qPrintable(growing_status));
    QVERIFY(!previews.isEmpty());
    QCOMPARE(in_view, previews);
    QVERIFY(previews.front() > 0);
    QVERIFY(previews.front() < with.triangles);
    QVERIFY2(growing_status.contains("triangles so far"), qPrintable(growing_status));
    QCOMPARE(w.view3d()->scene().layer_size(Layer::Mesh), with.triangles);
    QCOMPARE(with.triangles, without.triangles);  // the previews leave the final mesh alone
    qInfo("fusion wall time: %.2f s with %d previews (made in %.0f ms, shown in %.0f ms), %.2f s without (%s / %s)",
          with.wall_s, int(previews.size()), preview->worker_ms(), preview->show_ms(), without.wall_s,
          qPrintable(with.status.section(" — ", -1)), qPrintable(without.status.section(" — ", -1)));
  }

  // Cancel while the mesh grows: stops, reports it, no fusion adopted.
  void cancelDuringPreviewsStops() {
    MainWindow w;
    w.suppress_dialogs = true;
    w.show();
    QVERIFY(w.open_input(walk_));
    QSignalSpy shown(&w, &MainWindow::frameShown);
    QVERIFY(shown.wait(20000));
    w.fusion()->preview()->set_interval_ms(0);
    long long preview_triangles = 0;
    const Fused f = fuse(w, [&](long long triangles) {
      preview_triangles = triangles;
      w.cancel_sequence();
    });
    QVERIFY(!f.ok);
    QVERIFY2(f.status.contains("cancelled"), qPrintable(f.status));
    QCOMPARE(w.fused_frusta(), 0);
    // The partial mesh leaves the view: the current frame is shown again.
    QVERIFY(preview_triangles > 0);
    QVERIFY(shown.wait(20000));
    QCOMPARE(w.view3d()->scene().layer_size(Layer::Mesh), 0LL);
    QVERIFY(!w.fusion()->preview()->on_view());
  }
};

int main(int argc, char** argv) {
  QSurfaceFormat::setDefaultFormat(QVTKOpenGLNativeWidget::defaultFormat());
  QApplication app(argc, argv);
  QApplication::setOrganizationName("TunnelMapTest");
  GuiFusionPreviewTest test;
  return QTest::qExec(&test, argc, argv);
}

#include "gui_fusion_preview_test.moc"
