// GUI tests of the review workflow (run under xvfb-run -a, no LD_LIBRARY_PATH):
// - the GUI binary finds the simulated OpenNI2 camera with no environment variable set;
// - errors go to one message area (status bar + Messages dock), never a pile of dialogs, and a
//   --screenshot --exit run on a bad input exits 3 instead of blocking;
// - timeline, results table, plot and 3D view show the same frame, whichever is clicked, and
//   the frame keys work with the focus in the 3D view;
// - the plot draws width and height on their own axes, the current-frame marker, the ground
//   truth with its tolerance band, and flags frames outside it.
// - every row names its method and parameter set, summaries never mix them and give the error
//   against ground truth; a cancelled sequence says so; the preset's name is shown and the
//   dataset's matching preset offered;
// - parameter changes undo and redo (Edit menu, Ctrl+Z / Ctrl+Shift+Z); Reset all asks first.
// TUNNELMAP_GUI_SHOT_DIR=DIR keeps the window and plot grabs.
#include <QAbstractButton>
#include <QAction>
#include <QDialog>
#include <QDockWidget>
#include <QDoubleSpinBox>
#include <QLabel>
#include <QProcess>
#include <QProgressBar>
#include <QPushButton>
#include <QScrollArea>
#include <QScrollBar>
#include <QWheelEvent>
#include <QSignalSpy>
#include <QSlider>
#include <QStandardPaths>
#include <QStyleOptionSlider>
#include <QSurfaceFormat>
#include <QTableWidget>
#include <QTemporaryDir>
#include <QToolButton>
#include <QUndoStack>
#include <QVTKOpenGLNativeWidget.h>
#include <QtTest/QtTest>
#include <QFile>
#include <set>
#include <nlohmann/json.hpp>
#include <algorithm>
#include <cmath>

#include "core/util/build_paths.h"
#include "sensors/openni/register_openni.h"
#include "ui/main_window.h"
#include "ui/message_log.h"
#include "ui/parameter_panel.h"
#include "ui/parameter_row.h"
#include "ui/results_panel.h"
#include "ui/results_plot.h"
#include "ui/timeline_widget.h"
#include "ui/view3d_widget.h"

using tunnelmap::ui::MainWindow;

class GuiReviewTest : public QObject {
  Q_OBJECT

 private:
  QTemporaryDir dir_;
  QString sample_;  // 12-frame simulated lab dataset with ground truth
  static constexpr int kFrames = 12;

  static bool wait_frame(MainWindow& w, int timeout_ms = 20000) {
    QSignalSpy spy(&w, &MainWindow::frameShown);
    return spy.wait(timeout_ms);
  }
  // Waits until frame `index` is the one the views show.
  static bool wait_shown(MainWindow& w, int index) {
    for (int i = 0; i < 200 && !(w.last_outcome().frame_index == index && w.current()); ++i) QTest::qWait(50);
    return w.last_outcome().frame_index == index;
  }
  // Every widget's idea of the current frame: timeline, table selection, plot marker, 3D view.
  static QString frames_shown(MainWindow& w) {
    return QString("timeline %1, table %2, plot %3, 3D %4")
        .arg(w.timeline()->frame())
        .arg(w.results_panel()->selected_frame())
        .arg(w.results_panel()->plot()->current())
        .arg(w.last_outcome().frame_index);
  }
  static bool all_at(MainWindow& w, int index) {
    return wait_shown(w, index) && w.timeline()->frame() == index && w.results_panel()->selected_frame() == index &&
           w.results_panel()->plot()->current() == index;
  }
  static QProcessEnvironment without_ld_path() {
    QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
    env.remove("LD_LIBRARY_PATH");
    env.insert("XDG_CONFIG_HOME", QDir::tempPath() + "/tunnelmap-review-test-config");
    return env;
  }
  static void keep(const QImage& image, const QString& name) {
    const QString dir = qEnvironmentVariable("TUNNELMAP_GUI_SHOT_DIR");
    if (!dir.isEmpty()) image.save(QDir(dir).filePath(name));
  }

