#include "ui/report/report_profile.h"

#include <QFontMetricsF>
#include <QPainterPath>
#include <algorithm>
#include <cmath>
#include <limits>

#include "ui/report/report_axis.h"
#include "ui/report/report_draw.h"
#include "ui/report/report_format.h"
#include "ui/report/report_plan.h"

namespace tunnelmap::report {

namespace {

const QColor kDesign(35, 120, 60);
const QColor kBand(214, 238, 216);
const QColor kInferred(120, 120, 120);
const QColor kSectionValue(170, 95, 20);
const QColor kGrid(228, 228, 228);

struct Point {
  double station, value;
  bool inferred, beyond;
};

struct Series {
  std::vector<Point> points;
  std::optional<double> design;
  double tolerance_m = 0.0;
};

Series series_of(const StationMap& m, Dimension dim) {
  Series s;
  s.design = dim == Dimension::Width ? m.options.design_width_m : m.options.design_height_m;
  s.tolerance_m = m.options.tolerance_mm / 1000.0;
  for (const Station& st : m.stations) {
    const DimensionSource src = dim == Dimension::Width ? st.width_source : st.height_source;
    const double v = dim == Dimension::Width ? st.width_m : st.height_m;
    if (src == DimensionSource::Unseen || !std::isfinite(v)) continue;
    std::optional<double> dev = dim == Dimension::Width ? st.width_dev_mm : st.height_dev_mm;
    if (!dev) dev = deviation_mm(v, s.design);
    s.points.push_back({st.station_m, v, src != DimensionSource::Measured,
                        beyond_tolerance(dev, m.options.tolerance_mm)});
  }
  return s;
}

// Value range: every point, section value and the tolerance band, padded; at least 4 mm.
void value_range(const StationMap& m, const Series& s, Dimension dim, double& lo, double& hi) {
  lo = std::numeric_limits<double>::infinity();
  hi = -lo;
  auto take = [&](double v) {
    if (!std::isfinite(v)) return;
    lo = std::min(lo, v);
    hi = std::max(hi, v);
  };
  for (const Point& p : s.points) take(p.value);
  for (const Section& sec : m.sections) take(dim == Dimension::Width ? sec.width_m : sec.height_m);
  if (s.design) {
    take(*s.design - 1.25 * s.tolerance_m);
    take(*s.design + 1.25 * s.tolerance_m);
  }
  if (!std::isfinite(lo)) lo = 0.0, hi = 1.0;
  const double min_span = 0.004;
  if (hi - lo < min_span) {
    const double c = 0.5 * (lo + hi);
    lo = c - 0.5 * min_span;
    hi = c + 0.5 * min_span;
  }
  const double pad = 0.08 * (hi - lo);
  lo -= pad;
  hi += pad;
}

}  // namespace

void add_profile_plot(Document& doc, const StationMap& map, Dimension dim) {
  const QFont small = doc.font(7.0);
  const double lh = doc.metrics(small).height();
  const double px_per_mm = doc.mm(1.0);
  const double legend_h = lh + doc.mm(2.5), plot_h = doc.mm(50.0), ruler_h = doc.mm(2.0) + 2.0 * lh;
  const StationMap* m = &map;

  Block b;
  b.height = legend_h + plot_h + ruler_h;
  b.paint = [=](QPainter& p, const QRectF& box) {
    auto mm = [px_per_mm](double v) { return v * px_per_mm; };
    const QFontMetricsF fm(small, p.device());
    const Series s = series_of(*m, dim);
    double xlo, xhi, ylo, yhi;
    station_range(*m, xlo, xhi);
    value_range(*m, s, dim, ylo, yhi);
    const QRectF area(QPointF(box.left() + mm(kPlotLeftMm), box.top() + legend_h),
                      QPointF(box.right() - mm(kPlotRightMm), box.top() + legend_h + plot_h));
    const Axis x{xlo, xhi, area.left(), area.right()};
    const Axis y{ylo, yhi, area.bottom(), area.top()};
    const double ystep = nice_step(yhi - ylo, 8);
    const int ydec = std::max(3, decimals_for(ystep));
    const QString name = dim == Dimension::Width ? QStringLiteral("width") : QStringLiteral("height");

    // Grid and y labels.
    p.setFont(small);
    for (double t : ticks(ylo, yhi, ystep)) {
      p.setPen(QPen(kGrid, mm(0.15)));
      p.drawLine(QPointF(area.left(), y.at(t)), QPointF(area.right(), y.at(t)));
      p.setPen(colours::kText);
      p.drawText(QRectF(box.left(), y.at(t) - 0.5 * lh, area.left() - box.left() - mm(1.2), lh),
                 Qt::AlignRight | Qt::AlignVCenter, fixed(t, ydec));
    }
    p.setPen(colours::kMuted);
    p.drawText(QRectF(box.left(), box.top(), area.left() - box.left() - mm(1.2), legend_h),
               Qt::AlignRight | Qt::AlignVCenter, name + QStringLiteral(" (m)"));

    p.save();
    p.setClipRect(area);
    p.setRenderHint(QPainter::Antialiasing, true);
    // Design value and its tolerance band.
    if (s.design) {
      p.fillRect(QRectF(QPointF(area.left(), y.at(*s.design + s.tolerance_m)),
                        QPointF(area.right(), y.at(*s.design - s.tolerance_m))),
                 kBand);
      p.setPen(QPen(kDesign, mm(0.35)));
      p.drawLine(QPointF(area.left(), y.at(*s.design)), QPointF(area.right(), y.at(*s.design)));
    }
    // Section changes and section values.
    for (std::size_t i = 0; i < m->sections.size(); ++i) {
      const Section& sec = m->sections[i];
      if (i > 0) {
        const double j = x.at(0.5 * (m->sections[i - 1].to_m + sec.from_m));
        p.setPen(QPen(colours::kRule, mm(0.25), Qt::DotLine));
        p.drawLine(QPointF(j, area.top()), QPointF(j, area.bottom()));
      }
      const double v = y.at(dim == Dimension::Width ? sec.width_m : sec.height_m);
      p.setPen(QPen(kSectionValue, mm(0.35), Qt::DashLine));
      p.drawLine(QPointF(x.at(sec.from_m), v), QPointF(x.at(sec.to_m), v));
    }
    // Stations: a thin line through neighbours, then the markers on top.
    const double step = m->options.station_step_m;
    const double spacing = step * (x.p1 - x.p0) / (xhi - xlo);
    const double size = std::clamp(0.8 * spacing, mm(0.7), mm(1.6));
    p.setPen(QPen(QColor(120, 150, 190), mm(0.18)));
    for (std::size_t i = 1; i < s.points.size(); ++i)
      if (s.points[i].station - s.points[i - 1].station < 1.5 * step)
        p.drawLine(QPointF(x.at(s.points[i - 1].station), y.at(s.points[i - 1].value)),
                   QPointF(x.at(s.points[i].station), y.at(s.points[i].value)));
    // Red last, so out-of-tolerance stations stay visible where markers crowd.
    for (int pass = 0; pass < 2; ++pass)
      for (const Point& pt : s.points) {
        if (pt.beyond != (pass == 1)) continue;
        const QColor c = pt.beyond ? colours::kAlert : (pt.inferred ? kInferred : colours::kAccent);
        draw_mark(p, pt.inferred ? Mark::HollowDot : Mark::Dot, QPointF(x.at(pt.station), y.at(pt.value)), size, c);
      }
    p.restore();

    if (s.points.empty()) {
      p.setFont(small);
      p.setPen(colours::kMuted);
      p.drawText(area, Qt::AlignCenter, QStringLiteral("no station has a ") + name);
    }
    p.setPen(QPen(colours::kRule, mm(0.2)));
    p.setBrush(Qt::NoBrush);
    p.drawRect(area);
    const double xstep = nice_step(xhi - xlo, std::max(2, static_cast<int>((x.p1 - x.p0) / mm(16))));
    draw_station_ruler(p, x, area.bottom(), xstep, small, mm, true);

    std::vector<LegendItem> items;
    if (s.design)
      items.push_back({Mark::BandWithLine, kDesign,
                       QStringLiteral("design %1 m \u00b1 %2 mm").arg(metres(*s.design), QString::number(m->options.tolerance_mm)),
                       kBand});
    items.push_back({Mark::Dot, colours::kAccent, QStringLiteral("measured")});
    items.push_back({Mark::HollowDot, kInferred, QStringLiteral("from context / design")});
    items.push_back({Mark::Dot, colours::kAlert, QStringLiteral("out of tolerance")});
    items.push_back({Mark::DashedLine, kSectionValue, QStringLiteral("section value")});
    draw_legend(p, QRectF(area.left(), box.top(), area.width(), legend_h - mm(0.8)), items, small, mm);
  };
  doc.add(std::move(b));
}

}  // namespace tunnelmap::report
