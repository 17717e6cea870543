#include "ui/profile_plot.h"

#include <QMouseEvent>
#include <QPainter>
#include <algorithm>
#include <cmath>
#include <limits>

namespace tunnelmap::ui {

namespace {
constexpr int kLeft = 64, kRight = 12, kTop = 8, kGap = 22, kBottom = 30;
const QColor kBackground(31, 31, 36);
const QColor kAxisText(210, 210, 210);
const QColor kGrid(255, 255, 255, 28);
const QColor kMeasured(120, 200, 255);
const QColor kBeyond(255, 70, 70);
const QColor kDesign(240, 240, 240);
const QColor kBand(120, 200, 120, 50);
const QColor kMarker(255, 210, 60);

double value_of(const Station& s, int series) { return series == 0 ? s.width_m : s.height_m; }
DimensionSource source_of(const Station& s, int series) { return series == 0 ? s.width_source : s.height_source; }
std::optional<double> design_of(const StationMap& m, int series) {
  return series == 0 ? m.options.design_width_m : m.options.design_height_m;
}

// A tick step of 1, 2 or 5 times a power of ten giving about `n` ticks over `span`.
double nice_step(double span, int n) {
  const double raw = span / std::max(1, n), p = std::pow(10.0, std::floor(std::log10(raw)));
  for (double m : {1.0, 2.0, 5.0, 10.0})
    if (m * p >= raw) return m * p;
  return 10 * p;
}
}  // namespace

ProfilePlot::ProfilePlot(QWidget* parent) : QWidget(parent) {
  setMinimumSize(320, 220);
  setToolTip(tr("Click a station to show it in the other views"));
}

void ProfilePlot::set_map(const StationMap& map) {
  map_ = map;
  lo_ = 0.0, hi_ = 1.0;
  if (!map_.stations.empty()) {
    lo_ = map_.stations.front().station_m - 0.5 * map_.options.station_step_m;
    hi_ = map_.stations.back().station_m + 0.5 * map_.options.station_step_m;
  }
  update();
}

void ProfilePlot::clear() { set_map(StationMap()); }

void ProfilePlot::set_current_station(std::optional<double> station_m) {
  current_ = station_m;
  update();
}

QRectF ProfilePlot::area(int series) const {
  const double h = std::max(20.0, (height() - kTop - kGap - kBottom) / 2.0);
  const double top = kTop + series * (h + kGap);
  return QRectF(kLeft, top, std::max(20, width() - kLeft - kRight), h);
}

double ProfilePlot::x_of(double station_m) const {
  const QRectF a = area(0);
  return a.left() + (station_m - lo_) / (hi_ - lo_) * a.width();
}

std::optional<double> ProfilePlot::station_at(double x) const {
  std::optional<double> best;
  double best_d = std::numeric_limits<double>::infinity();
  for (const Station& s : map_.stations) {
    const double d = std::abs(x_of(s.station_m) - x);
    if (d < best_d) best_d = d, best = s.station_m;
  }
  return best;
}

void ProfilePlot::mousePressEvent(QMouseEvent* e) {
  if (e->button() != Qt::LeftButton) return QWidget::mousePressEvent(e);
  if (const auto s = station_at(e->pos().x())) {
    set_current_station(*s);
    emit stationClicked(*s);
  }
}

void ProfilePlot::draw_series(QPainter& p, int series) const {
  const QRectF a = area(series);
  const std::optional<double> design = design_of(map_, series);
  const double tol = map_.options.tolerance_mm / 1000.0;
  // Value range: every shown value and the tolerance band, at least 4 mm, padded.
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  for (const Station& s : map_.stations)
    if (source_of(s, series) != DimensionSource::Unseen) lo = std::min(lo, value_of(s, series)), hi = std::max(hi, value_of(s, series));
  if (design) lo = std::min(lo, *design - 1.25 * tol), hi = std::max(hi, *design + 1.25 * tol);
  if (!std::isfinite(lo)) lo = 0.0, hi = 1.0;
  if (hi - lo < 0.004) lo = 0.5 * (lo + hi) - 0.002, hi = lo + 0.004;
  const double pad = 0.08 * (hi - lo);
  lo -= pad, hi += pad;
  auto y_of = [&](double v) { return a.bottom() - (v - lo) / (hi - lo) * a.height(); };

  p.setPen(Qt::NoPen);
  if (design) {
    p.setBrush(kBand);
    p.drawRect(QRectF(QPointF(a.left(), y_of(*design + tol)), QPointF(a.right(), y_of(*design - tol))));
  }
  const double step = nice_step(hi - lo, 4);
  p.setFont(QFont(font().family(), 8));
  for (double t = std::ceil(lo / step) * step; t <= hi; t += step) {
    p.setPen(QPen(kGrid, 1));
    p.drawLine(QPointF(a.left(), y_of(t)), QPointF(a.right(), y_of(t)));
    p.setPen(kAxisText);
    p.drawText(QRectF(0, y_of(t) - 7, kLeft - 6, 14), Qt::AlignRight | Qt::AlignVCenter, QString::number(t, 'f', 3));
  }
  p.setPen(kAxisText);
  p.save();
  p.translate(10, a.center().y());
  p.rotate(-90);
  p.drawText(QRectF(-a.height() / 2, -8, a.height(), 16), Qt::AlignCenter,
             series == 0 ? tr("width (m)") : tr("height (m)"));
  p.restore();
  if (design) {
    p.setPen(QPen(kDesign, 1.2, Qt::DashLine));
    p.drawLine(QPointF(a.left(), y_of(*design)), QPointF(a.right(), y_of(*design)));
  }
  // Section changes.
  p.setPen(QPen(QColor(200, 200, 200, 120), 1, Qt::DotLine));
  for (std::size_t i = 1; i < map_.sections.size(); ++i)
    p.drawLine(QPointF(x_of(map_.sections[i].from_m), a.top()), QPointF(x_of(map_.sections[i].from_m), a.bottom()));
  // Stations.
  p.setRenderHint(QPainter::Antialiasing, true);
  for (const Station& s : map_.stations) {
    const DimensionSource src = source_of(s, series);
    if (src == DimensionSource::Unseen) continue;
    const std::optional<double> dev = series == 0 ? s.width_dev_mm : s.height_dev_mm;
    const bool beyond = dev && std::abs(*dev) > map_.options.tolerance_mm;
    const QColor c = beyond ? kBeyond : kMeasured;
    p.setPen(QPen(c, 1.5));
    p.setBrush(src == DimensionSource::Measured ? QBrush(c) : Qt::NoBrush);
    p.drawEllipse(QPointF(x_of(s.station_m), y_of(value_of(s, series))), 3.0, 3.0);
  }
  p.setRenderHint(QPainter::Antialiasing, false);
  p.setBrush(Qt::NoBrush);
  p.setPen(QPen(QColor(120, 120, 120), 1));
  p.drawRect(a);
}

void ProfilePlot::paintEvent(QPaintEvent*) {
  QPainter p(this);
  p.fillRect(rect(), kBackground);
  if (map_.stations.empty()) {
    p.setPen(kAxisText);
    p.drawText(rect().adjusted(12, 12, -12, -12), Qt::AlignCenter | Qt::TextWordWrap,
               tr("No station map: map a posed dataset (Processing \u25b8 Map tunnel) to see its profile"));
    return;
  }
  draw_series(p, 0);
  draw_series(p, 1);
  // Station axis under the height plot.
  const QRectF a = area(1);
  const double step = nice_step(hi_ - lo_, 8);
  p.setPen(kAxisText);
  p.setFont(QFont(font().family(), 8));
  for (double t = std::ceil(lo_ / step) * step; t <= hi_; t += step) {
    const double x = x_of(t);
    p.drawLine(QPointF(x, a.bottom()), QPointF(x, a.bottom() + 4));
    p.drawText(QRectF(x - 30, a.bottom() + 4, 60, 14), Qt::AlignCenter, QString::number(t, 'g', 4));
  }
  p.drawText(QRectF(a.right() - 160, a.bottom() + 16, 160, 14), Qt::AlignRight, tr("station along the axis (m)"));
  if (current_) {
    p.setPen(QPen(kMarker, 2));
    const double x = x_of(*current_);
    p.drawLine(QPointF(x, area(0).top()), QPointF(x, a.bottom()));
  }
}

}  // namespace tunnelmap::ui
