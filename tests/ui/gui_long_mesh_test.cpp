// The 3D view with a 100 m girder's mesh (run under xvfb-run -a): a mesh PLY as long and as
// fine as a fused 100 m girder at 8 mm voxels (a box tube around the shown frame's camera,
// ~12.5 M triangles) opens as pieces, the view of the frame draws the pieces near its camera at
// full resolution and the rest decimated, and a parameter slider released on the current frame
// gets the re-run frame rendered within the product's 200 ms (or, on a machine too busy for
// that even without the mesh, within 100 ms more than without it).
#include <QElapsedTimer>
#include <QSignalSpy>
#include <QSlider>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QTimer>
#include <QProcess>
#include <QtTest/QtTest>
#include <vtkRenderWindow.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "core/export/mesh_ply.h"
#include "core/fusion/triangle_mesh.h"
#include "core/util/build_paths.h"
#include "ui/main_window.h"
#include "ui/mesh_level_of_detail.h"
#include "ui/parameter_panel.h"
#include "ui/parameter_row.h"
#include "ui/view3d_widget.h"

using tunnelmap::ui::MainWindow;

namespace {

constexpr double kGirderM = 100.0, kWidthM = 0.8, kHeightM = 1.2, kGridM = 0.008;

// The four walls of a box tube along world x from `x0`, centred on (y, z), one vertex every
// 8 mm around and along, coloured by station.
tunnelmap::TriangleMesh long_girder(double x0, double y, double z) {
  tunnelmap::TriangleMesh m;
  std::vector<Eigen::Vector3f> ring;  // the cross-section, around
  const Eigen::Vector2d corners[5] = {{-kWidthM / 2, -kHeightM / 2}, {kWidthM / 2, -kHeightM / 2},
                                      {kWidthM / 2, kHeightM / 2}, {-kWidthM / 2, kHeightM / 2},
                                      {-kWidthM / 2, -kHeightM / 2}};
  for (int side = 0; side < 4; ++side) {
    const Eigen::Vector2d a = corners[side], b = corners[side + 1];
    const int steps = static_cast<int>(std::lround((b - a).norm() / kGridM));
    for (int s = 0; s < steps; ++s) {
      const Eigen::Vector2d p = a + (b - a) * (double(s) / steps);
      ring.emplace_back(0.0f, float(y + p.x()), float(z + p.y()));
    }
  }
  const int around = static_cast<int>(ring.size());
  const int along = static_cast<int>(std::lround(kGirderM / kGridM)) + 1;
  m.vertices.reserve(std::size_t(around) * along);
  for (int i = 0; i < along; ++i)
    for (const Eigen::Vector3f& r : ring) {
      m.vertices.emplace_back(float(x0 + i * kGridM), r.y(), r.z());
      m.colors.push_back({std::uint8_t(100 + i % 100), 120, std::uint8_t(80 + (i / 100) % 100)});
    }
  for (int i = 0; i + 1 < along; ++i)
    for (int k = 0; k < around; ++k) {
      const int a = i * around + k, b = i * around + (k + 1) % around, c = a + around, d = b + around;
      m.triangles.push_back({a, b, d});
      m.triangles.push_back({a, d, c});
    }
  return m;
}

}  // namespace

class GuiLongMeshTest : public QObject {
  Q_OBJECT

 private:
  QTemporaryDir dir_;

  static bool wait_frame(MainWindow& w, int timeout_ms = 20000) {
    QSignalSpy spy(&w, &MainWindow::frameShown);
    return spy.wait(timeout_ms);
  }

 private slots:
  void initTestCase() {
    QStandardPaths::setTestModeEnabled(true);
    QSettings().clear();
    QVERIFY(dir_.isValid());
    QProcess sim;
    sim.start(TUNNELMAP_CLI_PATH, {"simulate", "--preset", "lab", "--frames", "2", "--quiet", dir_.filePath("lab")});
    QVERIFY(sim.waitForFinished(60000));
    QCOMPARE(sim.exitCode(), 0);
  }

