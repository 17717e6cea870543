// The measuring views under Xvfb. The cross-section dock, on a hand-built 1.0 x 0.8 m tunnel,
// draws the fitted rectangle where the walls are, the dashed design rectangle, a caption with
// the deviation, measures between two clicked points, and its slider walks the frame's visible
// stations. The profile plot draws stations beyond tolerance red and selects the clicked one.
// The 3D view's and the 2D depth view's measure modes pick two wall points and measure the
// width between them. The
// main window maps a posed walk and moves to a clicked station.
// TUNNELMAP_GUI_SHOT_DIR=DIR keeps screenshots of both.
#include <QApplication>
#include <QDoubleSpinBox>
#include <QSignalSpy>
#include <QSlider>
#include <QProgressBar>
#include <QUndoStack>
#include <QTreeWidget>
#include <QAction>
#include <QRegularExpression>
#include <QtTest/QtTest>
#include <algorithm>
#include <cmath>
#include <memory>

#include "core/util/build_paths.h"
#include "tests/ui/synthetic_tunnel.h"
#include "ui/cross_section_panel.h"
#include "ui/depth_view_widget.h"
#include "core/tunnel/tunnel_options.h"
#include "ui/main_window.h"
#include "core/mapping/rescan_stretches.h"
#include "core/mapping/station_frames.h"
#include "ui/map_sections_panel.h"
#include "ui/parameter_panel.h"
#include "ui/profile_plot.h"
#include "ui/view3d_widget.h"
#include <QFile>
#include <QImage>
#include <QProcess>
#include <QSettings>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QDir>
#include <nlohmann/json.hpp>
#include <QSurfaceFormat>
#include <QVTKOpenGLNativeWidget.h>
#include <vtkRenderWindow.h>
#include "ui/scene/scene_colors.h"

using tunnelmap::ui::CrossSectionPanel;

namespace {

std::shared_ptr<const tunnelmap::scene::ProcessedFrame> tunnel() {
  auto pf = std::make_shared<tunnelmap::scene::ProcessedFrame>(tunnelmap::test::make_synthetic_tunnel(1.0, 0.8, 3.0));
  pf->result.map.width_source = pf->result.map.height_source = tunnelmap::DimensionSource::Measured;
  return pf;
}

bool is_blue(QRgb c) { return qBlue(c) > 200 && qRed(c) < 60 && qGreen(c) < 110; }
bool is_white(QRgb c) { return qRed(c) > 200 && qGreen(c) > 200 && qBlue(c) > 200; }

// Pixels of `pred` on a short vertical run through `x` around the middle height.
int count_near(const QImage& img, int x, int y0, int y1, bool (*pred)(QRgb)) {
  int n = 0;
  for (int dx = -2; dx <= 2; ++dx)
    for (int y = y0; y <= y1; ++y)
      if (x + dx >= 0 && x + dx < img.width() && pred(img.pixel(x + dx, y))) ++n;
  return n;
}

}  // namespace

class CrossSectionTest : public QObject {
  Q_OBJECT

 private slots:
  void drawsTheFittedAndDesignRectanglesWithTheDeviation() {
    CrossSectionPanel panel;
    panel.resize(640, 560);
    panel.show();
    QVERIFY(QTest::qWaitForWindowExposed(&panel));
    panel.set_frame(tunnel(), 0.98, 0.78);
    const tunnelmap::CrossSection s = panel.view()->section();
    QVERIFY(s.fitted.has_value());
    QCOMPARE(std::round(s.fitted->width() * 1000), 1000.0);
    QCOMPARE(std::round(s.fitted->height() * 1000), 800.0);
    QVERIFY(s.points.size() > 100);
    const QString caption = panel.view()->caption();
    QVERIFY2(caption.startsWith("1.50 m ahead, slab"), qPrintable(caption));  // of the camera, not a map station
    QVERIFY2(caption.contains("cut: width 1.000 m, height 0.800 m"), qPrintable(caption));
    QVERIFY2(caption.contains("frame fit: 1.000 \u00d7 0.800 m"), qPrintable(caption));
    QVERIFY2(caption.contains("width 20.0 mm, height 20.0 mm"), qPrintable(caption));
    // A height filled from the design (roof and floor not seen: their planes are no walls) is
    // labelled so, never "0.0 mm" off.
    auto from_design = std::make_shared<tunnelmap::scene::ProcessedFrame>(*tunnel());
    from_design->result.map.status = tunnelmap::TunnelStatus::Partial;
    from_design->result.map.height_source = tunnelmap::DimensionSource::Design;
    for (auto& c : from_design->result.map.plane_classes)
      if (c == tunnelmap::WallClass::Top || c == tunnelmap::WallClass::Bottom) c = tunnelmap::WallClass::Unassigned;
    panel.set_frame(from_design, 0.98, 0.78);
    const QString design_caption = panel.view()->caption();
    QVERIFY2(design_caption.contains("width 20.0 mm, height from design"), qPrintable(design_caption));
    QVERIFY2(!design_caption.contains("height 0.0 mm"), qPrintable(design_caption));
    QVERIFY2(design_caption.contains("cut: width 1.000 m, height –"), qPrintable(design_caption));
    panel.set_frame(tunnel(), 0.98, 0.78);

    if (const char* dir = std::getenv("TUNNELMAP_GUI_SHOT_DIR"))
      panel.view()->grab().toImage().save(QString(dir) + "/cross_section.png");
    // The rectangles alone (the synthetic points lie exactly on the fitted one and hide it).
    tunnelmap::CrossSection bare = s;
    bare.points.clear();
    panel.view()->set_section(bare);
    const QImage img = panel.view()->grab().toImage();
    // The fitted left edge is blue, the design's left edge (10 mm inside) is drawn too.
    const QPointF left = panel.view()->to_widget({s.fitted->left, 0.0});
    const QPointF top = panel.view()->to_widget({0.0, s.fitted->top * 0.5});
    const int mid = static_cast<int>(left.y()), y0 = static_cast<int>(top.y());
    QVERIFY(count_near(img, static_cast<int>(left.x()), y0, mid, is_blue) > 20);
    const QPointF design_left = panel.view()->to_widget({s.design->left, 0.0});
    QVERIFY(count_near(img, static_cast<int>(design_left.x()), y0, mid, is_white) > 5);
    // Equal scale: the drawn rectangle is 1.0 : 0.8.
    const QPointF a = panel.view()->to_widget({s.fitted->left, s.fitted->bottom});
    const QPointF b = panel.view()->to_widget({s.fitted->right, s.fitted->top});
    QCOMPARE(std::round(100.0 * (b.x() - a.x()) / (a.y() - b.y())), 125.0);
  }