 private slots:
  void initTestCase() {
    QStandardPaths::setTestModeEnabled(true);
    QSettings().clear();
    QVERIFY(dir_.isValid());
    sample_ = dir_.filePath("lab12");
    QProcess sim;
    sim.start(TUNNELMAP_CLI_PATH, {"simulate", "--preset", "lab", "--frames", QString::number(kFrames), "--quiet", sample_});
    QVERIFY(sim.waitForFinished(120000));
    QCOMPARE(sim.exitCode(), 0);
  }

  // The GUI binary, started without LD_LIBRARY_PATH, lists the simulated camera (its RUNPATH
  // selects the build's OpenNI2 copy whose drivers folder holds the simulator).
  void guiBinaryListsSimulatedDeviceWithoutEnvironment() {
    QProcess gui;
    gui.setProcessEnvironment(without_ld_path());
    gui.start(TUNNELMAP_GUI_PATH, {"--list-devices"});
    QVERIFY2(gui.waitForStarted(10000), qPrintable(TUNNELMAP_GUI_PATH + QString(": ") + gui.errorString()));
    QVERIFY(gui.waitForFinished(60000));
    const QString out = QString::fromUtf8(gui.readAllStandardOutput());
    QCOMPARE(gui.exitCode(), 0);
    QVERIFY2(out.split('\n').contains("tunnelmap-sim://lab"), qPrintable(out + gui.readAllStandardError()));
  }

  // A batch run on a corrupt input exits 3 with a one-line error instead of waiting on a dialog.
  void screenshotExitOnBadInputNeverBlocks() {
    const QString bad = dir_.filePath("corrupt.png");
    QFile f(bad);
    QVERIFY(f.open(QIODevice::WriteOnly));
    f.write("\x89PNG\r\n\x1a\n not a png");
    f.close();
    QProcess gui;
    gui.setProcessEnvironment(without_ld_path());
    QElapsedTimer t;
    t.start();
    gui.start(TUNNELMAP_GUI_PATH, {bad, "--screenshot", dir_.filePath("never.png"), "--exit"});
    QVERIFY2(gui.waitForStarted(10000), qPrintable(TUNNELMAP_GUI_PATH + QString(": ") + gui.errorString()));
    QVERIFY(gui.waitForFinished(30000));
    QCOMPARE(gui.exitCode(), 3);
    QVERIFY(QString::fromUtf8(gui.readAllStandardError()).contains("corrupt.png"));
    QVERIFY(!QFileInfo::exists(dir_.filePath("never.png")));
    qInfo("bad input, --screenshot --exit: exit 3 after %lld ms", (long long)t.elapsed());
  }

  // Three errors: three lines in the Messages dock, the newest in the status bar, no dialog.
  void errorsGoToOneMessageArea() {
    MainWindow w;
    w.resize(1280, 720);
    w.show();
    QVERIFY(QTest::qWaitForWindowExposed(&w));
    auto* button = w.findChild<QToolButton*>("messagesButton");
    auto* dock = w.findChild<QDockWidget*>("messagesDock");
    QVERIFY(button && dock);
    QVERIFY(!button->isVisible());
    const QStringList bad = {dir_.filePath("missing1.png"), dir_.filePath("missing2.pcd"), dir_.filePath("missing3.json")};
    for (const QString& p : bad) QVERIFY(!w.open_input(p));
    QVERIFY(!w.load_preset(dir_.filePath("nope.json")));
    QTest::qWait(100);
    QCOMPARE(w.messages()->count(), 4);
    for (int i = 0; i < 3; ++i) QVERIFY2(w.messages()->message(i).contains(QFileInfo(bad[i]).fileName()), qPrintable(w.messages()->message(i)));
    QVERIFY(w.status_text().contains("nope.json"));
    for (QWidget* top : QApplication::topLevelWidgets())
      QVERIFY2(!(qobject_cast<QDialog*>(top) && top->isVisible()), qPrintable(top->metaObject()->className()));
    QVERIFY(button->isVisible());
    QVERIFY2(button->text().contains("4"), qPrintable(button->text()));
    QVERIFY(!dock->isVisible());
    QTest::mouseClick(button, Qt::LeftButton);
    QVERIFY(dock->isVisible());
    keep(w.grab().toImage(), "messages.png");
  }

