#pragma once
// The cross-section dock: a station slider over the frame's visible stations, the slab
// thickness, and the CrossSectionView of the shown frame at that station. The design rectangle
// comes from tunnel.design_width_m / design_height_m when both are set.
#include <QWidget>
#include <memory>
#include <optional>

#include "core/tunnel/tunnel_options.h"
#include "ui/cross_section_view.h"
#include "ui/scene/processed_frame.h"

class QDoubleSpinBox;
class QSlider;
class QLabel;

namespace tunnelmap::ui {

class CrossSectionPanel : public QWidget {
  Q_OBJECT
 public:
  static constexpr double kDefaultAheadM = 1.5;  // near enough for dense points on all four walls

  explicit CrossSectionPanel(QWidget* parent = nullptr);

  // The frame to cut; null clears. Cuts at the distance last asked for (the spin box, the slider,
  // set_station), as near as the frame's walls reach. `zone_gap_m`: the
  // parameters' zone gap, with which the cut tells a wall's zones apart.
  void set_frame(std::shared_ptr<const scene::ProcessedFrame> frame, std::optional<double> design_width_m,
                 std::optional<double> design_height_m,
                 double zone_gap_m = mm_to_m(tunnel_keys::zone_cluster_mm.default_value));
  void set_station(double station_m);
  double station() const;
  CrossSectionView* view() const { return view_; }

 signals:
  void stationChanged(double station_m);

 private:
  void recompute();
  void update_range_label();

  std::shared_ptr<const scene::ProcessedFrame> frame_;
  double wanted_m_ = kDefaultAheadM;  // the distance the user (or a map station) asked for
  std::optional<double> design_w_, design_h_;
  double zone_gap_m_ = mm_to_m(tunnel_keys::zone_cluster_mm.default_value);
  StationRange range_;
  QSlider* slider_ = nullptr;
  QDoubleSpinBox* station_ = nullptr;
  QDoubleSpinBox* thickness_ = nullptr;
  QLabel* range_label_ = nullptr;
  CrossSectionView* view_ = nullptr;
};

}  // namespace tunnelmap::ui