  void twoClicksMeasureTheDistanceBetweenTheSnappedPoints() {
    CrossSectionPanel panel;
    panel.resize(640, 560);
    panel.show();
    QVERIFY(QTest::qWaitForWindowExposed(&panel));
    panel.set_frame(tunnel(), std::nullopt, std::nullopt);
    auto* view = panel.view();
    QVERIFY(!view->section().design.has_value());
    QSignalSpy measured(view, &tunnelmap::ui::CrossSectionView::measured);
    // Click 4 px inside the left wall and 4 px inside the right one, at mid height: the picks
    // snap onto the walls' points, 1.0 m apart.
    const QPointF l = view->to_widget({-0.5, 0.0}) + QPointF(4, 0);
    const QPointF r = view->to_widget({0.5, 0.0}) - QPointF(4, 0);
    QTest::mouseClick(view, Qt::LeftButton, {}, l.toPoint());
    QCOMPARE(view->picks().size(), std::size_t{1});
    QVERIFY(!view->measured_m().has_value());
    QTest::mouseClick(view, Qt::LeftButton, {}, r.toPoint());
    QVERIFY(view->measured_m().has_value());
    QVERIFY2(std::abs(*view->measured_m() - 1.0) < 0.03, qPrintable(QString::number(*view->measured_m())));
    QCOMPARE(measured.count(), 1);
    // A third click starts a new measurement.
    QTest::mouseClick(view, Qt::LeftButton, {}, l.toPoint());
    QCOMPARE(view->picks().size(), std::size_t{1});
  }

  void theSliderWalksTheVisibleStations() {
    CrossSectionPanel panel;
    panel.show();
    panel.set_frame(tunnel(), std::nullopt, std::nullopt);
    auto* slider = panel.findChild<QSlider*>();
    QVERIFY(slider && slider->isEnabled());
    QSignalSpy changed(&panel, &CrossSectionPanel::stationChanged);
    slider->setValue(slider->minimum());
    const double near = panel.station();
    slider->setValue(slider->maximum());
    const double far = panel.station();
    QVERIFY2(far - near > 1.0, qPrintable(QString("%1 .. %2").arg(near).arg(far)));
    QVERIFY(changed.count() >= 2);
    QCOMPARE(panel.view()->section().station_m, far);
    // No tunnel: the slider is off and the view shows no rectangle.
    auto none = std::make_shared<tunnelmap::scene::ProcessedFrame>(*tunnel());
    none->result.map.detected = false;
    panel.set_frame(none, std::nullopt, std::nullopt);
    QVERIFY(!slider->isEnabled());
    QVERIFY(!panel.view()->section().fitted.has_value());
  }

  // A frame whose walls end 1.0 m ahead cuts there; the next frame cuts at the distance asked
  // for again, not where the short one left it.
  void aFrameWhoseWallsEndShortDoesNotMoveTheCutOfTheNext() {
    auto short_view = std::make_shared<tunnelmap::scene::ProcessedFrame>(*tunnel());
    tunnelmap::TunnelMap& m = short_view->result.map;
    const double base = m.axis_point.dot(m.axis_dir), max = m.extent_max_m;
    m.extent_max_m = 1.0 - base;
    if (std::abs(tunnelmap::visible_stations(m).to_m - 1.0) > 1e-9) m.extent_max_m = max, m.extent_min_m = -1.0 - base;
    QVERIFY(std::abs(tunnelmap::visible_stations(m).to_m - 1.0) < 1e-9);
    CrossSectionPanel panel;
    panel.show();
    for (const double wanted : {CrossSectionPanel::kDefaultAheadM, 2.0}) {
      panel.set_frame(tunnel(), std::nullopt, std::nullopt);
      panel.set_station(wanted);
      panel.set_frame(short_view, std::nullopt, std::nullopt);
      QCOMPARE(panel.station(), 1.0);
      panel.set_frame(tunnel(), std::nullopt, std::nullopt);
      QCOMPARE(panel.station(), wanted);
      QCOMPARE(panel.view()->section().station_m, wanted);
    }
  }
};

// 20 stations of 0.1 m, two sections; design 0.82 x 1.30 m, 10 mm tolerance; the width reads
// 0.84 m (20 mm over) at stations 1.05 to 1.25.
tunnelmap::StationMap profile_map() {
  tunnelmap::StationMap m;
  m.ok = true;
  m.options.station_step_m = 0.1;
  m.options.tolerance_mm = 10.0;
  m.options.design_width_m = 0.82;
  m.options.design_height_m = 1.30;
  for (int i = 0; i < 20; ++i) {
    tunnelmap::Station s;
    s.station_m = 0.05 + 0.1 * i;
    s.width_m = i >= 10 && i <= 12 ? 0.84 : 0.8205;
    s.height_m = 1.301;
    s.width_source = s.height_source = tunnelmap::DimensionSource::Measured;
    if (i == 0) s.height_source = tunnelmap::DimensionSource::Context;
    s.width_dev_mm = (s.width_m - 0.82) * 1000.0;
    s.height_dev_mm = (s.height_m - 1.30) * 1000.0;
    s.out_of_tolerance = std::abs(*s.width_dev_mm) > 10.0;
    m.stations.push_back(s);
  }
  m.sections = {{0.0, 1.0, 0.8205, 1.301, 5}, {1.0, 2.0, 0.8205, 1.301, 5}};
  return m;
}

class ProfilePlotTest : public QObject {
  Q_OBJECT