  // Clicking the timeline, a table row or the plot, or pressing a frame key in the 3D view moves
  // every view to that frame; the table numbers frames from 1 like the timeline.
  void linkedNavigationAcrossViews() {
    MainWindow w;
    w.resize(1600, 1000);
    w.show();
    QVERIFY(QTest::qWaitForWindowExposed(&w));
    QVERIFY(w.open_input(sample_));
    QVERIFY(wait_frame(w));
    QVERIFY(all_at(w, 0));
    w.process_sequence();
    QTableWidget* table = w.results_panel()->table();
    for (int i = 0; i < 600 && w.results_panel()->records().size() < std::size_t(kFrames); ++i) QTest::qWait(100);
    QCOMPARE(int(w.results_panel()->records().size()), kFrames);
    QTest::qWait(200);
    QCOMPARE(table->item(0, 0)->text(), QString("1"));
    QCOMPARE(table->item(kFrames - 1, 0)->text(), QString::number(kFrames));

    // Timeline: a click on frame 6 (index 5) goes there, not a page step of 10.
    QSlider* slider = w.timeline()->slider();
    QStyleOptionSlider opt;
    opt.initFrom(slider);
    opt.orientation = slider->orientation();
    opt.minimum = slider->minimum();
    opt.maximum = slider->maximum();
    const QRect groove = slider->style()->subControlRect(QStyle::CC_Slider, &opt, QStyle::SC_SliderGroove, slider);
    const QRect handle = slider->style()->subControlRect(QStyle::CC_Slider, &opt, QStyle::SC_SliderHandle, slider);
    const int span = groove.width() - handle.width();
    const int x = groove.left() + handle.width() / 2 + QStyle::sliderPositionFromValue(0, kFrames - 1, 5, span);
    QTest::mouseClick(slider, Qt::LeftButton, {}, QPoint(x, slider->height() / 2));
    QVERIFY2(all_at(w, 5), qPrintable(frames_shown(w)));
    QVERIFY2(w.timeline()->label_text().startsWith("6 / 12"), qPrintable(w.timeline()->label_text()));
    QVERIFY2(w.status_text().startsWith("Frame 6/12"), qPrintable(w.status_text()));

    // Table: a click on the row numbered 10.
    const QRect row = table->visualItemRect(table->item(9, 1));
    table->scrollToItem(table->item(9, 1));
    QTest::mouseClick(table->viewport(), Qt::LeftButton, {}, table->visualItemRect(table->item(9, 1)).center());
    Q_UNUSED(row);
    QVERIFY2(all_at(w, 9), qPrintable(frames_shown(w)));
    QCOMPARE(table->item(table->currentRow(), 0)->text(), QString("10"));
    QVERIFY2(std::abs(table->item(9, 2)->text().toDouble() - 0.82) < 0.03, qPrintable(table->item(9, 2)->text()));  // width (m)

    // Plot: a click at frame 3's x.
    tunnelmap::ui::ResultsPlot* plot = w.results_panel()->plot();
    QTest::mouseClick(plot, Qt::LeftButton, {}, QPoint(int(std::lround(plot->x_of(2))), int(plot->area(1).center().y())));
    QVERIFY2(all_at(w, 2), qPrintable(frames_shown(w)));

    // Keys with the focus in the 3D view.
    w.activateWindow();  // no window manager under Xvfb
    QApplication::setActiveWindow(&w);
    QVERIFY(QTest::qWaitForWindowActive(&w));
    w.view3d()->setFocus();
    QTRY_VERIFY(w.view3d()->hasFocus());
    const struct { Qt::Key key; int expected; } keys[] = {
        {Qt::Key_Right, 3}, {Qt::Key_End, kFrames - 1}, {Qt::Key_Left, kFrames - 2}, {Qt::Key_Home, 0},
        {Qt::Key_Left, 0},  {Qt::Key_PageDown, 10},     {Qt::Key_PageDown, kFrames - 1}, {Qt::Key_PageUp, 1}};
    for (const auto& k : keys) {
      QTest::keyClick(w.view3d(), k.key);
      QVERIFY2(all_at(w, k.expected), qPrintable(QString("key %1: %2").arg(int(k.key), 0, 16).arg(frames_shown(w))));
    }
    keep(w.grab().toImage(), "review_1600x1000.png");
  }

