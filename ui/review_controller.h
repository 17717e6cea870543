#pragma once
// Map and review: Processing > Map tunnel (a posed dataset's station map, on the background job
// with progress and Cancel), the tunnel profile and the Sections dock it fills, the
// cross-section of the shown frame at a station, View > Measure in 3D, and the map's exports
// (sectioned map PLY, station CSV, diaphragms CSV, PDF report) written by the CLI's writers.
// Clicking a station on the profile or the Sections dock shows the frame that sees it best
// and cuts the cross-section there.
#include <QObject>
#include <functional>
#include <memory>
#include <optional>

#include <nlohmann/json.hpp>

#include "core/io/frame_source.h"

class QDockWidget;
class QMenu;

namespace tunnelmap {
struct DatasetMapping;
struct StationMap;
}

namespace tunnelmap::ui {

class CrossSectionPanel;
class FrameController;
class MapSectionsPanel;
class ProfilePlot;
struct ReviewMap;
struct WindowContext;

class ReviewController : public QObject {
  Q_OBJECT
 public:
  ReviewController(WindowContext& ctx, FrameController* frames);

  void add_actions(QMenu* processing, QMenu* view);
  void map_tunnel();  // posed datasets: the station map, on the background job
  bool map_running() const { return map_running_; }
  // The frame that sees `station_m` best is shown, the cross-section cut there; false when the
  // station lies outside the map (its sections and plates), no frame sees it, or there is no map
  // of this input, with the reason (one line, lower case) in `why_not`; the first two also on
  // the status line.
  bool show_station(double station_m, QString* why_not = nullptr);
  // Once `frame` is shown, the cut moves `ahead_m` in front of its camera (a session's cut).
  void cut_when_shown(int frame, std::optional<double> ahead_m);
  void forget();  // a new input or the live camera: its map, profile, cut and measurements go
  CrossSectionPanel* cross_section() const { return cross_section_; }
  MapSectionsPanel* map_sections() const { return sections_; }
  ProfilePlot* profile() const { return profile_; }

  // The station map of the open input (Map tunnel) and the parameters it was made with.
  struct MappedTunnel {
    const StationMap* map;
    nlohmann::json params;
    std::vector<std::string> notes;  // the mapping's, as `map` prints them
  };
  std::optional<MappedTunnel> mapped_tunnel() const;
  // After Map tunnel, as `map --ply`, `--csv`, `--diaphragms-csv` and `--report` write them;
  // an error when the open input has not been mapped.
  bool export_sectioned_map_ply(const QString& path);
  bool export_station_csv(const QString& path);
  bool export_diaphragms_csv(const QString& path);
  bool export_report(const QString& path);

 signals:
  void tunnelMapped(bool ok);

 private:
  void build_cross_section_dock();
  void build_profile_dock();
  void build_sections_dock();
  void frame_shown();  // the cross-section follows the shown frame
  void finish_map_tunnel(const std::shared_ptr<const FrameSource>& source, const DatasetMapping& result,
                         const nlohmann::json& params, const QString& error);
  bool write_map_export(const QString& path, const std::function<void(const MappedTunnel&)>& write);

  WindowContext& ctx_;
  FrameController* frames_;
  CrossSectionPanel* cross_section_ = nullptr;
  ProfilePlot* profile_ = nullptr;
  MapSectionsPanel* sections_ = nullptr;
  QDockWidget* cross_section_dock_ = nullptr;
  QDockWidget* profile_dock_ = nullptr;
  QDockWidget* sections_dock_ = nullptr;
  std::shared_ptr<ReviewMap> review_map_;
  int review_frame_ = -1;
  bool map_running_ = false;
};

}  // namespace tunnelmap::ui