 private slots:
  void stationsBeyondToleranceAreRedAndAClickSelectsTheNearest() {
    tunnelmap::ui::ProfilePlot plot;
    plot.resize(800, 360);
    plot.show();
    QVERIFY(QTest::qWaitForWindowExposed(&plot));
    plot.set_map(profile_map());
    const QImage img = plot.grab().toImage();
    if (const char* dir = std::getenv("TUNNELMAP_GUI_SHOT_DIR")) img.save(QString(dir) + "/profile.png");
    // Red dots at 1.05-1.25 m in the width plot, none elsewhere; the height plot has none.
    auto red_in = [&](int series, double from, double to) {
      const QRectF a = plot.area(series);
      int n = 0;
      for (int y = static_cast<int>(a.top()); y < a.bottom(); ++y)
        for (int x = static_cast<int>(plot.x_of(from)); x <= plot.x_of(to); ++x) {
          const QRgb c = img.pixel(x, y);
          n += qRed(c) > 200 && qGreen(c) < 110 && qBlue(c) < 110;
        }
      return n;
    };
    QVERIFY(red_in(0, 1.0, 1.3) > 30);
    QCOMPARE(red_in(0, 0.0, 0.95), 0);
    QCOMPARE(red_in(1, 0.0, 2.0), 0);

    QSignalSpy clicked(&plot, &tunnelmap::ui::ProfilePlot::stationClicked);
    const QPoint at(static_cast<int>(plot.x_of(1.15) + 2), static_cast<int>(plot.area(1).center().y()));
    QTest::mouseClick(&plot, Qt::LeftButton, {}, at);
    QCOMPARE(clicked.count(), 1);
    QVERIFY(std::abs(clicked.at(0).at(0).toDouble() - 1.15) < 1e-9);
    QVERIFY(plot.current_station().has_value());
    // The marker is drawn at the current station.
    const QImage marked = plot.grab().toImage();
    const QRgb m = marked.pixel(static_cast<int>(std::lround(plot.x_of(1.15))), static_cast<int>(plot.area(0).top()) + 3);
    QVERIFY2(qRed(m) > 200 && qGreen(m) > 150 && qBlue(m) < 120, qPrintable(QColor(m).name()));
  }

  void withoutAMapItSaysHowToGetOne() {
    tunnelmap::ui::ProfilePlot plot;
    QVERIFY(!plot.station_at(100).has_value());
    plot.resize(400, 240);
    const QImage img = plot.grab().toImage();
    QVERIFY(img.width() == 400);
  }
};

// The sections dock's list of stretches to rescan: the profile map with its roof out of view
// over 0.8-1.4 m, where a joint was placed between views.
class MapSectionsPanelTest : public QObject {
  Q_OBJECT

  // A shown panel listing `m`, or null when the window never showed.
  static std::unique_ptr<tunnelmap::ui::MapSectionsPanel> shown_panel(const tunnelmap::StationMap& m) {
    auto panel = std::make_unique<tunnelmap::ui::MapSectionsPanel>();
    panel->resize(700, 500);
    panel->show();
    if (!QTest::qWaitForWindowExposed(panel.get())) return nullptr;
    panel->set_map(m);
    return panel;
  }

  // The panel's group whose title starts with `title`, or null.
  static QTreeWidgetItem* top_group(const tunnelmap::ui::MapSectionsPanel& panel, const char* title) {
    for (int i = 0; i < panel.tree()->topLevelItemCount(); ++i)
      if (panel.tree()->topLevelItem(i)->text(0).startsWith(title)) return panel.tree()->topLevelItem(i);
    return nullptr;
  }

 private slots:
  void listsTheStretchesToRescanAndAClickShowsTheirMiddle() {
    tunnelmap::StationMap m = profile_map();
    for (int i = 8; i <= 13; ++i) m.stations[i].height_source = tunnelmap::DimensionSource::Context;
    m.sections[1].joint_seen = false;
    m.sections[1].joint_uncertainty_m = 0.3;
    tunnelmap::ui::MapSectionsPanel panel;
    panel.resize(700, 500);
    panel.show();
    QVERIFY(QTest::qWaitForWindowExposed(&panel));
    panel.set_map(m);
    // The lone context station at 0.05 m is shorter than a section: not listed.
    QCOMPARE(panel.rescan_rows(), 1);
    QTreeWidgetItem* group = panel.tree()->topLevelItem(2);
    QCOMPARE(group->text(0), QStringLiteral("To rescan (1)"));
    QTreeWidgetItem* stretch = group->child(0);
    QCOMPARE(stretch->text(0), QStringLiteral("0.80 – 1.40"));
    QCOMPARE(stretch->text(1), QString());
    QCOMPARE(stretch->text(2), QStringLiteral("not measured"));
    QCOMPARE(stretch->text(3), QStringLiteral("joint inside"));
    QVERIFY(stretch->toolTip(0).contains("a joint lies somewhere in this stretch"));
    QSignalSpy chosen(&panel, &tunnelmap::ui::MapSectionsPanel::stationChosen);
    panel.tree()->scrollToItem(stretch);
    QTest::qWait(50);
    QTest::mouseClick(panel.tree()->viewport(), Qt::LeftButton, {},
                      panel.tree()->visualItemRect(stretch).topLeft() + QPoint(30, 5));
    QCOMPARE(chosen.count(), 1);
    QVERIFY(std::abs(chosen.at(0).at(0).toDouble() - 1.1) < 1e-9);
    if (const char* dir = std::getenv("TUNNELMAP_GUI_SHOT_DIR")) panel.grab().save(QString(dir) + "/rescan_list.png");
  }

  void namesEachPlateAsTheMapJsonDoes() {
    tunnelmap::StationMap m = profile_map();
    tunnelmap::Diaphragm open, closed, end;
    open.station_m = 0.6;
    tunnelmap::Manhole hole;
    hole.width_m = 0.45, hole.height_m = 0.70;
    open.manhole = hole;
    closed.station_m = 1.2, closed.closed = true;
    end.station_m = 1.9, end.closed = true, end.kind = "end_wall";
    m.girder.diaphragms = {open, closed, end};
    const auto panel = shown_panel(m);
    QVERIFY(panel);
    QTreeWidgetItem* plates = top_group(*panel, "Diaphragms");
    QVERIFY(plates);
    QCOMPARE(plates->childCount(), 3);
    // The manhole's width and height stand in the width and height columns, its shape beside.
    QCOMPARE(plates->child(0)->text(1), QStringLiteral("0.450"));
    QCOMPARE(plates->child(0)->text(2), QStringLiteral("0.700"));
    QCOMPARE(plates->child(1)->text(1), QStringLiteral("–"));
    QCOMPARE(plates->child(1)->text(3), QStringLiteral("closed: no opening"));
    QCOMPARE(plates->child(2)->text(3), QStringLiteral("end wall"));
    QVERIFY(plates->child(0)->toolTip(0).contains("clearance to the left wall not measured"));
    plates->setExpanded(true);
    if (const char* dir = std::getenv("TUNNELMAP_GUI_SHOT_DIR")) panel->grab().save(QString(dir) + "/plates_list.png");
  }