  // The plot: two axes, marker at the shown frame (green pixels there), the dataset's ground
  // truth as reference; a 0.5 mm tolerance flags frames (red dots), 500 mm flags none.
  void plotShowsMarkerReferenceAndFlags() {
    MainWindow w;
    w.resize(1280, 720);
    w.show();
    QVERIFY(QTest::qWaitForWindowExposed(&w));
    QVERIFY(w.open_input(sample_));
    QVERIFY(wait_frame(w));
    w.process_sequence();
    for (int i = 0; i < 600 && w.results_panel()->records().size() < std::size_t(kFrames); ++i) QTest::qWait(100);
    QVERIFY(w.select_frame(4));
    QVERIFY(all_at(w, 4));
    tunnelmap::ui::ResultsPlot* plot = w.results_panel()->plot();
    const auto& ref = plot->reference();
    QCOMPARE(ref.source, QString("ground truth"));
    QVERIFY(ref.width_m && ref.height_m);
    QVERIFY2(std::abs(*ref.width_m - 0.82) < 0.05 && std::abs(*ref.height_m - 1.30) < 0.05,
             qPrintable(QString("%1 x %2").arg(*ref.width_m).arg(*ref.height_m)));
    QVERIFY(plot->area(0).bottom() < plot->area(1).top());  // separate width and height axes

    // A tolerance change re-runs from a late stage; the Time column keeps the whole pipeline's
    // time of the shown result (cloud + normals + planes + tunnel), not the re-run's.
    QTableWidget* table = w.results_panel()->table();
    const double full_ms = table->item(4, 5)->text().toDouble();
    auto* tol = w.parameter_panel()->row("map.tolerance_mm");
    QVERIFY(tol);
    tol->spin_box()->setValue(0.5);
    QVERIFY(wait_frame(w));
    QVERIFY(int(w.last_outcome().from) > int(tunnelmap::Stage::Planes));
    const double rerun_total = w.current()->result.timings_ms.at("total");
    const double shown_ms = table->item(4, 5)->text().toDouble();
    qInfo("Time column: %.1f ms after the full run, %.1f ms after a re-run from stage %d that took %.2f ms",
          full_ms, shown_ms, int(w.last_outcome().from), rerun_total);
    // The whole pipeline takes milliseconds (3-10 ms per frame here), the re-run a few
    // hundredths. The shown row is the frame's own run (not the sequence's, whose parameters
    // differ now), so its whole-pipeline time is that run's, not the sequence's: two runs'
    // times, which a cold cache or a busy machine sets apart by 12x and more, so only the
    // re-run's far smaller time is ruled out.
    QVERIFY2(full_ms > 1.0 && full_ms > 10.0 * rerun_total && shown_ms > 10.0 * rerun_total,
             qPrintable(QString("%1 vs %2 (re-run %3)").arg(shown_ms).arg(full_ms).arg(rerun_total)));
    const auto flagged = plot->out_of_tolerance();
    QVERIFY2(!flagged.empty(), "0.5 mm tolerance flags no frame");
    const QImage img = plot->grab().toImage();
    keep(img, "plot_flags.png");
    // The marker: green pixels in the column of frame 5.
    const int mx = int(std::lround(plot->x_of(4)));
    int green = 0, red = 0;
    for (int x = mx - 1; x <= mx + 1; ++x) {
      int column = 0;
      for (int y = 0; y < img.height(); ++y) {
        const QColor c = img.pixelColor(x, y);
        if (c.green() > 120 && c.red() < 60 && c.blue() < 100) ++column;
      }
      green = std::max(green, column);
    }
    for (int y = 0; y < img.height(); ++y)
      for (int x = 0; x < img.width(); ++x) {
        const QColor c = img.pixelColor(x, y);
        if (c.red() > 200 && c.green() < 60 && c.blue() < 60) ++red;
      }
    QVERIFY2(green > plot->area(0).height(), qPrintable(QString::number(green)));
    QVERIFY2(red >= 10, qPrintable(QString::number(red)));
    keep(w.grab().toImage(), "review_1280x720.png");
    tol->spin_box()->setValue(500.0);
    QTest::qWait(100);
    QVERIFY(plot->out_of_tolerance().empty());
    qInfo("plot: %zu of %d frames outside 0.5 mm of the ground truth %.3f x %.3f m", flagged.size(), kFrames,
          *ref.width_m, *ref.height_m);
  }

