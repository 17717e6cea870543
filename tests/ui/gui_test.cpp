// GUI tests in a real window (run under xvfb-run -a): open a simulated sample, move the angle
// slider and check the pipeline re-ran from the planes stage with a different plane count,
// export a planes PLY and read it back, survive a corrupt file with an error shown.
#include <QDir>
#include <QElapsedTimer>
#include <QFile>
#include <QProcess>
#include <QSignalSpy>
#include <QSlider>
#include <QStandardPaths>
#include <QSurfaceFormat>
#include <QTemporaryDir>
#include <QVTKOpenGLNativeWidget.h>
#include <QtTest/QtTest>

#include "ui/main_window.h"
#include "ui/parameter_panel.h"
#include "ui/parameter_row.h"

using tunnelmap::ui::MainWindow;

class GuiTest : public QObject {
  Q_OBJECT

 private:
  QTemporaryDir dir_;
  QString sample_;

  // Waits for the next shown frame; false on timeout.
  static bool wait_frame(MainWindow& w, int timeout_ms = 20000) {
    QSignalSpy spy(&w, &MainWindow::frameShown);
    return spy.wait(timeout_ms);
  }

 private slots:
  void initTestCase() {
    QStandardPaths::setTestModeEnabled(true);  // QSettings in a test location
    QSettings().clear();
    QVERIFY(dir_.isValid());
    sample_ = dir_.filePath("lab");
    QProcess sim;
    sim.start(TUNNELMAP_CLI_PATH, {"simulate", "--preset", "lab", "--frames", "2", "--quiet", sample_});
    QVERIFY(sim.waitForFinished(60000));
    QCOMPARE(sim.exitCode(), 0);
  }

  void openSampleMoveAngleSliderReRunsPlanes() {
    MainWindow w;
    w.suppress_dialogs = true;
    w.resize(1280, 800);
    w.show();
    QVERIFY(QTest::qWaitForWindowExposed(&w));
    QVERIFY(w.open_input(sample_));
    QVERIFY(wait_frame(w));
    QVERIFY(w.current());
    const auto planes_before = w.current()->result.planes.planes.size();
    QVERIFY(planes_before > 0);
    const int runs_before = w.shown_runs();

    auto* row = w.parameter_panel()->row("grow.angle_deg");
    QVERIFY(row);
    QSlider* slider = row->slider();
    // Drag to 1 degree (a strict normal test splits walls into many small planes), release.
    QElapsedTimer latency;
    slider->setSliderDown(true);
    slider->setValue(static_cast<int>((1.0 - row->spec().min) / row->spec().step));
    latency.start();
    slider->setSliderDown(false);  // emits sliderReleased
    QVERIFY(wait_frame(w));
    const double ms = latency.nsecsElapsed() / 1e6;
    QCOMPARE(w.parameter_panel()->parameters().get("grow.angle_deg"), 1.0);
    QVERIFY(w.shown_runs() > runs_before);
    QCOMPARE(int(w.last_outcome().from), int(tunnelmap::Stage::Planes));  // cloud+normals reused
    const auto planes_after = w.current()->result.planes.planes.size();
    QVERIFY2(planes_after != planes_before,
             qPrintable(QString("plane count stayed %1").arg(planes_before)));
    const auto& t = w.current()->result.timings_ms;
    auto get = [&](const char* k) { auto it = t.find(k); return it == t.end() ? -1.0 : it->second; };
    qInfo("slider release -> view updated: %.1f ms; request -> result %.1f ms; stages planes %.1f, "
          "tunnel %.1f, total %.1f ms (planes %zu -> %zu, re-run from 'planes')",
          ms, w.last_outcome().wall_ms, get("planes"), get("tunnel"), get("total"), planes_before,
          planes_after);
  }

  void exportPlanesPlyAndReadBack() {
    MainWindow w;
    w.suppress_dialogs = true;
    w.show();
    QVERIFY(w.open_input(sample_));
    QVERIFY(wait_frame(w));
    const QString ply = dir_.filePath("planes.ply");
    QVERIFY(w.export_planes_ply(ply));
    QFile f(ply);
    QVERIFY(f.open(QIODevice::ReadOnly));
    const QByteArray head = f.read(4096);
    QVERIFY(head.startsWith("ply\n"));
    const int at = head.indexOf("element vertex ");
    QVERIFY(at > 0);
    const long long n = head.mid(at + 15, head.indexOf('\n', at) - at - 15).toLongLong();
    long long labelled = 0;
    const auto& r = w.current()->result;
    for (std::size_t i = 0; i < r.planes.labels.size(); ++i)
      if (r.planes.labels[i] > 0 && tunnelmap::OrganizedCloud::valid(r.cloud.points[i])) ++labelled;
    QCOMPARE(n, labelled);
    QVERIFY(w.export_map_ply(dir_.filePath("map.ply")));
    QVERIFY(QFile::exists(dir_.filePath("map.ply")));
    QVERIFY(w.save_screenshot(dir_.filePath("shot.png")));
    QImage shot(dir_.filePath("shot.png"));
    QCOMPARE(shot.size(), w.size());
  }

  void corruptFileShowsErrorAndKeepsState() {
    MainWindow w;
    w.suppress_dialogs = true;
    w.show();
    QVERIFY(w.open_input(sample_));
    QVERIFY(wait_frame(w));
    const auto* before = w.current();
    const QString bad = dir_.filePath("corrupt.png");
    QFile f(bad);
    QVERIFY(f.open(QIODevice::WriteOnly));
    f.write("\x89PNG\r\n\x1a\n this is not really a png");
    f.close();
    QSignalSpy errors(&w, &MainWindow::errorShown);
    QVERIFY(!w.open_input(bad));
    QCOMPARE(errors.count(), 1);
    QVERIFY2(w.last_error().contains("corrupt.png"), qPrintable(w.last_error()));
    QCOMPARE(w.input_path(), sample_);
    QCOMPARE(w.current(), before);
    QVERIFY(w.isVisible());
    QVERIFY(!w.load_preset(bad));  // not JSON either
    QVERIFY(w.last_error().contains("corrupt.png"));
  }
};

int main(int argc, char** argv) {
  QSurfaceFormat::setDefaultFormat(QVTKOpenGLNativeWidget::defaultFormat());
  QApplication app(argc, argv);
  QApplication::setOrganizationName("TunnelMapTest");
  GuiTest test;
  return QTest::qExec(&test, argc, argv);
}

#include "gui_test.moc"