  void withoutADesignNothingIsCountedOutOfTolerance() {
    tunnelmap::StationMap m = profile_map();
    m.options.design_width_m.reset();
    m.options.design_height_m.reset();
    const auto panel = shown_panel(m);
    QVERIFY(panel);
    QTreeWidgetItem* group = top_group(*panel, "Out of tolerance");
    QVERIFY(group);
    QCOMPARE(group->text(0), QStringLiteral("Out of tolerance: not checked, no design cross-section given"));
    QCOMPARE(group->childCount(), 0);
    QCOMPARE(panel->out_of_tolerance_rows(), 0);
  }

  void listsTheCompartmentsAndKeepsAClickedPlateSelected() {
    tunnelmap::StationMap m = profile_map();
    tunnelmap::Diaphragm plate;
    plate.station_m = 1.0;
    m.girder.diaphragms = {plate};
    tunnelmap::Compartment before, after;
    before.from_m = 0.0, before.to_m = 1.0, before.closed_to = true;
    before.width_m = 0.851, before.height_m = 1.302, before.stations_measured = 6;
    after.from_m = 1.0, after.to_m = 1.2, after.closed_from = true;
    after.width_m = after.height_m = NAN;  // nothing measured in it
    m.girder.compartments = {before, after};
    const auto panel = shown_panel(m);
    QVERIFY(panel);
    QTreeWidgetItem* parts = top_group(*panel, "Compartments");
    QTreeWidgetItem* plates = top_group(*panel, "Diaphragms");
    QVERIFY(parts && plates);
    QCOMPARE(parts->text(0), QStringLiteral("Compartments (2)"));
    QCOMPARE(parts->child(0)->text(0), QStringLiteral("0.00 – 1.00"));
    QCOMPARE(parts->child(0)->text(1), QStringLiteral("0.851"));
    QCOMPARE(parts->child(0)->text(2), QStringLiteral("1.302"));
    QCOMPARE(parts->child(1)->text(1), QStringLiteral("–"));  // unknown, never 0
    QCOMPARE(parts->child(1)->text(2), QStringLiteral("–"));
    // The window answers a click by selecting the station; the plate's row stays selected.
    QTreeWidgetItem* row = plates->child(0);
    panel->tree()->scrollToItem(row);
    QTest::qWait(50);
    QObject::connect(panel.get(), &tunnelmap::ui::MapSectionsPanel::stationChosen, panel.get(),
                     [&](double s) { panel->select_station(s); });
    QTest::mouseClick(panel->tree()->viewport(), Qt::LeftButton, {},
                      panel->tree()->visualItemRect(row).topLeft() + QPoint(30, 5));
    QCOMPARE(panel->tree()->currentItem(), row);
  }
};

class View3DMeasureTest : public QObject {
  Q_OBJECT

 private slots:
  void twoClicksInTheMeasureModeMeasureTheTunnelWidth() {
    tunnelmap::ui::View3DWidget view;
    view.resize(640, 400);
    view.show();
    QVERIFY(QTest::qWaitForWindowExposed(&view));
    const auto pf = tunnel();
    view.show_frame(*pf, true);
    view.set_layer_visible(tunnelmap::scene::Layer::Planes, false);
    // Widget pixels of a left-wall and a right-wall cloud point 1.5 m ahead.
    auto pixel_of = [&](const Eigen::Vector3d& target) {
      Eigen::Vector3d best(1e9, 1e9, 1e9);
      for (const auto& p : pf->result.cloud.points)
        if (tunnelmap::OrganizedCloud::valid(p) && (p.cast<double>() - target).norm() < (best - target).norm())
          best = p.cast<double>();
      auto* r = view.scene().renderer();
      r->SetWorldPoint(best.x(), best.y(), best.z(), 1.0);
      r->WorldToDisplay();
      const double* d = r->GetDisplayPoint();
      const double ratio = view.devicePixelRatioF();
      return QPoint(static_cast<int>(std::lround(d[0] / ratio)),
                    static_cast<int>(std::lround((view.renderWindow()->GetSize()[1] - 1 - d[1]) / ratio)));
    };
    const QPoint left = pixel_of({-0.5, 0.0, 1.5}), right = pixel_of({0.5, 0.0, 1.5});
    QSignalSpy changed(&view, &tunnelmap::ui::View3DWidget::measurementChanged);
    // Not measuring: a click rotates the camera, picks nothing.
    QTest::mouseClick(&view, Qt::LeftButton, {}, left);
    QVERIFY(view.scene().measurement().picks.empty());
    view.show_frame(*pf, true);
    view.set_measuring(true);
    QTest::mouseClick(&view, Qt::LeftButton, {}, left);
    QTest::mouseClick(&view, Qt::LeftButton, {}, right);
    const auto d = view.scene().measurement().distance_m();
    QVERIFY(d.has_value());
    QVERIFY2(std::abs(*d - 1.0) < 0.02, qPrintable(QString::number(*d)));
    QCOMPARE(changed.count(), 2);
    QVERIFY(changed.last().at(0).toString().endsWith(" mm"));
    // A second distance: the first stays drawn beside it.
    QTest::mouseClick(&view, Qt::LeftButton, {}, pixel_of({-0.5, 0.25, 1.2}));
    QTest::mouseClick(&view, Qt::LeftButton, {}, pixel_of({0.5, 0.25, 1.2}));
    QCOMPARE(int(view.scene().measurements().size()), 2);
    QVERIFY(std::abs(*view.scene().measurements().front().distance_m() - *d) < 1e-12);
    QVERIFY(view.scene().measurement().distance_m().has_value());
    QCOMPARE(changed.count(), 4);
    const QImage shot = view.grabFramebuffer();
    if (const char* dir = std::getenv("TUNNELMAP_GUI_SHOT_DIR")) shot.save(QString(dir) + "/measure3d.png");
    view.clear_measurement();
    QVERIFY(view.scene().measurement().picks.empty());
    QCOMPARE(changed.last().at(0).toString(), QString());
  }
};