  // Parameter changes are undoable steps (Edit > Undo / Redo, Ctrl+Z / Ctrl+Shift+Z) that re-run
  // the frame; Reset all asks first, and a batch/test window (suppress_dialogs) is never asked.
  void parameterUndoRedoAndResetAsks() {
    MainWindow w;
    w.show();
    QVERIFY(QTest::qWaitForWindowExposed(&w));
    QVERIFY(w.open_input(sample_));
    QVERIFY(wait_frame(w));
    auto* panel = w.parameter_panel();
    auto* angle = panel->row("grow.angle_deg");
    auto* range = panel->row("cloud.max_range_m");
    QVERIFY(angle && range);
    const double angle0 = angle->value(), range0 = range->value();
    auto value = [&](const char* key) { return w.parameter_panel()->parameters().get(key); };
    angle->spin_box()->setValue(angle0 + 2.0);
    QVERIFY(wait_frame(w));
    range->spin_box()->setValue(range0 - 1.0);
    QVERIFY(wait_frame(w));
    QCOMPARE(panel->undo_stack()->count(), 2);

    w.findChild<QAction*>("undo")->trigger();  // the range change
    QVERIFY(wait_frame(w));
    QCOMPARE(value("cloud.max_range_m"), range0);
    QCOMPARE(range->value(), range0);
    QCOMPARE(w.last_outcome().params.get("cloud.max_range_m"), range0);  // the shown run used it
    QCOMPARE(value("grow.angle_deg"), angle0 + 2.0);

    w.activateWindow();
    QApplication::setActiveWindow(&w);
    QVERIFY(QTest::qWaitForWindowActive(&w));
    w.view3d()->setFocus();
    QTest::keyClick(w.view3d(), Qt::Key_Z, Qt::ControlModifier);  // the angle change
    QVERIFY(wait_frame(w));
    QCOMPARE(value("grow.angle_deg"), angle0);
    QTest::keyClick(w.view3d(), Qt::Key_Z, Qt::ControlModifier | Qt::ShiftModifier);
    QVERIFY(wait_frame(w));
    QCOMPARE(value("grow.angle_deg"), angle0 + 2.0);
    QCOMPARE(angle->value(), angle0 + 2.0);

    auto* reset = w.findChild<QAbstractButton*>("resetAll");
    QVERIFY(reset);
    int asked = 0;
    const auto ask = panel->confirm_reset;
    panel->confirm_reset = [&] { ++asked; return false; };
    reset->click();
    QCOMPARE(asked, 1);
    QCOMPARE(value("grow.angle_deg"), angle0 + 2.0);  // "no" keeps the values
    panel->confirm_reset = [&] { ++asked; return true; };
    reset->click();
    QVERIFY(wait_frame(w));
    QCOMPARE(asked, 2);
    QCOMPARE(value("grow.angle_deg"), angle0);
    QCOMPARE(value("cloud.max_range_m"), range0);
    w.findChild<QAction*>("undo")->trigger();  // Reset all is one step
    QVERIFY(wait_frame(w));
    QCOMPARE(value("grow.angle_deg"), angle0 + 2.0);

    // The window's own hook under suppress_dialogs: never asks, answers no, shows no dialog.
    panel->confirm_reset = ask;
    w.suppress_dialogs = true;
    reset->click();
    QTest::qWait(100);
    QCOMPARE(value("grow.angle_deg"), angle0 + 2.0);
    for (QWidget* top : QApplication::topLevelWidgets())
      QVERIFY2(!(qobject_cast<QDialog*>(top) && top->isVisible()), qPrintable(top->metaObject()->className()));
  }

