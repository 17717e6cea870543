#include "ui/results_plot.h"

#include <QMouseEvent>
#include <QPainter>
#include <QPainterPath>
#include <algorithm>
#include <cmath>

namespace tunnelmap::ui {

namespace {
constexpr double kLeft = 52, kRight = 8, kTop = 6, kBottom = 18, kGap = 14, kInset = 6;
constexpr double kTitleBand = 16;  // the series title's line at the top of its area
const QColor kSeriesColour[2] = {QColor(30, 110, 200), QColor(200, 90, 30)};
const QColor kFlagColour(220, 20, 20);
const QColor kMarkerColour(20, 150, 60);

// The value a frame shows: measured, or from the context of the other frames. Unknown values
// and values filled from the design are not observations: never plotted, never flagged.
std::optional<double> value_of(const FrameRecord& r, int series) {
  const std::optional<DimensionSource>& source = series == 0 ? r.width_source : r.height_source;
  if (!r.detected || !source || *source == DimensionSource::Design) return std::nullopt;
  return series == 0 ? r.width_m : r.height_m;
}
}  // namespace

ResultsPlot::ResultsPlot(QWidget* parent) : QWidget(parent) {
  setMinimumSize(220, 120);
  setObjectName("resultsPlot");
  setCursor(Qt::PointingHandCursor);
}

void ResultsPlot::set_records(const std::vector<FrameRecord>& records) {
  records_ = records;
  update();
}

void ResultsPlot::set_frame_count(int count) {
  count_ = count;
  update();
}

void ResultsPlot::set_current(int index) {
  current_ = index;
  update();
}

void ResultsPlot::set_reference(const PlotReference& reference) {
  reference_ = reference;
  update();
}

std::vector<int> ResultsPlot::out_of_tolerance() const {
  std::vector<int> out;
  const auto off = [&](const std::optional<double>& v, const std::optional<double>& ref) {
    return v && ref && std::abs(*v - *ref) > reference_.tolerance_m;
  };
  for (const auto& r : records_)
    if (off(value_of(r, 0), reference_.width_m) || off(value_of(r, 1), reference_.height_m)) out.push_back(r.index);
  return out;
}

QRectF ResultsPlot::area(int series) const {
  const double h = (height() - kTop - kBottom - kGap) / 2.0;
  return QRectF(kLeft, kTop + series * (h + kGap), width() - kLeft - kRight, h);
}

double ResultsPlot::x_of(int index) const {
  const QRectF a = area(0).adjusted(kInset, 0, -kInset, 0);  // end dots clear of the frame
  const int last = std::max({1, count_ - 1, records_.empty() ? 0 : records_.back().index});
  return a.left() + a.width() * index / last;
}

void ResultsPlot::mousePressEvent(QMouseEvent* e) {
  if (e->button() != Qt::LeftButton || count_ <= 0) return;
  const QRectF a = area(0).adjusted(kInset, 0, -kInset, 0);
  const int last = std::max({1, count_ - 1, records_.empty() ? 0 : records_.back().index});
  const int index = static_cast<int>(std::lround((e->pos().x() - a.left()) / a.width() * last));
  emit frameClicked(std::clamp(index, 0, std::max(0, count_ - 1)));
}

void ResultsPlot::paintEvent(QPaintEvent*) {
  QPainter p(this);
  p.fillRect(rect(), QColor(250, 250, 250));
  const QRectF b = area(1);
  const int last = std::max({1, count_ - 1, records_.empty() ? 0 : records_.back().index});
  // The current-frame marker first, so that the frame's dots stay visible on top of it.
  if (current_ >= 0) {
    const double x = std::round(x_of(current_)) + 0.5;  // a crisp 2-pixel line, not a blend
    p.setPen(QPen(kMarkerColour, 2));
    p.drawLine(QPointF(x, area(0).top()), QPointF(x, b.bottom()));
  }
  p.setRenderHint(QPainter::Antialiasing);
  for (int series = 0; series < 2; ++series) draw_series(p, series);
  // Frame axis: first and last frame numbers (1-based, as the timeline), and the current one.
  p.setPen(Qt::darkGray);
  if (count_ <= 0 && records_.empty()) return;  // no input: no frame axis
  p.drawText(QRectF(x_of(0) - 20, b.bottom() + 2, 40, 14), Qt::AlignCenter, "1");
  p.drawText(QRectF(x_of(last) - 20, b.bottom() + 2, 40, 14), Qt::AlignCenter, QString::number(last + 1));
  if (current_ >= 0) {
    // The label stays inside the widget, also for the first and last frame.
    const double left = std::clamp(x_of(current_) - 40, 0.0, std::max(0.0, width() - 80.0));
    p.fillRect(QRectF(left, b.bottom() + 2, 80, 14), QColor(250, 250, 250));
    p.setPen(kMarkerColour);
    p.drawText(QRectF(left, b.bottom() + 2, 80, 14), Qt::AlignCenter, tr("frame %1").arg(current_ + 1));
  }
}

void ResultsPlot::draw_series(QPainter& p, int series) const {
  const QRectF a = area(series);
  const std::optional<double> ref = series == 0 ? reference_.width_m : reference_.height_m;
  double lo = 1e9, hi = -1e9;
  for (const auto& r : records_)
    if (const auto v = value_of(r, series)) {
      lo = std::min(lo, *v);
      hi = std::max(hi, *v);
    }
  if (ref) {
    lo = std::min(lo, *ref - reference_.tolerance_m);
    hi = std::max(hi, *ref + reference_.tolerance_m);
  }
  p.setPen(QColor(190, 190, 190));
  p.drawRect(a);
  const QString name = series == 0 ? tr("width (m)") : tr("height (m)");
  if (hi < lo) {
    p.setPen(Qt::darkGray);
    p.drawText(a, Qt::AlignCenter, tr("%1: no detection yet").arg(name));
    return;
  }
  // At least 4 mm tall so that equal values do not divide by zero; 10 % margin.
  const double span = std::max(hi - lo, 0.004), mid = (hi + lo) / 2;
  lo = mid - 0.55 * span;
  hi = mid + 0.55 * span;
  const QRectF plot = a.adjusted(0, kTitleBand, 0, 0);  // the title's line stays clear of the data
  auto y_of = [&](double v) { return plot.bottom() - plot.height() * (v - lo) / (hi - lo); };
  if (ref) {
    p.fillRect(QRectF(QPointF(a.left(), y_of(*ref + reference_.tolerance_m)),
                      QPointF(a.right(), y_of(*ref - reference_.tolerance_m)))
                   .intersected(a),
               QColor(120, 200, 120, 60));
    p.setPen(QPen(QColor(60, 60, 60), 1, Qt::DashLine));
    p.drawLine(QPointF(a.left(), y_of(*ref)), QPointF(a.right(), y_of(*ref)));
  }
  QPainterPath path;
  bool started = false;
  for (const auto& r : records_) {
    const auto v = value_of(r, series);
    if (!v) continue;
    const QPointF q(x_of(r.index), y_of(*v));
    started ? path.lineTo(q) : path.moveTo(q);
    started = true;
  }
  p.setPen(QPen(kSeriesColour[series], 1.5));
  p.drawPath(path);
  for (const auto& r : records_) {
    const auto v = value_of(r, series);
    if (!v) continue;
    const bool out = ref && std::abs(*v - *ref) > reference_.tolerance_m;
    p.setPen(Qt::NoPen);
    p.setBrush(out ? kFlagColour : kSeriesColour[series]);
    const double radius = out ? 4.0 : 2.0;
    p.drawEllipse(QPointF(x_of(r.index), y_of(*v)), radius, radius);
  }
  p.setBrush(Qt::NoBrush);
  p.setPen(Qt::darkGray);
  p.drawText(QRectF(0, plot.top() - 2, kLeft - 4, 14), Qt::AlignRight, QString::number(hi, 'f', 3));
  p.drawText(QRectF(0, a.bottom() - 12, kLeft - 4, 14), Qt::AlignRight, QString::number(lo, 'f', 3));
  p.setPen(kSeriesColour[series]);
  QString title = name;
  if (ref) title += tr(" — %1 %2 ± %3 mm").arg(reference_.source).arg(*ref, 0, 'f', 3).arg(reference_.tolerance_m * 1000, 0, 'f', 1);
  p.drawText(QRectF(a.left() + 4, a.top() + 1, a.width() - 8, 14), Qt::AlignLeft, title);
}

}  // namespace tunnelmap::ui