class DepthViewMeasureTest : public QObject {
  Q_OBJECT

 private slots:
  void clicksOnTheDepthImageMeasureInSpaceAndKeepEarlierMeasurements() {
    tunnelmap::ui::DepthViewWidget view;
    view.resize(640, 480);
    view.show();
    QVERIFY(QTest::qWaitForWindowExposed(&view));
    const auto pf = tunnel();
    view.show_frame(pf);
    // The pixels of a left-wall and a right-wall point 1.5 m ahead.
    auto pixel_of = [&](const Eigen::Vector3d& target) {
      const auto& c = pf->result.cloud;
      std::size_t best = 0;
      double best_d = 1e9;
      for (std::size_t i = 0; i < c.points.size(); ++i)
        if (tunnelmap::OrganizedCloud::valid(c.points[i]) && (c.points[i].cast<double>() - target).norm() < best_d)
          best_d = (c.points[i].cast<double>() - target).norm(), best = i;
      return QPoint(static_cast<int>(best % c.width), static_cast<int>(best / c.width));
    };
    const QPoint l = pixel_of({-0.5, 0.0, 1.5}), r = pixel_of({0.5, 0.0, 1.5});
    QSignalSpy changed(&view, &tunnelmap::ui::DepthViewWidget::measurementChanged);
    QTest::mouseClick(&view, Qt::LeftButton, {}, view.widget_point(l.x(), l.y()));
    QVERIFY(view.measurement().picks.empty());  // not measuring: a click picks nothing
    view.set_measuring(true);
    QTest::mouseClick(&view, Qt::LeftButton, {}, view.widget_point(l.x(), l.y()));
    QTest::mouseClick(&view, Qt::LeftButton, {}, view.widget_point(r.x(), r.y()));
    const auto d = view.measurement().distance_m();
    QVERIFY(d.has_value());
    QVERIFY2(std::abs(*d - 1.0) < 0.02, qPrintable(QString::number(*d)));
    QCOMPARE(changed.count(), 2);
    // The segment is drawn over the image in white.
    const QImage img = view.grab().toImage();
    const QPoint mid = (view.widget_point(l.x(), l.y()) + view.widget_point(r.x(), r.y())) / 2;
    const QRgb c = img.pixel(mid);
    QVERIFY2(qRed(c) > 240 && qGreen(c) > 240 && qBlue(c) > 240, qPrintable(QColor(c).name()));
    // Two more picks, 1 m apart along the left wall: a second measurement, the first one kept.
    const QPoint near = pixel_of({-0.5, 0.0, 1.2}), far = pixel_of({-0.5, 0.0, 2.2});
    QTest::mouseClick(&view, Qt::LeftButton, {}, view.widget_point(near.x(), near.y()));
    QCOMPARE(int(view.measurements().size()), 2);
    QVERIFY(!view.measurement().distance_m());
    QTest::mouseClick(&view, Qt::LeftButton, {}, view.widget_point(far.x(), far.y()));
    QCOMPARE(changed.count(), 4);
    QVERIFY(std::abs(*view.measurements().front().distance_m() - *d) < 1e-12);
    const auto along = view.measurement().distance_m();
    QVERIFY(along.has_value());
    QVERIFY2(std::abs(*along - 1.0) < 0.03, qPrintable(QString::number(*along)));
    // Both segments are drawn.
    const QImage both = view.grab().toImage();
    const QPoint mid2 = (view.widget_point(near.x(), near.y()) + view.widget_point(far.x(), far.y())) / 2;
    for (const QPoint& m : {mid, mid2}) {
      const QRgb px = both.pixel(m);
      QVERIFY2(qRed(px) > 240 && qGreen(px) > 240 && qBlue(px) > 240, qPrintable(QColor(px).name()));
    }
    view.clear_measurement();
    QVERIFY(view.measurement().picks.empty());
    QVERIFY(view.measurements().empty());
    const QRgb cleared = view.grab().toImage().pixel(mid2);
    QVERIFY2(qRed(cleared) < 240 || qGreen(cleared) < 240 || qBlue(cleared) < 240, qPrintable(QColor(cleared).name()));
  }
};

// The main window's review docks on a simulated posed walk: Processing > Map tunnel fills the
// profile; clicking a station shows the frame that sees it best and cuts the cross-section
// there, where the fitted width is the map's width at that station.
class MapReviewTest : public QObject {
  Q_OBJECT

 private:
  QTemporaryDir dir_;
  QString walk_;

 private slots:
  void initTestCase() {
    QStandardPaths::setTestModeEnabled(true);
    QSettings().clear();
    QVERIFY(dir_.isValid());
    walk_ = dir_.filePath("walk");
    QProcess sim;
    sim.start(TUNNELMAP_CLI_PATH, {"simulate", "--preset", "lab", "--frames", "16", "--seed", "4", "--quiet",
                                   "--sections", "2:0.84x1.30,2:0.80x1.28", "--walk", "-1,2.5,8", walk_});
    QVERIFY(sim.waitForFinished(120000));
    QCOMPARE(sim.exitCode(), 0);
  }

