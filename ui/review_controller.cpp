#include "ui/review_controller.h"

#include <QAction>
#include <QDockWidget>
#include <QMainWindow>
#include <QMenu>
#include <QScrollArea>
#include <QStyle>

#include "core/mapping/dataset_mapping.h"
#include "core/mapping/station_frames.h"
#include "core/tunnel/tunnel_options.h"
#include "ui/background_job.h"
#include "ui/cross_section_panel.h"
#include "ui/depth_view_widget.h"
#include "ui/frame_controller.h"
#include "ui/map_sections_panel.h"
#include "ui/measure_actions.h"
#include "ui/parameter_panel.h"
#include "ui/profile_plot.h"
#include "ui/view3d_widget.h"
#include "ui/window_context.h"
#include "ui/window_status.h"

namespace tunnelmap::ui {

// What the profile needs to turn a station into a frame.
struct ReviewMap {
  std::shared_ptr<const FrameSource> source;  // the input the map was built from
  std::vector<Eigen::Isometry3d> poses;       // per frame, as the map used them
  std::vector<bool> detected;
  std::vector<std::string> notes;             // the mapping's (MappingNotes::all())
  std::optional<double> pending_ahead;        // cut here once the chosen frame is shown
  int pending_frame = -1;                     // ... that frame
  nlohmann::json params;                      // the parameters the map was made with
};

namespace {
std::optional<double> positive(double v) { return v > 0 ? std::optional<double>(v) : std::nullopt; }
}  // namespace

ReviewController::ReviewController(WindowContext& ctx, FrameController* frames)
    : QObject(ctx.window), ctx_(ctx), frames_(frames), review_map_(std::make_shared<ReviewMap>()) {
  build_cross_section_dock();
  build_profile_dock();
  build_sections_dock();
  connect(frames_, &FrameController::frameShown, this, &ReviewController::frame_shown);
}

void ReviewController::build_cross_section_dock() {
  cross_section_ = new CrossSectionPanel(ctx_.window);
  cross_section_->setObjectName("crossSection");
  cross_section_dock_ = new QDockWidget(tr("Cross-section"), ctx_.window);
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
  ctx_.window->addDockWidget(Qt::RightDockWidgetArea, cross_section_dock_);
  connect(cross_section_->view(), &CrossSectionView::measured, this, [this](double m) {
    ctx_.status->set_text(tr("Cross-section: %1 mm between the two picks").arg(m * 1000.0, 0, 'f', 1));
  });
}

// Along the bottom, a tab beside the frames and results: a profile is wide, and the
// cross-section it drives stays in view on the right.
void ReviewController::build_profile_dock() {
  profile_ = new ProfilePlot(ctx_.window);
  profile_->setObjectName("profilePlot");
  profile_dock_ = new QDockWidget(tr("Tunnel profile"), ctx_.window);
  profile_dock_->setObjectName("profileDock");
  profile_dock_->setWidget(profile_);
  ctx_.window->addDockWidget(Qt::BottomDockWidgetArea, profile_dock_);
  if (auto* results = frames_->results_dock()) {
    ctx_.window->tabifyDockWidget(results, profile_dock_);
    results->raise();
  }
  connect(profile_, &ProfilePlot::stationClicked, this, [this](double s) { show_station(s); });
}

// The map's sections, out-of-tolerance stations and plates, beside the profile they select on.
void ReviewController::build_sections_dock() {
  sections_ = new MapSectionsPanel(ctx_.window);
  sections_->setObjectName("mapSections");
  sections_dock_ = new QDockWidget(tr("Sections"), ctx_.window);
  sections_dock_->setObjectName("sectionsDock");
  sections_dock_->setWidget(sections_);
  ctx_.window->addDockWidget(Qt::BottomDockWidgetArea, sections_dock_);
  ctx_.window->splitDockWidget(profile_dock_, sections_dock_, Qt::Horizontal);
  ctx_.window->resizeDocks({sections_dock_}, {440}, Qt::Horizontal);
  sections_dock_->hide();  // until there is a map
  connect(sections_, &MapSectionsPanel::stationChosen, this, [this](double s) { show_station(s); });
}

void ReviewController::add_actions(QMenu* processing, QMenu* view) {
  processing->addSeparator();
  QAction* map = processing->addAction(tr("&Map tunnel"), this, &ReviewController::map_tunnel);
  map->setObjectName("mapTunnel");
  map->setStatusTip(tr("Posed datasets: the station-by-station profile of the whole tunnel"));
  add_measure_actions(view, ctx_.view3d, ctx_.depth_view, ctx_.status);
  view->addAction(cross_section_dock_->toggleViewAction());
  view->addAction(profile_dock_->toggleViewAction());
  view->addAction(sections_dock_->toggleViewAction());
}

void ReviewController::frame_shown() {
  if (!frames_->current()) return;
  // A measurement belongs to the frame it was picked in.
  if (review_frame_ != frames_->frame_index()) {
    ctx_.view3d->clear_measurement();
    ctx_.depth_view->clear_measurement();
  }
  review_frame_ = frames_->frame_index();
  const Parameters& p = ctx_.params->parameters();
  const std::optional<double> dw = positive(p.get(tunnel_keys::design_width_m)),
                              dh = positive(p.get(tunnel_keys::design_height_m));
  cross_section_->set_frame(frames_->current_frame(), dw && dh ? dw : std::nullopt, dw && dh ? dh : std::nullopt,
                            mm_to_m(p.get(tunnel_keys::zone_cluster_mm)));
  if (review_map_->pending_ahead && review_map_->pending_frame == frames_->last_outcome().frame_index) {
    cross_section_->set_station(*review_map_->pending_ahead);
    review_map_->pending_ahead.reset();
  }
}

void ReviewController::forget() {
  *review_map_ = ReviewMap{};
  review_frame_ = -1;
  profile_->clear();
  sections_->clear();
  cross_section_->set_frame(nullptr, std::nullopt, std::nullopt, mm_to_m(tunnel_keys::zone_cluster_mm.default_value));
  ctx_.view3d->clear_measurement();
  ctx_.depth_view->clear_measurement();
}

void ReviewController::cut_when_shown(int frame, std::optional<double> ahead_m) {
  review_map_->pending_frame = frame;
  review_map_->pending_ahead = ahead_m;
}

void ReviewController::map_tunnel() {
  if (map_running_ || ctx_.job->running()) return;
  const Dataset* ds = ctx_.dataset();
  if (!ds) {
    ctx_.status->show_error(tr("%1: Map tunnel needs a posed dataset (dataset.json with poses or joints)")
                                .arg(ctx_.input_path.isEmpty() ? tr("no input") : ctx_.input_path));
    return emit tunnelMapped(false);
  }
  map_running_ = true;
  const int n = static_cast<int>(ds->frames.size());
  ctx_.status->set_text(tr("Mapping the tunnel over %1 frame(s)…").arg(n));
  ctx_.status->show_progress(n + 1);  // the last step is the map itself, after every frame
  auto source = ctx_.source;
  Pipeline pipeline(ctx_.params->parameters());
  const nlohmann::json params = ctx_.params->parameters().to_json();
  const std::atomic<bool>& cancel = ctx_.job->cancel_flag();
  ctx_.job->start([this, source, pipeline, params, &cancel]() mutable {
    auto result = std::make_shared<DatasetMapping>();
    QString error;
    try {
      *result = map_dataset(*source->dataset(), pipeline, true, [this, &cancel](std::size_t done) {
        QMetaObject::invokeMethod(this, [this, done] { ctx_.status->set_progress(static_cast<int>(done)); });
        return !cancel.load();
      });
    } catch (const std::exception& e) {
      error = QString::fromStdString(e.what());
    }
    QMetaObject::invokeMethod(this, [this, source, result, params, error] {
      map_running_ = false;
      ctx_.job->finished();
      ctx_.status->hide_progress();
      finish_map_tunnel(source, *result, params, error);
    });
  });
}

void ReviewController::finish_map_tunnel(const std::shared_ptr<const FrameSource>& source,
                                         const DatasetMapping& result, const nlohmann::json& params,
                                         const QString& error) {
  if (!error.isEmpty()) {
    ctx_.status->show_error(error);
    return emit tunnelMapped(false);
  }
  if (result.cancelled) {
    ctx_.status->set_text(tr("Map tunnel cancelled; the previous map is kept"));
    return emit tunnelMapped(false);
  }
  const StationMap& m = result.mapped.stations;
  if (!m.ok) {
    ctx_.status->show_error(tr("%1: no map: %2").arg(ctx_.input_path, QString::fromStdString(m.reason)));
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
  const std::vector<std::string> notes = result.notes.all();
  review_map_->notes = notes;
  sections_->set_map(m, notes);
  sections_dock_->show();
  if (!notes.empty()) sections_dock_->raise();  // what the map cannot show, before the profile
  const bool design = m.options.design_width_m || m.options.design_height_m;
  ctx_.status->set_text(tr("Tunnel mapped from %1 of %2 frame(s): %3 stations over %4 m, %5 section(s), %6")
                            .arg(m.frames_used)
                            .arg(m.frames)
                            .arg(m.stations.size())
                            .arg(m.sections.back().to_m - m.sections.front().from_m, 0, 'f', 2)
                            .arg(m.sections.size())
                            .arg(design ? tr("%1 out of tolerance").arg(m.out_of_tolerance().size())
                                        : tr("no tolerance check (no design)")) +
                        (notes.empty() ? QString() : tr("; %n note(s) in Sections", nullptr, static_cast<int>(notes.size()))));
  emit tunnelMapped(true);
}

std::optional<ReviewController::MappedTunnel> ReviewController::mapped_tunnel() const {
  if (!ctx_.source || review_map_->source != ctx_.source || profile_->map().stations.empty()) return std::nullopt;
  return MappedTunnel{&profile_->map(), review_map_->params, review_map_->notes};
}

bool ReviewController::show_station(double station_m, QString* why_not) {
  const auto refuse = [&](const QString& why, bool on_status) {
    if (on_status) ctx_.status->set_text(why.left(1).toUpper() + why.mid(1));
    if (why_not) *why_not = why;
    return false;
  };
  if (review_map_->source != ctx_.source || profile_->map().stations.empty())
    return refuse(tr("no map of this input (Processing > Map tunnel first)"), false);
  const StationMap& map = profile_->map();
  if (const MapExtent extent = map_extent(map); !extent.contains(station_m))
    return refuse(tr("station %1 m lies outside the map, which runs from %2 to %3 m")
                      .arg(station_m, 0, 'f', 2).arg(extent.from_m, 0, 'f', 2).arg(extent.to_m, 0, 'f', 2), true);
  const auto view = frame_for_station(map, review_map_->poses, review_map_->detected, station_m);
  profile_->set_current_station(station_m);
  sections_->select_station(station_m);
  if (!view) return refuse(tr("no frame sees station %1 m from 0.5 to 4.5 m ahead").arg(station_m, 0, 'f', 2), true);
  cross_section_dock_->show();
  cross_section_dock_->raise();
  if (view->frame == frames_->frame_index() && frames_->current()) {
    cross_section_->set_station(view->ahead_m);
    return true;
  }
  cut_when_shown(view->frame, view->ahead_m);
  return frames_->select_frame(view->frame);
}

}  // namespace tunnelmap::ui
