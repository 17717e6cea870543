#pragma once
// The tunnel's profile along its axis from the station map: width and height against station,
// each on its own axis. Measured stations are filled dots, stations inferred from the context or
// the design hollow, stations out of tolerance red; the design value is a dashed line in its
// tolerance band, section changes are dotted verticals. A marker shows the current station;
// clicking selects the nearest station.
#include <QWidget>
#include <optional>

#include "core/mapping/station_map.h"

namespace tunnelmap::ui {

class ProfilePlot : public QWidget {
  Q_OBJECT
 public:
  explicit ProfilePlot(QWidget* parent = nullptr);

  void set_map(const StationMap& map);
  void clear();
  const StationMap& map() const { return map_; }
  void set_current_station(std::optional<double> station_m);
  std::optional<double> current_station() const { return current_; }

  // Widget x of a station and the plot areas (0 width, 1 height), for clicks and tests.
  double x_of(double station_m) const;
  QRectF area(int series) const;
  // Station nearest to widget x, none without stations.
  std::optional<double> station_at(double x) const;

 signals:
  void stationClicked(double station_m);

 protected:
  void paintEvent(QPaintEvent*) override;
  void mousePressEvent(QMouseEvent* e) override;

 private:
  void draw_series(class QPainter& p, int series) const;

  StationMap map_;
  std::optional<double> current_;
  double lo_ = 0.0, hi_ = 1.0;  // station range shown
};

}  // namespace tunnelmap::ui