  void clickingAStationShowsItsFrameAndCutsThere() {
    tunnelmap::ui::MainWindow w;
    w.suppress_dialogs = true;
    w.resize(1600, 1000);
    w.show();
    QVERIFY(QTest::qWaitForWindowExposed(&w));
    QSignalSpy shown(&w, &tunnelmap::ui::MainWindow::frameShown);
    QVERIFY(w.open_input(walk_));
    QVERIFY(shown.wait(30000));
    // The cross-section follows the shown frame from the start.
    QVERIFY(w.cross_section()->view()->section().fitted.has_value());

    QSignalSpy mapped(&w, &tunnelmap::ui::MainWindow::tunnelMapped);
    w.map_tunnel();
    QVERIFY(mapped.wait(120000));
    QCOMPARE(mapped.at(0).at(0).toBool(), true);
    const tunnelmap::StationMap& m = w.profile()->map();
    QVERIFY(m.stations.size() > 20);
    QCOMPARE(m.sections.size(), std::size_t{2});

    // A measured station of the first section, then one well inside the second: the frame
    // shown for a station just past the joint is one from before it, whose own walls (the cut's
    // fitted box) are those of the first section.
    for (double want : {1.0, 4.2}) {
      const tunnelmap::Station* st = nullptr;
      for (const auto& s : m.stations)
        if (s.width_source == tunnelmap::DimensionSource::Measured && (!st || std::abs(s.station_m - want) < std::abs(st->station_m - want)))
          st = &s;
      QVERIFY(st);
      const int before = w.frame_index();
      QVERIFY(w.show_station(st->station_m));
      if (w.frame_index() != before) QVERIFY(shown.wait(30000));
      QVERIFY(w.profile()->current_station().has_value());
      const auto& cut = w.cross_section()->view()->section();
      QVERIFY(cut.fitted.has_value());
      QVERIFY2(std::abs(cut.fitted->width() - st->width_m) < 0.01,
               qPrintable(QString("station %1: cut %2 vs map %3").arg(st->station_m).arg(cut.fitted->width()).arg(st->width_m)));
      QVERIFY(cut.station_m > 0.4 && cut.station_m < 4.6);
      QVERIFY(cut.cut_width_m.has_value());  // the caption's width: the cut's own walls
      QVERIFY2(std::abs(*cut.cut_width_m - st->width_m) < 0.01,
               qPrintable(QString("station %1: cut walls %2 vs map %3").arg(st->station_m).arg(*cut.cut_width_m).arg(st->width_m)));
    }
    // The sections dock lists both sections; a click on the second shows its middle, and the
    // profile's station selects the row it lies in.
    auto* sections = w.map_sections();
    QCOMPARE(sections->section_rows(), 2);
    // The stretches to rescan are those the command line lists.
    QCOMPARE(sections->rescan_rows(), static_cast<int>(tunnelmap::rescan_stretches(m).size()));
    QTreeWidgetItem* second = sections->tree()->topLevelItem(0)->child(1);
    sections->tree()->scrollToItem(second);
    QTest::qWait(100);  // the dock shown after the map is laid out
    QVERIFY(sections->isVisible());
    const QPoint on_second = sections->tree()->visualItemRect(second).topLeft() + QPoint(30, 5);
    QVERIFY2(sections->tree()->viewport()->rect().contains(on_second),
             qPrintable(QString("row at %1,%2 in a %3x%4 list").arg(on_second.x()).arg(on_second.y())
                            .arg(sections->tree()->viewport()->width()).arg(sections->tree()->viewport()->height())));
    const int before = w.frame_index();
    QTest::mouseClick(sections->tree()->viewport(), Qt::LeftButton, {}, on_second);
    QVERIFY(w.profile()->current_station().has_value());
    QVERIFY2(std::abs(*w.profile()->current_station() - 0.5 * (m.sections[1].from_m + m.sections[1].to_m)) < 1e-6,
             qPrintable(QString::number(*w.profile()->current_station())));
    if (w.frame_index() != before) QVERIFY(shown.wait(30000));
    QVERIFY(w.show_station(m.sections[0].from_m + 0.3));
    QCOMPARE(sections->tree()->currentItem(), sections->tree()->topLevelItem(0)->child(0));
    // A station past the map's end is refused with the map's extent, and the selection stays.
    QString why;
    const tunnelmap::MapExtent runs = tunnelmap::map_extent(m);
    QVERIFY(!w.show_station(runs.to_m + 5.0, &why));
    const QString extent = QString("from %1 to %2 m").arg(runs.from_m, 0, 'f', 2).arg(runs.to_m, 0, 'f', 2);
    QVERIFY2(why.contains("outside the map") && why.contains(extent), qPrintable(why));
    QVERIFY2(w.status_text().contains(extent), qPrintable(w.status_text()));
    QCOMPARE(sections->tree()->currentItem(), sections->tree()->topLevelItem(0)->child(0));
    if (const char* dir = std::getenv("TUNNELMAP_GUI_SHOT_DIR")) w.grab().save(QString(dir) + "/review_window.png");
  }