  // A click on the groove, an arrow key and a drag are one undo step each, and an undo reverts
  // exactly its own parameter; the wheel over a slider or a value scrolls the panel and edits
  // nothing; a range over decades (min points) is logarithmic, so a 10-pixel drag from 40
  // stays below 100 (linear, it reached 23,258).
  void everyInputIsOneUndoStepAndTheWheelScrolls() {
    MainWindow w;  // the first-start layout (no saved settings)
    w.show();
    QVERIFY(QTest::qWaitForWindowExposed(&w));
    QVERIFY(w.open_input(sample_));
    QVERIFY(wait_frame(w));
    auto* panel = w.parameter_panel();
    QUndoStack* undo = panel->undo_stack();
    auto value = [&](const char* key) { return panel->parameters().get(key); };
    QSlider* angle = panel->row("grow.angle_deg")->slider();
    const double angle0 = value("grow.angle_deg");
    QTest::mouseClick(angle, Qt::LeftButton, {}, QPoint(angle->width() - 3, angle->height() / 2));
    QVERIFY(value("grow.angle_deg") > angle0);
    QCOMPARE(undo->count(), 1);
    const double angle1 = value("grow.angle_deg");

    QSlider* distance = panel->row("grow.distance_mm")->slider();
    const double distance0 = value("grow.distance_mm");
    distance->setFocus();
    QTest::keyClick(distance, Qt::Key_Right);
    QCOMPARE(value("grow.distance_mm"), distance0 + 0.5);
    QCOMPARE(undo->count(), 2);

    auto* scroll = panel->findChild<QScrollArea*>();
    QVERIFY(scroll && scroll->verticalScrollBar()->maximum() > 0);
    const int scrolled0 = scroll->verticalScrollBar()->value();
    for (QWidget* target : {static_cast<QWidget*>(distance),
                            static_cast<QWidget*>(panel->row("grow.distance_mm")->spin_box())}) {
      QWheelEvent wheel(QPointF(5, 5), target->mapToGlobal(QPoint(5, 5)), QPoint(), QPoint(0, -120), Qt::NoButton,
                        Qt::NoModifier, Qt::NoScrollPhase, false);
      QApplication::sendEvent(target, &wheel);
    }
    QCOMPARE(value("grow.distance_mm"), distance0 + 0.5);
    QCOMPARE(undo->count(), 2);
    QVERIFY(scroll->verticalScrollBar()->value() > scrolled0);

    undo->undo();  // the key only
    QCOMPARE(value("grow.distance_mm"), distance0);
    QCOMPARE(value("grow.angle_deg"), angle1);
    QVERIFY(wait_frame(w));

    auto* min_points = panel->row("grow.min_points");
    QVERIFY(min_points->scale().logarithmic());
    QVERIFY(!panel->row("grow.angle_deg")->scale().logarithmic());
    scroll->ensureWidgetVisible(min_points);
    QTest::qWait(50);
    QSlider* slider = min_points->slider();
    QStyleOptionSlider opt;
    opt.initFrom(slider);
    opt.orientation = Qt::Horizontal;
    opt.minimum = slider->minimum(), opt.maximum = slider->maximum();
    opt.sliderPosition = opt.sliderValue = slider->value();
    const QPoint handle =
        slider->style()->subControlRect(QStyle::CC_Slider, &opt, QStyle::SC_SliderHandle, slider).center();
    QTest::mousePress(slider, Qt::LeftButton, {}, handle);
    for (int dx : {5, 10}) {  // QTest::mouseMove carries no pressed button: a drag needs one
      QMouseEvent move(QEvent::MouseMove, handle + QPoint(dx, 0), slider->mapToGlobal(handle + QPoint(dx, 0)),
                       Qt::NoButton, Qt::LeftButton, Qt::NoModifier);
      QApplication::sendEvent(slider, &move);
    }
    QTest::mouseRelease(slider, Qt::LeftButton, {}, handle + QPoint(10, 0));
    const double points = value("grow.min_points");
    keep(w.grab().toImage(), "parameters_1600x900.png");
    QVERIFY2(points > 40 && points < 100, qPrintable(QString::number(points)));
    QCOMPARE(undo->count(), 2);  // the drag: one step (the undone key step was replaced)
  }