  void sliderOnTheCurrentFrameRendersWithinTheBoundBesideAHundredMetreMesh() {
    MainWindow w;
    w.suppress_dialogs = true;
    w.resize(1280, 800);
    w.show();
    QVERIFY(QTest::qWaitForWindowExposed(&w));
    QVERIFY(w.open_input(dir_.filePath("lab")));
    QVERIFY(wait_frame(w));
    QVERIFY(w.current() && w.current()->frame.pose);
    auto* row = w.parameter_panel()->row("grow.angle_deg");
    QVERIFY(row);
    QSlider* slider = row->slider();
    auto release_at = [&](double deg) -> double {
      QElapsedTimer latency;
      slider->setSliderDown(true);
      slider->setValue(static_cast<int>(std::lround((deg - row->spec().min) / row->spec().step)));
      latency.start();
      slider->setSliderDown(false);  // runs at once, no debounce
      if (!wait_frame(w)) return -1.0;
      return latency.nsecsElapsed() / 1e6;
    };
    // Median over five releases between the default and 1 degree.
    auto median_release_ms = [&](std::vector<double>& ms) {
      for (double deg : {1.0, row->spec().default_value, 1.0, row->spec().default_value, 1.0})
        ms.push_back(release_at(deg));
      std::sort(ms.begin(), ms.end());
      return ms[ms.size() / 2];
    };
    // The same window without a mesh first: what the re-run itself costs on this machine.
    std::vector<double> without_ms;
    const double without = median_release_ms(without_ms);
    QVERIFY2(without_ms.front() >= 0, qPrintable(w.last_error()));

    // The girder starts a metre behind the camera and runs 99 m ahead of it along x.
    const Eigen::Vector3d camera = w.current()->frame.pose->translation();
    const QString ply = dir_.filePath("girder.ply");
    long long triangles = 0;
    {
      const tunnelmap::TriangleMesh girder = long_girder(camera.x() - 1.0, camera.y(), camera.z());
      tunnelmap::write_mesh_ply(ply.toStdString(), girder, {});
      triangles = static_cast<long long>(girder.triangles.size());
    }
    // Cancel while the file is read: nothing shown, the job ends.
    QSignalSpy opened(&w, &MainWindow::meshOpened);
    QVERIFY(w.open_mesh(ply));
    QVERIFY(!w.open_mesh(ply));  // one job at a time
    w.cancel_sequence();  // the status bar's Cancel
    QVERIFY(opened.wait(120000));
    QCOMPARE(opened.takeFirst().at(0).toBool(), false);
    QCOMPARE(w.view3d()->scene().layer_size(tunnelmap::scene::Layer::Mesh), vtkIdType(0));

    // Opened on the background job: the event loop keeps turning while the file is read and
    // cut (a 10 ms timer's longest gap), and the mesh is swapped in when ready.
    QElapsedTimer open, since_tick;
    double longest_gap_ms = 0.0;
    int ticks = 0;
    QTimer tick;
    tick.setInterval(10);
    QObject::connect(&tick, &QTimer::timeout, [&] {
      longest_gap_ms = std::max(longest_gap_ms, since_tick.nsecsElapsed() / 1e6);
      since_tick.restart();
      ++ticks;
    });
    open.start();
    since_tick.start();
    tick.start();
    QVERIFY(w.open_mesh(ply));
    QVERIFY(opened.wait(300000));
    tick.stop();
    const double open_s = open.nsecsElapsed() / 1e9;
    QCOMPARE(opened.takeFirst().at(0).toBool(), true);
    qInfo("opening on the background job: %.1f s, %d ticks of the event loop, longest gap %.0f ms", open_s, ticks,
          longest_gap_ms);
    QVERIFY2(longest_gap_ms < 1000.0, qPrintable(QString("the event loop stalled for %1 ms").arg(longest_gap_ms)));

    vtkPolyData* shown = w.view3d()->scene().layer_polydata(tunnelmap::scene::Layer::Mesh);
    QVERIFY(shown);
    const long long drawn = shown->GetNumberOfPolys();
    // Full resolution near the camera (the budget) plus the decimated rest: a small part.
    QVERIFY2(drawn >= tunnelmap::ui::kLevelOfDetailNearTriangles / 2 &&
                 drawn <= tunnelmap::ui::kLevelOfDetailNearTriangles + triangles / 20,
             qPrintable(QString("%1 of %2 triangles drawn").arg(drawn).arg(triangles)));

    std::vector<double> ms;
    const double median = median_release_ms(ms);
    QVERIFY2(ms.front() >= 0, qPrintable(w.last_error()));
    // The same mesh layer after the re-runs: only the frame's own layers were rebuilt.
    QCOMPARE(w.view3d()->scene().layer_polydata(tunnelmap::scene::Layer::Mesh), shown);
    qInfo("long mesh: %lld triangles, opened (read + pieces) in %.1f s, %lld drawn; slider release -> "
          "view rendered over %zu releases: median %.1f ms (min %.1f, max %.1f), last GUI update + render "
          "%.1f ms; without the mesh: median %.1f ms (min %.1f, max %.1f)",
          triangles, open_s, drawn, ms.size(), median, ms.front(), ms.back(), w.last_show_ms(), without,
          without_ms.front(), without_ms.back());
    // The product's bound is 200 ms from release to the rendered view. On a machine so busy that
    // the re-run alone takes longer, the mesh may add at most 100 ms to it.
    const double bound = std::max(200.0, without + 100.0);
    QVERIFY2(median <= bound, qPrintable(QString("median %1 ms, bound %2 ms").arg(median).arg(bound)));
  }
};

QTEST_MAIN(GuiLongMeshTest)
#include "gui_long_mesh_test.moc"