  // File > Export station CSV, diaphragms CSV, map PLY and inspection report after Map tunnel
  // write what `tunnelmap-cli map` writes for the same dataset and parameters; before it, the
  // map exports say how to get a map.
  void theMapsExportsAreTheCommandLinesFiles() {
    tunnelmap::ui::MainWindow w;
    w.suppress_dialogs = true;
    QSignalSpy shown(&w, &tunnelmap::ui::MainWindow::frameShown);
    QVERIFY(w.open_input(walk_));
    QVERIFY(shown.wait(30000));
    QString target;
    w.choose_save_path = [&](const QString&, const QString&, const QString&) { return target; };
    const auto export_to = [&](const char* action, const QString& name) {
      target = dir_.filePath(name);
      w.findChild<QAction*>(action)->trigger();
      return target;
    };
    QVERIFY(!w.export_station_csv(dir_.filePath("early.csv")));
    QVERIFY2(w.last_error().contains("Map tunnel"), qPrintable(w.last_error()));
    QVERIFY(!QFile::exists(dir_.filePath("early.csv")));

    // The test binary has no renderer beside it; the GUI finds app/render/tunnelmap-render.
    qputenv("TUNNELMAP_RENDER", TUNNELMAP_RENDER_PATH);
    QSignalSpy mapped(&w, &tunnelmap::ui::MainWindow::tunnelMapped);
    w.map_tunnel();
    QVERIFY(mapped.wait(120000));
    QSignalSpy errors(&w, &tunnelmap::ui::MainWindow::errorShown);
    const QString csv = export_to("exportStationCsv", "gui_stations.csv");
    const QString diaphragms = export_to("exportDiaphragmsCsv", "gui_diaphragms.csv");
    const QString ply = export_to("exportMapPly", "gui_map.ply");
    const QString pdf = export_to("exportReport", "gui_report.pdf");
    QVERIFY2(errors.isEmpty(), qPrintable(w.last_error()));
    QVERIFY2(w.status_text().startsWith("Wrote"), qPrintable(w.status_text()));

    QProcess cli;
    cli.start(TUNNELMAP_CLI_PATH, {"map", walk_, "--quiet", "--csv", dir_.filePath("cli_stations.csv"), "--diaphragms-csv",
                                   dir_.filePath("cli_diaphragms.csv"), "--ply", dir_.filePath("cli_map.ply"), "--report",
                                   dir_.filePath("cli_report.pdf")});
    QVERIFY(cli.waitForFinished(120000));
    QCOMPARE(cli.exitCode(), 0);
    const auto bytes = [](const QString& path) {
      QFile f(path);
      return f.open(QIODevice::ReadOnly) ? f.readAll() : QByteArray();
    };
    QVERIFY(bytes(csv).count('\n') > 20);
    QCOMPARE(bytes(csv), bytes(dir_.filePath("cli_stations.csv")));
    QCOMPARE(bytes(diaphragms), bytes(dir_.filePath("cli_diaphragms.csv")));
    QVERIFY(bytes(ply).startsWith("ply"));
    QCOMPARE(bytes(ply), bytes(dir_.filePath("cli_map.ply")));
    // The reports differ only in the time they were written.
    const auto report_text = [](const QString& path) {
      QProcess text;
      text.start("pdftotext", {"-layout", path, "-"});
      text.waitForFinished(60000);
      QStringList lines = QString::fromUtf8(text.readAllStandardOutput()).split('\n');
      lines.erase(std::remove_if(lines.begin(), lines.end(),
                                 [](const QString& l) { return l.contains(QRegularExpression("\\d{4}-\\d\\d-\\d\\d \\d\\d:")); }),
                  lines.end());
      return lines;
    };
    if (const char* shots = std::getenv("TUNNELMAP_GUI_SHOT_DIR")) QFile::copy(pdf, QString(shots) + "/gui_report.pdf");
    const QStringList gui_text = report_text(pdf), cli_text = report_text(dir_.filePath("cli_report.pdf"));
    QVERIFY(gui_text.size() > 30);
    for (const QString& l : gui_text)
      if (!cli_text.contains(l)) qInfo("only in the GUI's report: %s", qPrintable(l));
    for (const QString& l : cli_text)
      if (!gui_text.contains(l)) qInfo("only in the CLI's report: %s", qPrintable(l));
    QCOMPARE(gui_text, cli_text);
  }

  // The command line: --map --station S waits for the map and the station's frame, then grabs.
  void commandLineMapStationScreenshot() {
    const QString shot = dir_.filePath("review.png");
    QProcess gui;
    QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
    env.insert("XDG_CONFIG_HOME", dir_.filePath("config"));
    gui.setProcessEnvironment(env);
    gui.start(TUNNELMAP_GUI_PATH, {walk_, "--map", "--station", "3.0", "--size", "1400x880", "--screenshot", shot, "--exit"});
    QVERIFY(gui.waitForFinished(120000));
    QCOMPARE(gui.exitCode(), 0);
    QCOMPARE(QImage(shot).size(), QSize(1400, 880));
    // A plain frame has no poses to map: exit 3, one line naming it.
    QProcess bad;
    bad.setProcessEnvironment(env);
    bad.start(TUNNELMAP_GUI_PATH, {QString(TUNNELMAP_SOURCE_DIR) + "/resources/sample/lab/depth/000000.png", "--map",
                                   "--screenshot", dir_.filePath("no.png"), "--exit"});
    QVERIFY(bad.waitForFinished(60000));
    QCOMPARE(bad.exitCode(), 3);
    const QString err = QString::fromUtf8(bad.readAllStandardError());
    QVERIFY2(err.contains("000000.png") && err.contains("needs a posed dataset"), qPrintable(err));
    QVERIFY(!QFile::exists(dir_.filePath("no.png")));
  }

  // A stop reported 10 m from where it stood is mapped where its pose puts it; the Sections panel
  // says so in the words `map` prints and writes to its JSON's "notes".
  void aPoseNothingChecksIsNotedInTheSectionsPanelAsTheCommandLineNotesIt() {
    const QString moved = dir_.filePath("moved");
    QVERIFY(QDir().mkpath(moved));
    for (const QFileInfo& entry : QDir(walk_).entryInfoList(QDir::Dirs | QDir::NoDotAndDotDot)) {
      QVERIFY(QDir().mkpath(moved + "/" + entry.fileName()));
      for (const QString& file : QDir(entry.filePath()).entryList(QDir::Files))
        QVERIFY(QFile::copy(entry.filePath() + "/" + file, moved + "/" + entry.fileName() + "/" + file));
    }
    QFile in(walk_ + "/dataset.json");
    QVERIFY(in.open(QIODevice::ReadOnly));
    nlohmann::json d = nlohmann::json::parse(in.readAll().toStdString());
    for (nlohmann::json& f : d["frames"])
      if (f["pose_group"] == 3) f["pose"][3] = f["pose"][3].get<double>() + 10.0;
    QFile out(moved + "/dataset.json");
    QVERIFY(out.open(QIODevice::WriteOnly));
    out.write(QByteArray::fromStdString(d.dump()));
    out.close();

    tunnelmap::ui::MainWindow w;
    w.suppress_dialogs = true;
    w.resize(1400, 900);
    w.show();
    QVERIFY(QTest::qWaitForWindowExposed(&w));
    QSignalSpy shown(&w, &tunnelmap::ui::MainWindow::frameShown);
    QVERIFY(w.open_input(moved));
    QVERIFY(shown.wait(30000));
    QSignalSpy mapped(&w, &tunnelmap::ui::MainWindow::tunnelMapped);
    w.map_tunnel();
    QVERIFY(mapped.wait(120000));
    QCOMPARE(mapped.at(0).at(0).toBool(), true);
    QVERIFY2(w.status_text().endsWith("; 1 note(s) in Sections"), qPrintable(w.status_text()));

    QProcess cli;
    cli.start(TUNNELMAP_CLI_PATH, {"map", moved, "--quiet", "--json", dir_.filePath("moved.json")});
    QVERIFY(cli.waitForFinished(120000));
    QCOMPARE(cli.exitCode(), 0);
    QFile json(dir_.filePath("moved.json"));
    QVERIFY(json.open(QIODevice::ReadOnly));
    const nlohmann::json notes = nlohmann::json::parse(json.readAll().toStdString())["notes"];
    QCOMPARE(notes.size(), std::size_t{1});
    QVERIFY(notes[0].get<std::string>().rfind("pose 3 (frames 6-7): nothing it saw", 0) == 0);

    auto* panel = w.map_sections();
    QCOMPARE(panel->note_rows(), 1);
    QTreeWidgetItem* group = panel->tree()->topLevelItem(0);
    QVERIFY2(group->text(0).startsWith("Notes (1)"), qPrintable(group->text(0)));
    QCOMPARE(group->child(0)->text(0), QString::fromStdString(notes[0].get<std::string>()));
    QVERIFY(panel->isVisible());  // raised over the profile: the map cannot show what the note says
    if (const char* dir = std::getenv("TUNNELMAP_GUI_SHOT_DIR")) w.grab().save(QString(dir) + "/notes_window.png");

    // The walk as simulated has nothing to note.
    QVERIFY(w.open_input(walk_));
    QVERIFY(shown.wait(30000));
    w.map_tunnel();
    QVERIFY(mapped.wait(120000));
    QCOMPARE(mapped.at(1).at(0).toBool(), true);
    QCOMPARE(panel->note_rows(), 0);
    QVERIFY(!panel->tree()->topLevelItem(0)->text(0).startsWith("Notes"));
  }

