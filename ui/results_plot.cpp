#include "ui/results_plot.h"

#include <QPainter>
#include <QPainterPath>
#include <algorithm>

namespace tunnelmap::ui {

ResultsPlot::ResultsPlot(QWidget* parent) : QWidget(parent) { setMinimumSize(200, 90); }

void ResultsPlot::set_records(const std::vector<FrameRecord>& records) {
  records_ = records;
  update();
}

void ResultsPlot::paintEvent(QPaintEvent*) {
  QPainter p(this);
  p.fillRect(rect(), QColor(250, 250, 250));
  double lo = 1e9, hi = -1e9;
  int max_index = 1;
  for (const auto& r : records_) {
    max_index = std::max(max_index, r.index);
    if (!r.detected) continue;
    lo = std::min({lo, r.width_m, r.height_m});
    hi = std::max({hi, r.width_m, r.height_m});
  }
  p.setPen(Qt::darkGray);
  if (hi < lo) {
    p.drawText(rect(), Qt::AlignCenter, tr("width / height per frame"));
    return;
  }
  lo -= 0.02;
  hi += 0.02;
  const QRectF area = QRectF(rect()).adjusted(40, 8, -8, -16);
  auto pt = [&](int i, double v) {
    return QPointF(area.left() + area.width() * i / max_index,
                   area.bottom() - area.height() * (v - lo) / (hi - lo));
  };
  p.drawText(QRectF(0, area.top() - 6, 38, 14), Qt::AlignRight, QString::number(hi, 'f', 2));
  p.drawText(QRectF(0, area.bottom() - 8, 38, 14), Qt::AlignRight, QString::number(lo, 'f', 2));
  p.drawRect(area);
  for (int series = 0; series < 2; ++series) {
    QPainterPath path;
    bool started = false;
    for (const auto& r : records_) {
      if (!r.detected) continue;
      const QPointF q = pt(r.index, series == 0 ? r.width_m : r.height_m);
      started ? path.lineTo(q) : path.moveTo(q);
      started = true;
    }
    p.setPen(QPen(series == 0 ? QColor(30, 110, 200) : QColor(200, 90, 30), 1.5));
    p.drawPath(path);
  }
  p.setPen(QColor(30, 110, 200));
  p.drawText(QPointF(area.left() + 4, area.bottom() + 13), tr("width"));
  p.setPen(QColor(200, 90, 30));
  p.drawText(QPointF(area.left() + 50, area.bottom() + 13), tr("height"));
}

}  // namespace tunnelmap::ui
