#pragma once
// The cross-section view: the points of a slab across the tunnel at one station (coloured by
// wall class), the fitted rectangle in boundary blue with its width and height, the design
// rectangle dashed when known, a 0.1 m grid, equal scale on both axes. Two clicks measure: each
// snaps to the nearest section point within 12 px, and the distance between them is drawn.
#include <QWidget>
#include <optional>

#include "core/tunnel/cross_section.h"

namespace tunnelmap::ui {

class CrossSectionView : public QWidget {
  Q_OBJECT
 public:
  explicit CrossSectionView(QWidget* parent = nullptr);

  void set_section(const CrossSection& section);
  void clear();
  const CrossSection& section() const { return section_; }

  // Section coordinates (metres) <-> widget pixels, with the current scale.
  QPointF to_widget(const Eigen::Vector2d& at) const;
  Eigen::Vector2d to_section(const QPointF& pixel) const;

  // Measurement: the picked points (0, 1 or 2) and their distance once there are two.
  const std::vector<Eigen::Vector2d>& picks() const { return picks_; }
  std::optional<double> measured_m() const;
  void clear_picks();

  // The caption under the drawing: station, size, deviation from the design.
  QString caption() const;

 signals:
  void measured(double metres);

 protected:
  void paintEvent(QPaintEvent*) override;
  void mousePressEvent(QMouseEvent* e) override;
  void resizeEvent(QResizeEvent*) override;

 private:
  void fit();
  QRectF plot_rect() const;
  int caption_height() const;

  CrossSection section_;
  std::vector<Eigen::Vector2d> picks_;
  double scale_ = 1.0;       // pixels per metre
  QPointF origin_;           // widget position of section (0, 0)
};

}  // namespace tunnelmap::ui