  // Map tunnel shows its progress and says how many frames it used; Cancel keeps the previous
  // map. A new input forgets the map, the cut and the design typed for the previous one (one
  // undo step brings the design back).
  void mapTunnelProgressCancelAndANewInputForgetsTheMap() {
    tunnelmap::ui::MainWindow w;
    w.suppress_dialogs = true;
    w.show();
    QVERIFY(QTest::qWaitForWindowExposed(&w));
    QSignalSpy shown(&w, &tunnelmap::ui::MainWindow::frameShown);
    QVERIFY(w.open_input(walk_));
    QVERIFY(shown.wait(30000));
    tunnelmap::Parameters design = w.parameter_panel()->parameters();
    design.set(tunnelmap::tunnel_keys::design_width_m, 0.84);
    design.set(tunnelmap::tunnel_keys::design_height_m, 1.30);
    w.parameter_panel()->set_parameters(design, "design");

    QSignalSpy mapped(&w, &tunnelmap::ui::MainWindow::tunnelMapped);
    w.map_tunnel();
    auto* progress = w.findChild<QProgressBar*>();
    QVERIFY(progress && progress->isVisible());
    QCOMPARE(progress->maximum(), 17);  // 16 frames and the map
    QVERIFY(mapped.wait(120000));
    QCOMPARE(mapped.at(0).at(0).toBool(), true);
    QVERIFY(!progress->isVisible());
    QVERIFY2(w.status_text().contains(QRegularExpression("from \\d+ of 16 frame")), qPrintable(w.status_text()));
    const std::size_t stations = w.profile()->map().stations.size();

    w.map_tunnel();
    w.cancel_sequence();
    QVERIFY(mapped.wait(120000));
    QCOMPARE(mapped.at(1).at(0).toBool(), false);
    QVERIFY2(w.status_text().contains("cancelled"), qPrintable(w.status_text()));
    QCOMPARE(w.profile()->map().stations.size(), stations);
    QVERIFY(w.export_station_csv(dir_.filePath("kept.csv")));

    QVERIFY(w.open_input(QString(TUNNELMAP_SOURCE_DIR) + "/resources/sample/lab/depth/000000.png"));
    QVERIFY(shown.wait(30000));
    QVERIFY(w.profile()->map().stations.empty());
    QVERIFY(!w.export_station_csv(dir_.filePath("stale.csv")));
    QVERIFY(!w.show_station(1.0));
    const auto& p = w.parameter_panel()->parameters();
    QCOMPARE(p.get(tunnelmap::tunnel_keys::design_width_m), 0.0);
    QCOMPARE(p.get(tunnelmap::tunnel_keys::design_height_m), 0.0);
    QVERIFY(w.cross_section()->view()->section().design == std::nullopt);
    w.parameter_panel()->undo_stack()->undo();
    QCOMPARE(w.parameter_panel()->parameters().get(tunnelmap::tunnel_keys::design_width_m), 0.84);
  }

  void mapTunnelOnAPlainFrameSaysWhy() {
    tunnelmap::ui::MainWindow w;
    w.suppress_dialogs = true;
    QSignalSpy shown(&w, &tunnelmap::ui::MainWindow::frameShown);
    QVERIFY(w.open_input(QString(TUNNELMAP_SOURCE_DIR) + "/resources/sample/lab/depth/000000.png"));
    QVERIFY(shown.wait(30000));
    QSignalSpy mapped(&w, &tunnelmap::ui::MainWindow::tunnelMapped);
    w.map_tunnel();
    QCOMPARE(mapped.count(), 1);
    QCOMPARE(mapped.at(0).at(0).toBool(), false);
    QVERIFY2(w.last_error().contains("needs a posed dataset"), qPrintable(w.last_error()));
    QString why;
    QVERIFY(!w.show_station(1.0, &why));
    QVERIFY2(why.contains("no map"), qPrintable(why));
  }
};

int main(int argc, char** argv) {
  QSurfaceFormat::setDefaultFormat(QVTKOpenGLNativeWidget::defaultFormat());
  QApplication app(argc, argv);
  QApplication::setOrganizationName("TunnelMapTest");
  CrossSectionTest cross_section;
  ProfilePlotTest profile;
  View3DMeasureTest measure;
  DepthViewMeasureTest depth;
  MapReviewTest review;
  MapSectionsPanelTest sections_panel;
  int failures = QTest::qExec(&cross_section, argc, argv);
  failures += QTest::qExec(&profile, argc, argv);
  failures += QTest::qExec(&measure, argc, argv);
  failures += QTest::qExec(&depth, argc, argv);
  failures += QTest::qExec(&review, argc, argv);
  failures += QTest::qExec(&sections_panel, argc, argv);
  return failures;
}

#include "measure_views_test.moc"