  // Only the sliders the detection reads are live: another method's rows are hidden, and rows
  // the growing order does not read are greyed with the reason in their tooltip.
  void onlySlidersThatCountAreShown() {
    MainWindow w;
    w.show();
    QVERIFY(QTest::qWaitForWindowExposed(&w));
    auto* panel = w.parameter_panel();
    auto* ransac = panel->row("ransac.iterations");
    auto* normal_window = panel->row("normals.smoothing_px");
    auto* angle = panel->row("grow.angle_deg");
    QVERIFY(ransac->isHidden());
    QVERIFY(!angle->isHidden() && angle->isEnabled());
    QVERIFY(!normal_window->isHidden() && !normal_window->isEnabled());
    QVERIFY(normal_window->slider()->toolTip().startsWith("Not used now"));
    QVERIFY(!panel->row("grow.grid_step")->isEnabled());
    QVERIFY(!panel->row("grow.neighbourhood_n")->isEnabled());
    QVERIFY(panel->row("grow.candidate_distance_mm")->isEnabled());

    w.set_method(tunnelmap::Method::Ransac);
    QVERIFY(!ransac->isHidden());
    QVERIFY(angle->isHidden());
    QVERIFY(panel->row("qhull.min_points")->isHidden());
    w.set_method(tunnelmap::Method::Pgc);

    panel->row("grow.cell_px")->spin_box()->setValue(0);  // the pixel grid reads the normals
    QVERIFY(normal_window->isEnabled());
    QVERIFY(!normal_window->slider()->toolTip().startsWith("Not used now"));
    QVERIFY(panel->row("grow.grid_step")->isEnabled());
    QVERIFY(ransac->isHidden());
  }

  // Every row names its method and parameter set; the summary has one line per (method, set)
  // with the error against the dataset's ground truth; a cancelled sequence says so and keeps
  // the rows that finished.
  void summariesNeverMixMethodsOrParameterSets() {
    MainWindow w;
    w.suppress_dialogs = true;
    w.show();
    QVERIFY(w.open_input(sample_));
    QVERIFY(wait_frame(w));
    w.process_sequence();
    for (int i = 0; i < 600 && w.results_panel()->records().size() < std::size_t(kFrames); ++i) QTest::qWait(100);
    QTRY_VERIFY_WITH_TIMEOUT(!w.findChild<QProgressBar*>()->isVisible(), 20000);
    QTableWidget* table = w.results_panel()->table();
    QString summary = w.results_panel()->summary_text();
    qInfo("%s", qPrintable(summary));
    QCOMPARE(summary.count('\n'), 0);
    QVERIFY2(summary.startsWith("PG&C, params #1: 12/12 detected"), qPrintable(summary));
    QVERIFY2(summary.contains(" mm vs ground truth"), qPrintable(summary));
    // The error printed is the mean |width - 0.820|: recompute it from the rows.
    double ew = 0;
    for (const auto& r : w.results_panel()->records()) {
      QVERIFY(r.width_m);
      ew += std::abs(*r.width_m - 0.82) * 1000 / kFrames;
    }
    QVERIFY2(summary.contains(QString("error %1 / ").arg(ew, 0, 'f', 1)), qPrintable(QString::number(ew)));
    QCOMPARE(table->item(3, 7)->text(), QString("#1"));

    // Another parameter set for frame 1: its row says #2 and gets its own summary line.
    auto* angle = w.parameter_panel()->row("grow.angle_deg");
    angle->spin_box()->setValue(angle->value() + 1.0);
    QVERIFY(wait_frame(w));
    QCOMPARE(table->item(0, 7)->text(), QString("#2"));
    summary = w.results_panel()->summary_text();
    QVERIFY2(summary.contains("PG&C, params #1: 11/11") && summary.contains("PG&C, params #2: 1/1"), qPrintable(summary));

    // Qhull over the sequence, cancelled at once: "cancelled", the finished rows are Qhull's,
    // the others stay PG&C's, and the summaries are separate.
    w.set_method(tunnelmap::Method::Qhull);
    QVERIFY(wait_frame(w));
    w.process_sequence();
    w.cancel_sequence();
    QTRY_VERIFY_WITH_TIMEOUT(!w.findChild<QProgressBar*>()->isVisible(), 20000);
    QVERIFY2(w.status_text().startsWith("Sequence cancelled after "), qPrintable(w.status_text()));
    int qhull = 0;
    for (const auto& r : w.results_panel()->records()) qhull += r.method == tunnelmap::Method::Qhull;
    QCOMPARE(int(w.results_panel()->records().size()), kFrames);
    QVERIFY2(qhull >= 1 && qhull < kFrames, qPrintable(QString::number(qhull)));
    summary = w.results_panel()->summary_text();
    qInfo("after the cancelled Qhull run (%d Qhull rows):\n%s", qhull, qPrintable(summary));
    QVERIFY2(summary.contains("Qhull, params #2: ") && summary.contains("PG&C, params #1: "), qPrintable(summary));
    for (const QString& line : summary.split('\n')) QVERIFY(line.count("params #") == 1);

    // The exported results never mix them either: the summary is the current group's (Qhull,
    // set #2), every row names its set, and "summaries" gives each group its own.
    const QString json = dir_.filePath("mixed.json");
    QVERIFY(w.export_results_json(json));
    QFile file(json);
    QVERIFY(file.open(QIODevice::ReadOnly));
    const auto doc = nlohmann::json::parse(file.readAll().toStdString());
    QCOMPARE(QString::fromStdString(doc["method"].get<std::string>()), QString("qhull"));
    QCOMPARE(doc["summary"]["frames"].get<int>(), qhull);
    std::set<std::pair<int, int>> groups;  // (method, set) of the rows: PG&C #1 and Qhull #2 here
    for (const auto& r : w.results_panel()->records()) groups.insert({static_cast<int>(r.method), r.param_set});
    QVERIFY(groups.size() >= 2);
    QCOMPARE(doc["summaries"].size(), groups.size());
    int rows = 0;
    for (const auto& g : doc["summaries"]) rows += g["summary"]["frames"].get<int>();
    QCOMPARE(rows, kFrames);
    for (const auto& f : doc["frames"]) QVERIFY(f.contains("param_set"));
    QCOMPARE(doc["params"]["grow.angle_deg"].get<double>(), angle->value());
  }

