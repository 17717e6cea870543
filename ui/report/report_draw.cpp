#include "ui/report/report_draw.h"

#include <algorithm>

#include <QFontMetricsF>
#include <QPainterPath>

namespace tunnelmap::report {

void draw_mark(QPainter& p, Mark m, const QPointF& c, double size, const QColor& colour, const QColor& fill) {
  const double r = 0.5 * size;
  p.save();
  p.setRenderHint(QPainter::Antialiasing, true);
  switch (m) {
    case Mark::Dot:
      p.setPen(Qt::NoPen);
      p.setBrush(colour);
      p.drawEllipse(c, r, r);
      break;
    case Mark::HollowDot:
      p.setPen(QPen(colour, size * 0.22));
      p.setBrush(Qt::white);
      p.drawEllipse(c, r * 0.85, r * 0.85);
      break;
    case Mark::TriangleUp: {
      QPainterPath path;
      path.moveTo(c.x(), c.y() - r);
      path.lineTo(c.x() + r, c.y() + r);
      path.lineTo(c.x() - r, c.y() + r);
      path.closeSubpath();
      p.fillPath(path, colour);
      break;
    }
    case Mark::Line:
    case Mark::DashedLine: {
      QPen pen(colour, size * 0.18);
      if (m == Mark::DashedLine) pen.setStyle(Qt::DashLine);
      p.setPen(pen);
      p.drawLine(QPointF(c.x() - 1.4 * r, c.y()), QPointF(c.x() + 1.4 * r, c.y()));
      break;
    }
    case Mark::Swatch:
      p.setPen(QPen(colour, size * 0.08));
      p.setBrush(fill);
      p.drawRect(QRectF(c.x() - 1.2 * r, c.y() - 0.6 * r, 2.4 * r, 1.2 * r));
      break;
    case Mark::BandWithLine:
      p.fillRect(QRectF(c.x() - 1.4 * r, c.y() - 0.6 * r, 2.8 * r, 1.2 * r), fill);
      p.setPen(QPen(colour, size * 0.15));
      p.drawLine(QPointF(c.x() - 1.4 * r, c.y()), QPointF(c.x() + 1.4 * r, c.y()));
      break;
  }
  p.restore();
}

void draw_legend(QPainter& p, const QRectF& row, const std::vector<LegendItem>& items, const QFont& f,
                 const std::function<double(double)>& mm) {
  const QFontMetricsF fm(f, p.device());
  const double symbol = mm(2.6), gap = mm(1.2);
  // The gaps between items close up (to 1.5 mm) before an item would be left out.
  double items_w = 0.0;
  for (const LegendItem& item : items) items_w += symbol * 1.5 + gap + fm.horizontalAdvance(item.text);
  const double room =
      items.size() > 1 ? (row.width() - items_w - mm(0.5)) / static_cast<double>(items.size() - 1) : mm(5.0);
  const double item_gap = std::clamp(room, mm(1.5), mm(5.0));
  double x = row.left();
  p.setFont(f);
  for (const LegendItem& item : items) {
    const double text_w = fm.horizontalAdvance(item.text);
    if (x + symbol * 1.5 + gap + text_w > row.right()) break;  // never past the row
    draw_mark(p, item.mark, QPointF(x + symbol * 0.75, row.center().y()), symbol, item.colour, item.fill);
    x += symbol * 1.5 + gap;
    p.setPen(colours::kText);
    p.drawText(QRectF(x, row.top(), text_w + mm(1), row.height()), Qt::AlignLeft | Qt::AlignVCenter, item.text);
    x += text_w + item_gap;
  }
}

void draw_station_ruler(QPainter& p, const Axis& x, double y, double step, const QFont& f,
                        const std::function<double(double)>& mm, bool with_caption) {
  const QFontMetricsF fm(f, p.device());
  const int decimals = decimals_for(step);
  p.setFont(f);
  p.setPen(QPen(QColor(60, 60, 60), mm(0.2)));
  p.drawLine(QPointF(x.p0, y), QPointF(x.p1, y));
  const QString caption = QStringLiteral("station (m)");
  const double caption_left = x.p1 - fm.horizontalAdvance(caption);
  double last_right = -1e18;
  for (double t : ticks(x.lo, x.hi, step)) {
    const double px = x.at(t);
    p.drawLine(QPointF(px, y), QPointF(px, y + mm(1.2)));
    const QString label = QString::number(t, 'f', decimals);
    const double w = fm.horizontalAdvance(label);
    const double left = px - 0.5 * w;
    if (left < last_right + mm(1.5)) continue;
    p.drawText(QRectF(left, y + mm(1.5), w, fm.height()), Qt::AlignCenter, label);
    last_right = left + w;
  }
  if (with_caption) {
    p.setPen(QColor(105, 105, 105));
    p.drawText(QRectF(caption_left, y + mm(1.5) + fm.height(), fm.horizontalAdvance(caption) + 1, fm.height()),
               Qt::AlignRight | Qt::AlignVCenter, caption);
  }
}

}  // namespace tunnelmap::report
