// MainWindow, review docks: the cross-section of the shown frame at a station, the tunnel's
// profile from Processing > Map tunnel (a posed dataset's station map, on a worker thread), and
// the 3D view's measure tool. Clicking a station on the profile shows the frame that sees it
// best and cuts the cross-section there.
#include <QAction>
#include <QDockWidget>
#include <QLabel>
#include <QMenu>
#include <QProgressBar>
#include <QPushButton>
#include <QScrollArea>
#include <QStyle>
#include <QtConcurrent/QtConcurrentRun>
#include <optional>
#include <nlohmann/json.hpp>

#include "core/mapping/dataset_mapping.h"
#include "core/mapping/station_frames.h"
#include "core/tunnel/tunnel_options.h"
#include "ui/cross_section_panel.h"
#include "ui/depth_view_widget.h"
#include "ui/map_sections_panel.h"
#include "ui/main_window.h"
#include "ui/parameter_panel.h"
#include "ui/profile_plot.h"
#include "ui/view3d_widget.h"

namespace tunnelmap::ui {

// What the profile needs to turn a station into a frame.
struct ReviewMap {
  std::shared_ptr<const FrameSource> source;  // the input the map was built from
  std::vector<Eigen::Isometry3d> poses;       // per frame, as the map used them
  std::vector<bool> detected;
  std::optional<double> pending_ahead;        // cut here once the chosen frame is shown
  int pending_frame = -1;                     // ... that frame
  nlohmann::json params;                      // the parameters the map was made with
};

namespace {
std::optional<double> positive(double v) { return v > 0 ? std::optional<double>(v) : std::nullopt; }
}  // namespace

void MainWindow::build_review_docks(QMenu* processing, QMenu* view) {
  review_map_ = std::make_shared<ReviewMap>();
  cross_section_ = new CrossSectionPanel(this);
  cross_section_->setObjectName("crossSection");
  cross_section_dock_ = new QDockWidget(tr("Cross-section"), this);
  cross_section_dock_->setObjectName("crossSectionDock");
  // Scrolls rather than clipping the caption when the dock is shorter than the panel.
  auto* scroll = new QScrollArea;
  scroll->setWidgetResizable(true);
  scroll->setFrameShape(QFrame::NoFrame);
  scroll->setWidget(cross_section_);
  scroll->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
  scroll->setMinimumWidth(cross_section_->minimumSizeHint().width() +
                          scroll->style()->pixelMetric(QStyle::PM_ScrollBarExtent));
  cross_section_dock_->setWidget(scroll);
  addDockWidget(Qt::RightDockWidgetArea, cross_section_dock_);

  profile_ = new ProfilePlot(this);
  profile_->setObjectName("profilePlot");
  profile_dock_ = new QDockWidget(tr("Tunnel profile"), this);
  profile_dock_->setObjectName("profileDock");
  profile_dock_->setWidget(profile_);
  // Along the bottom, a tab beside the frames and results: a profile is wide, and the
  // cross-section it drives stays in view on the right.
  addDockWidget(Qt::BottomDockWidgetArea, profile_dock_);
  if (auto* results = findChild<QDockWidget*>("resultsDock")) {
    tabifyDockWidget(results, profile_dock_);
    results->raise();
  }
  connect(profile_, &ProfilePlot::stationClicked, this, [this](double s) { show_station(s); });
  build_sections_dock();
  connect(cross_section_->view(), &CrossSectionView::measured, this, [this](double m) {
    status_label_->setText(tr("Cross-section: %1 mm between the two picks").arg(m * 1000.0, 0, 'f', 1));
  });

  processing->addSeparator();
  QAction* map = processing->addAction(tr("&Map tunnel"), this, &MainWindow::map_tunnel);
  map->setObjectName("mapTunnel");
  map->setStatusTip(tr("Posed datasets: the station-by-station profile of the whole tunnel"));

  view->addSeparator();
  QAction* measure = view->addAction(tr("&Measure in 3D"));
  measure->setObjectName("measure3d");
  measure->setCheckable(true);
  measure->setShortcut(QKeySequence("M"));
  measure->setStatusTip(tr("Click two points in the 3D view to measure their distance"));
  connect(measure, &QAction::toggled, view3d_, &View3DWidget::set_measuring);
  connect(measure, &QAction::toggled, depth_view_, &DepthViewWidget::set_measuring);
  view->addAction(tr("C&lear measurement"), this, [this] {
    view3d_->clear_measurement();
    depth_view_->clear_measurement();
  }, QKeySequence("Esc"));
  connect(view3d_, &View3DWidget::measurementChanged, this, [this](const QString& text) {
    if (!text.isEmpty()) status_label_->setText(tr("3D measurement: %1").arg(text));
  });
  connect(depth_view_, &DepthViewWidget::measurementChanged, this, [this](const QString& text) {
    if (!text.isEmpty()) status_label_->setText(tr("2D view measurement: %1").arg(text));
  });
  view->addAction(cross_section_dock_->toggleViewAction());
  view->addAction(profile_dock_->toggleViewAction());
  view->addAction(sections_dock_->toggleViewAction());
}

// The map's sections, out-of-tolerance stations and plates, beside the profile they select on.
void MainWindow::build_sections_dock() {
  sections_ = new MapSectionsPanel(this);
  sections_->setObjectName("mapSections");
  sections_dock_ = new QDockWidget(tr("Sections"), this);
  sections_dock_->setObjectName("sectionsDock");
  sections_dock_->setWidget(sections_);
  addDockWidget(Qt::BottomDockWidgetArea, sections_dock_);
  splitDockWidget(profile_dock_, sections_dock_, Qt::Horizontal);
  resizeDocks({sections_dock_}, {440}, Qt::Horizontal);
  sections_dock_->hide();  // until there is a map
  connect(sections_, &MapSectionsPanel::stationChosen, this, [this](double s) { show_station(s); });
}

void MainWindow::review_frame_shown() {
  if (!current_ || !cross_section_) return;
  // A measurement belongs to the frame it was picked in.
  if (review_frame_ != frame_index_) {
    view3d_->clear_measurement();
    depth_view_->clear_measurement();
  }
  review_frame_ = frame_index_;
  const Parameters& p = params_->parameters();
  const double w = p.get(tunnel_keys::design_width_m), h = p.get(tunnel_keys::design_height_m);
  const std::optional<double> dw = positive(w), dh = positive(h);
  cross_section_->set_frame(current_, dw && dh ? dw : std::nullopt, dw && dh ? dh : std::nullopt);
  if (review_map_->pending_ahead && review_map_->pending_frame == last_.frame_index) {
    cross_section_->set_station(*review_map_->pending_ahead);
    review_map_->pending_ahead.reset();
  }
}

// A new input (or the live camera) starts clean: the previous input's map, profile, cut and
// measurements describe another tunnel.
void MainWindow::forget_review_state() {
  *review_map_ = ReviewMap{};
  review_frame_ = -1;
  profile_->clear();
  sections_->clear();
  cross_section_->set_frame(nullptr, std::nullopt, std::nullopt);
  view3d_->clear_measurement();
  depth_view_->clear_measurement();
}

void MainWindow::review_map_pending_station(int frame, std::optional<double> ahead_m) {
  review_map_->pending_frame = frame;
  review_map_->pending_ahead = ahead_m;
}

bool MainWindow::map_running() const { return map_running_; }

void MainWindow::map_tunnel() {
  if (map_running_ || sequence_running_) return;
  const Dataset* ds = source_ ? source_->dataset() : nullptr;
  if (!ds) {
    show_error(tr("%1: Map tunnel needs a posed dataset (dataset.json with poses or joints)")
                   .arg(input_path_.isEmpty() ? tr("no input") : input_path_));
    emit tunnelMapped(false);
    return;
  }
  // One background job at a time (the window waits for it on close): sequence, fusion or map.
  map_running_ = sequence_running_ = true;
  cancel_.store(false);
  const int n = static_cast<int>(ds->frames.size());
  status_label_->setText(tr("Mapping the tunnel over %1 frame(s)…").arg(n));
  progress_->setRange(0, n + 1);  // the last step is the map itself, after every frame
  progress_->setValue(0);
  progress_->show();
  cancel_button_->show();
  auto source = source_;
  Pipeline pipeline(params_->parameters());
  const nlohmann::json params = params_->parameters().to_json();
  sequence_future_ = QtConcurrent::run([this, source, pipeline, params]() mutable {
    auto result = std::make_shared<DatasetMapping>();
    QString error;
    try {
      *result = map_dataset(*source->dataset(), pipeline, true, [this](std::size_t done) {
        QMetaObject::invokeMethod(this, [this, done] { progress_->setValue(static_cast<int>(done)); });
        return !cancel_.load();
      });
    } catch (const std::exception& e) {
      error = QString::fromStdString(e.what());
    }
    QMetaObject::invokeMethod(this, [this, source, result, params, error] {
      map_running_ = sequence_running_ = false;
      progress_->hide();
      cancel_button_->hide();
      finish_map_tunnel(source, *result, params, error);
    });
  });
}

void MainWindow::finish_map_tunnel(const std::shared_ptr<const FrameSource>& source, const DatasetMapping& result,
                                   const nlohmann::json& params, const QString& error) {
  if (!error.isEmpty()) {
    show_error(error);
    return emit tunnelMapped(false);
  }
  if (result.cancelled) {
    status_label_->setText(tr("Map tunnel cancelled; the previous map is kept"));
    return emit tunnelMapped(false);
  }
  const StationMap& m = result.mapped.stations;
  if (!m.ok) {
    show_error(tr("%1: no map: %2").arg(input_path_, QString::fromStdString(m.reason)));
    return emit tunnelMapped(false);
  }
  review_map_->source = source;
  review_map_->poses = result.mapped.poses;
  review_map_->params = params;
  review_map_->detected.clear();
  for (const TunnelMap& f : result.maps) review_map_->detected.push_back(f.detected);
  profile_->set_map(m);
  profile_dock_->show();
  profile_dock_->raise();
  sections_->set_map(m);
  sections_dock_->show();
  status_label_->setText(tr("Tunnel mapped from %1 of %2 frame(s): %3 stations over %4 m, %5 section(s), "
                            "%6 out of tolerance")
                             .arg(m.frames_used)
                             .arg(m.frames)
                             .arg(m.stations.size())
                             .arg(m.sections.back().to_m - m.sections.front().from_m, 0, 'f', 2)
                             .arg(m.sections.size())
                             .arg(m.out_of_tolerance().size()));
  emit tunnelMapped(true);
}

std::optional<MainWindow::MappedTunnel> MainWindow::mapped_tunnel() const {
  if (!source_ || review_map_->source != source_ || profile_->map().stations.empty()) return std::nullopt;
  return MappedTunnel{&profile_->map(), review_map_->params};
}

bool MainWindow::show_station(double station_m) {
  if (review_map_->source != source_ || profile_->map().stations.empty()) return false;
  const auto view = frame_for_station(profile_->map(), review_map_->poses, review_map_->detected, station_m);
  profile_->set_current_station(station_m);
  sections_->select_station(station_m);
  if (!view) {
    status_label_->setText(tr("No frame sees station %1 m from 0.5 to 4.5 m ahead").arg(station_m, 0, 'f', 2));
    return false;
  }
  cross_section_dock_->show();
  cross_section_dock_->raise();
  if (view->frame == frame_index_ && current_) {
    cross_section_->set_station(view->ahead_m);
    return true;
  }
  review_map_pending_station(view->frame, view->ahead_m);
  return select_frame(view->frame);
}

}  // namespace tunnelmap::ui
