#include "ui/report/report_plan.h"

#include <QFontMetricsF>
#include <QPainterPath>
#include <algorithm>
#include <cmath>
#include <vector>

#include "ui/report/report_axis.h"
#include "ui/report/report_draw.h"
#include "ui/report/report_format.h"

namespace tunnelmap::report {

namespace {

const QColor kSectionFill[2] = {QColor(205, 222, 240), QColor(228, 236, 245)};
const QColor kOutline(55, 55, 55);
const QColor kJoint(30, 30, 30);
const QColor kPose(80, 80, 80);
const QColor kPlate(120, 128, 140);

// Distance of the left and right walls from the centre line at a station (NaN when unseen).
// Prefers the measured wall positions; otherwise splits the width around the centre line.
void wall_offsets(const Station& s, double& left, double& right) {
  const bool width_known = s.width_source != DimensionSource::Unseen;
  left = s.wall_m[0];
  right = s.wall_m[1];
  if (std::isfinite(left) && !std::isfinite(right) && width_known) right = s.width_m - left;
  if (!std::isfinite(left) && std::isfinite(right) && width_known) left = s.width_m - right;
  if (!std::isfinite(left) && !std::isfinite(right) && width_known) left = right = 0.5 * s.width_m;
}

double widest_of(const StationMap& m) {
  double widest = 0.0;
  for (const Section& s : m.sections) widest = std::max(widest, s.width_m);
  for (const Station& s : m.stations) {
    double l, r;
    wall_offsets(s, l, r);
    if (std::isfinite(l) && std::isfinite(r)) widest = std::max(widest, 2.0 * std::max(l, r));
  }
  if (m.options.design_width_m) widest = std::max(widest, *m.options.design_width_m);
  return widest > 0.0 ? widest : 1.0;
}

}  // namespace

void add_plan(Document& doc, const StationMap& map) {
  const QFont small = doc.font(7.0), small_bold = doc.font(7.0, true), label_font = doc.font(8.0, true);
  const double lh = doc.metrics(small).height();
  const double px_per_mm = doc.mm(1.0);
  // Rows from the top: joint labels (two staggered rows), the band, marks below it, the ruler,
  // the legend.
  const double joints_h = 2.0 * lh + doc.mm(1.0), band_h = doc.mm(24.0), marks_h = doc.mm(3.4);
  const double ruler_h = doc.mm(2.0) + 2.0 * lh, legend_h = lh + doc.mm(3.0);
  const StationMap* m = &map;

  Block b;
  b.height = joints_h + band_h + marks_h + ruler_h + legend_h;
  b.paint = [=](QPainter& p, const QRectF& box) {
    auto mm = [px_per_mm](double v) { return v * px_per_mm; };
    const QFontMetricsF fm(small, p.device()), fm_label(label_font, p.device());
    double lo, hi;
    station_range(*m, lo, hi);
    const Axis x{lo, hi, box.left() + mm(kPlotLeftMm), box.right() - mm(kPlotRightMm)};
    const double band_top = box.top() + joints_h, band_bottom = band_top + band_h;
    const double mid = 0.5 * (band_top + band_bottom);
    const double widest = widest_of(*m);
    const double k_lat = 0.92 * band_h / widest;  // page pixels per metre across the tunnel
    auto lateral = [&](double left_m) { return mid - left_m * k_lat; };
    const double half_step = 0.5 * m->options.station_step_m;
    p.setRenderHint(QPainter::Antialiasing, true);

    // Sections, shaded alternately, named and sized in the upper half of the band (the names are
    // drawn last, over the plates' lines, on their section's shade).
    struct SectionLabel {
      QRectF box;
      QString text;
      QColor fill;
    };
    std::vector<SectionLabel> labels;
    for (std::size_t i = 0; i < m->sections.size(); ++i) {
      const Section& s = m->sections[i];
      const QRectF r(QPointF(x.at(s.from_m), lateral(0.5 * s.width_m)), QPointF(x.at(s.to_m), lateral(-0.5 * s.width_m)));
      p.fillRect(r, kSectionFill[i % 2]);
      const QString name = QStringLiteral("S%1").arg(i + 1);
      const QString size = metres(s.width_m) + QStringLiteral(" \u00d7 ") + metres(s.height_m);
      const QRectF label_box(r.left(), r.top() + mm(0.8), r.width(), fm_label.height());
      if (fm_label.horizontalAdvance(name + QStringLiteral("  ") + size) + mm(2) < r.width())
        labels.push_back({label_box, name + QStringLiteral("  ") + size, kSectionFill[i % 2]});
      else if (fm_label.horizontalAdvance(name) + mm(1) < r.width())
        labels.push_back({label_box, name, kSectionFill[i % 2]});
    }

    // Centre line.
    p.setPen(QPen(colours::kRule, mm(0.15), Qt::DashDotLine));
    p.drawLine(QPointF(x.p0, mid), QPointF(x.p1, mid));

    // The outline: each wall through its stations' positions, one path per run of adjacent
    // stations (a gap where the wall was unseen).
    p.setPen(QPen(kOutline, mm(0.3), Qt::SolidLine, Qt::FlatCap, Qt::RoundJoin));
    p.setBrush(Qt::NoBrush);
    for (int side = 0; side < 2; ++side) {
      const double sign = side == 0 ? 1.0 : -1.0;  // left wall above the centre line
      QPainterPath path;
      double last_station = 0.0, last_y = 0.0;
      bool open = false;
      auto close_run = [&] {
        if (!open) return;
        path.lineTo(x.at(last_station + half_step), last_y);
        open = false;
      };
      for (const Station& s : m->stations) {
        double l, r;
        wall_offsets(s, l, r);
        const double off = side == 0 ? l : r;
        if (!std::isfinite(off)) {
          close_run();
          continue;
        }
        const double y = lateral(sign * off);
        if (open && std::abs(s.station_m - last_station - 2 * half_step) > 0.25 * half_step) close_run();
        if (!open) {
          path.moveTo(x.at(s.station_m - half_step), y);
          open = true;
        }
        path.lineTo(x.at(s.station_m), y);
        last_station = s.station_m;
        last_y = y;
      }
      close_run();
      p.drawPath(path);
    }

    // Diaphragms: a thick line across the section at each plate, open where its manhole is.
    const double plate_pen = mm(0.7);
    p.setPen(QPen(kPlate, plate_pen, Qt::SolidLine, Qt::FlatCap));
    for (const Diaphragm& d : m->girder.diaphragms) {
      double width = widest;
      for (const Section& s : m->sections)
        if (d.station_m >= s.from_m && d.station_m <= s.to_m) width = s.width_m;
      const double px = x.at(d.station_m);
      if (!d.manhole) {
        p.drawLine(QPointF(px, lateral(0.5 * width)), QPointF(px, lateral(-0.5 * width)));
        continue;
      }
      const double gap_left = d.manhole->lateral_m + 0.5 * d.manhole->width_m;
      const double gap_right = d.manhole->lateral_m - 0.5 * d.manhole->width_m;
      p.drawLine(QPointF(px, lateral(0.5 * width)), QPointF(px, lateral(std::min(gap_left, 0.5 * width))));
      p.drawLine(QPointF(px, lateral(std::max(gap_right, -0.5 * width))), QPointF(px, lateral(-0.5 * width)));
    }

    // The sections' names, each on its shade where a plate's line would cross the text.
    p.setFont(label_font);
    for (const SectionLabel& l : labels) {
      const double w = fm_label.horizontalAdvance(l.text) + mm(1.2);
      const QRectF behind(l.box.center().x() - 0.5 * w, l.box.top(), w, l.box.height());
      p.fillRect(behind, l.fill);
      p.setPen(colours::kText);
      p.drawText(l.box, Qt::AlignCenter, l.text);
    }

    // Side names, left of the drawing.
    p.setFont(small);
    p.setPen(colours::kMuted);
    const QRectF names(box.left(), band_top, x.p0 - box.left() - mm(1.5), band_h);
    p.drawText(names, Qt::AlignRight | Qt::AlignTop, QStringLiteral("left wall"));
    p.drawText(names, Qt::AlignRight | Qt::AlignBottom, QStringLiteral("right wall"));

    // Joints: dashed lines across the band, their station above (two rows when crowded).
    p.setFont(small);
    double row_right[2] = {-1e18, -1e18};
    for (std::size_t i = 1; i < m->sections.size(); ++i) {
      const double j = 0.5 * (m->sections[i - 1].to_m + m->sections[i].from_m);
      const double px = x.at(j);
      p.setPen(QPen(kJoint, mm(0.35), Qt::DashLine));
      p.drawLine(QPointF(px, band_top - mm(1.0)), QPointF(px, band_bottom + mm(0.8)));
      const QString label = fixed(j, 2) + QStringLiteral(" m");
      const double w = fm.horizontalAdvance(label);
      const double left = std::clamp(px - 0.5 * w, box.left(), box.right() - w);
      // The row next to the band first; the upper row (with a leader line) when that is taken.
      // The leader line must not cross the lower row's last label.
      const bool lower_free = left > row_right[1] + mm(1);
      const bool upper_free = left > row_right[0] + mm(1) && px > row_right[1] + mm(0.6);
      const int row = lower_free ? 1 : (upper_free ? 0 : -1);
      if (row < 0) continue;  // no room: the sections table lists every joint
      p.setPen(kJoint);
      p.drawText(QRectF(left, box.top() + row * lh, w + 1, lh), Qt::AlignCenter, label);
      row_right[row] = left + w;
      if (row == 0) {
        p.setPen(QPen(kJoint, mm(0.15)));
        p.drawLine(QPointF(px, box.top() + lh), QPointF(px, band_top - mm(1.0)));
      }
    }

    // Out-of-tolerance stations: red marks under the band.
    for (const Station& s : m->stations)
      if (s.out_of_tolerance)
        draw_mark(p, Mark::TriangleUp, QPointF(x.at(s.station_m), band_bottom + 0.5 * marks_h), mm(1.8),
                  colours::kAlert);

    // Pose cameras where they stood (rescans in red), named below the marker where the name has
    // room: the poses to rescan first, so that none of them goes unnamed for a neighbour.
    const Eigen::Vector3d left_dir = m->up.cross(m->axis).normalized();
    const QFontMetricsF fm_bold(small_bold, p.device());
    struct PoseMark {
      QPointF at;
      QString name;
      bool rescan;
    };
    std::vector<PoseMark> marks;
    for (const PoseGroupStatus& pose : m->poses) {
      const Eigen::Vector3d t = pose.camera_to_world.translation();
      const double s = m->station_of(t);
      if (!std::isfinite(s)) continue;
      const double side = std::clamp(left_dir.dot(t - m->origin), -0.45 * widest, 0.45 * widest);
      marks.push_back({QPointF(x.at(s), lateral(side)), QStringLiteral("P%1").arg(pose.group), pose.rescan});
      draw_mark(p, Mark::Dot, marks.back().at, mm(2.4), Qt::white);
      draw_mark(p, Mark::Dot, marks.back().at, mm(1.8), pose.rescan ? colours::kAlert : kPose);
    }
    std::stable_partition(marks.begin(), marks.end(), [](const PoseMark& k) { return k.rescan; });
    std::vector<std::pair<double, double>> named;  // horizontal extents of the names drawn
    p.setFont(small_bold);
    for (const PoseMark& k : marks) {
      const double w = fm_bold.horizontalAdvance(k.name) + mm(0.4);
      const double l = k.at.x() - 0.5 * w - mm(0.4), r = k.at.x() + 0.5 * w + mm(0.4);
      if (std::any_of(named.begin(), named.end(), [&](const auto& n) { return l < n.second && r > n.first; }))
        continue;
      named.emplace_back(l, r);
      p.setPen(k.rescan ? colours::kAlert : kPose);
      p.drawText(QRectF(k.at.x() - 0.5 * w, k.at.y() + mm(1.4), w, lh), Qt::AlignCenter, k.name);
    }

    // Station ruler.
    const double step = nice_step(hi - lo, std::max(2, static_cast<int>((x.p1 - x.p0) / mm(16))));
    draw_station_ruler(p, x, band_bottom + marks_h, step, small, mm, true);

    // How much the widths are stretched against the stations, under the ruler's labels.
    const double kx = (x.p1 - x.p0) / (hi - lo);
    p.setFont(small);
    p.setPen(colours::kMuted);
    p.drawText(QRectF(x.p0, band_bottom + marks_h + mm(1.5) + lh, 0.6 * (x.p1 - x.p0), lh),
               Qt::AlignLeft | Qt::AlignVCenter,
               QStringLiteral("widths drawn at %1\u00d7 the station scale").arg(fixed(k_lat / kx, 1)));

    const std::vector<LegendItem> items = {
        {Mark::Swatch, kOutline, QStringLiteral("section"), kSectionFill[0]},
        {Mark::DashedLine, kJoint, QStringLiteral("joint (section change)")},
        {Mark::Line, kPlate, QStringLiteral("diaphragm")},
        {Mark::Line, kOutline, QStringLiteral("walls")},
        {Mark::TriangleUp, colours::kAlert, QStringLiteral("out of tolerance")},
        {Mark::Dot, kPose, QStringLiteral("pose camera")},
        {Mark::Dot, colours::kAlert, QStringLiteral("pose to rescan")},
    };
    draw_legend(p, QRectF(x.p0, box.bottom() - legend_h + mm(1.0), x.p1 - x.p0, legend_h - mm(1.0)), items,
                small, mm);
  };
  doc.add(std::move(b));
}

}  // namespace tunnelmap::report
