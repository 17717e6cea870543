#pragma once
// Width and height per frame, each on its own axis (millimetre changes stay visible), against a
// frame axis numbered from 1 like the timeline. A vertical marker shows the current frame; the
// reference (ground truth, else the design) is a dashed line with its tolerance band, and frames
// outside the band are drawn as red dots. Clicking selects the nearest frame.
#include <QWidget>
#include <optional>
#include <vector>

#include "ui/frame_record.h"

namespace tunnelmap::ui {

struct PlotReference {
  std::optional<double> width_m, height_m;  // none: no line, no band, nothing flagged
  double tolerance_m = 0.010;
  QString source;  // "ground truth" or "design"
};

class ResultsPlot : public QWidget {
  Q_OBJECT
 public:
  explicit ResultsPlot(QWidget* parent = nullptr);
  void set_records(const std::vector<FrameRecord>& records);
  void set_frame_count(int count);  // x axis 1..count
  void set_current(int index);      // 0-based frame index; -1 = none
  void set_reference(const PlotReference& reference);
  int current() const { return current_; }
  const PlotReference& reference() const { return reference_; }
  // 0-based indices of detected frames whose width or height is outside the tolerance band.
  std::vector<int> out_of_tolerance() const;
  // Widget x of frame `index` (for clicks) and the two plot areas (0 width, 1 height).
  double x_of(int index) const;
  QRectF area(int series) const;

 signals:
  void frameClicked(int index);

 protected:
  void paintEvent(QPaintEvent*) override;
  void mousePressEvent(QMouseEvent* e) override;

 private:
  void draw_series(class QPainter& p, int series) const;

  std::vector<FrameRecord> records_;
  int count_ = 0;
  int current_ = -1;
  PlotReference reference_;
};

}  // namespace tunnelmap::ui