  // The loaded preset is named in the title and status bar; the simulated lab dataset names its
  // kind, so the lab preset is offered (a status-bar button, no dialog) and loads on a click.
  void presetNameShownAndMatchingPresetOffered() {
    MainWindow w;
    w.suppress_dialogs = true;
    w.show();
    auto* label = w.findChild<QLabel*>("presetLabel");
    auto* offer = w.findChild<QPushButton*>("offerPreset");
    QVERIFY(label && offer);
    QCOMPARE(label->text(), QString("Preset: defaults"));
    QVERIFY(w.open_input(sample_));
    QVERIFY(wait_frame(w));
    QVERIFY(offer->isVisible());
    QVERIFY2(offer->text().contains("lab"), qPrintable(offer->text()));
    QTest::mouseClick(offer, Qt::LeftButton);
    QVERIFY(wait_frame(w));
    QCOMPARE(w.preset_name(), QString("lab"));
    QCOMPARE(label->text(), QString("Preset: lab"));
    QVERIFY2(w.windowTitle().contains("lab12") && w.windowTitle().contains("preset lab"), qPrintable(w.windowTitle()));
    QVERIFY(!offer->isVisible());
    auto* range = w.parameter_panel()->row("cloud.max_range_m");
    range->spin_box()->setValue(range->value() - 0.5);
    QVERIFY(wait_frame(w));
    QCOMPARE(label->text(), QString("Preset: lab (modified)"));
    w.findChild<QAction*>("undo")->trigger();
    QVERIFY(wait_frame(w));
    QCOMPARE(label->text(), QString("Preset: lab"));
  }
};

int main(int argc, char** argv) {
  QSurfaceFormat::setDefaultFormat(QVTKOpenGLNativeWidget::defaultFormat());
  QApplication app(argc, argv);
  QApplication::setOrganizationName("TunnelMapTest");
  tunnelmap::openni2::register_openni_inputs();
  GuiReviewTest test;
  return QTest::qExec(&test, argc, argv);
}

#include "gui_review_test.moc"
