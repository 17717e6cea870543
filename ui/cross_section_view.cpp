#include "ui/cross_section_view.h"

#include <QMouseEvent>
#include <QPainter>
#include <QPainterPath>
#include <algorithm>
#include <cmath>

#include "ui/scene/scene_colors.h"

namespace tunnelmap::ui {

namespace {
constexpr int kMargin = 36;         // room for the grid labels
constexpr int kMinCaptionHeight = 56;  // room for three lines under the drawing
constexpr double kSnapPx = 12.0;

QColor qcolor(const scene::Rgb& c, int alpha = 255) {
  return QColor::fromRgbF(c[0], c[1], c[2], alpha / 255.0);
}
}  // namespace

CrossSectionView::CrossSectionView(QWidget* parent) : QWidget(parent) {
  setMinimumSize(200, 200);
  setFocusPolicy(Qt::ClickFocus);
  setToolTip(tr("Click two points to measure their distance; a third click starts again"));
}

void CrossSectionView::set_section(const CrossSection& section) {
  section_ = section;
  picks_.clear();
  fit();
  update();
}

void CrossSectionView::clear() { set_section(CrossSection()); }

int CrossSectionView::caption_height() const {
  // As many lines as the caption wraps to in this width (a narrow dock wraps each line in two).
  const QRect needed = QFontMetrics(font()).boundingRect(QRect(0, 0, std::max(10, width() - 16), 10000),
                                                         Qt::AlignLeft | Qt::TextWordWrap, caption());
  return std::max(kMinCaptionHeight, needed.height() + 6);
}

QRectF CrossSectionView::plot_rect() const {
  return QRectF(kMargin, 8, std::max(10, width() - kMargin - 12), std::max(10, height() - 8 - kMargin - caption_height()));
}

void CrossSectionView::fit() {
  // The fitted (and design) rectangle with 15 % room, else the points' extent.
  double x0 = -0.6, x1 = 0.6, y0 = -0.8, y1 = 0.8;
  auto include = [&](const SectionRect& r) {
    x0 = std::min(x0, r.left), x1 = std::max(x1, r.right), y0 = std::min(y0, r.bottom), y1 = std::max(y1, r.top);
  };
  if (section_.fitted) {
    x0 = section_.fitted->left, x1 = section_.fitted->right, y0 = section_.fitted->bottom, y1 = section_.fitted->top;
    if (section_.design) include(*section_.design);
  } else if (!section_.points.empty()) {
    x0 = y0 = 1e9, x1 = y1 = -1e9;
    for (const SectionPoint& p : section_.points)
      x0 = std::min(x0, p.at.x()), x1 = std::max(x1, p.at.x()), y0 = std::min(y0, p.at.y()), y1 = std::max(y1, p.at.y());
  }
  const double pad = 0.15 * std::max(x1 - x0, y1 - y0) + 0.02;
  x0 -= pad, x1 += pad, y0 -= pad, y1 += pad;
  const QRectF area = plot_rect();
  scale_ = std::min(area.width() / (x1 - x0), area.height() / (y1 - y0));  // equal on both axes
  const double cx = 0.5 * (x0 + x1), cy = 0.5 * (y0 + y1);
  origin_ = QPointF(area.center().x() - cx * scale_, area.center().y() + cy * scale_);
}

void CrossSectionView::resizeEvent(QResizeEvent*) { fit(); }

QPointF CrossSectionView::to_widget(const Eigen::Vector2d& at) const {
  return QPointF(origin_.x() + at.x() * scale_, origin_.y() - at.y() * scale_);
}

Eigen::Vector2d CrossSectionView::to_section(const QPointF& pixel) const {
  return {(pixel.x() - origin_.x()) / scale_, (origin_.y() - pixel.y()) / scale_};
}

std::optional<double> CrossSectionView::measured_m() const {
  if (picks_.size() < 2) return std::nullopt;
  return (picks_[1] - picks_[0]).norm();
}

void CrossSectionView::clear_picks() {
  picks_.clear();
  update();
}

void CrossSectionView::mousePressEvent(QMouseEvent* e) {
  if (e->button() != Qt::LeftButton) return QWidget::mousePressEvent(e);
  // Snap to the nearest section point; a click far from every point picks where it landed.
  Eigen::Vector2d at = to_section(e->pos());
  double best = kSnapPx;
  for (const SectionPoint& p : section_.points) {
    const QPointF w = to_widget(p.at);
    const double d = std::hypot(w.x() - e->pos().x(), w.y() - e->pos().y());
    if (d < best) best = d, at = p.at;
  }
  if (picks_.size() >= 2) picks_.clear();
  picks_.push_back(at);
  if (auto m = measured_m()) emit measured(*m);
  update();
}

namespace {

QString metres(std::optional<double> v) { return v ? QString::number(*v, 'f', 3) + " m" : QObject::tr("–"); }

// A deviation only of a value measured in the cut, or of the frame's measured or context value;
// a value filled from the design is labelled so, never "0.0 mm" off.
QString deviation(std::optional<double> cut, double fitted, DimensionSource source, double design) {
  if (cut) return QObject::tr("%1 mm").arg((*cut - design) * 1000.0, 0, 'f', 1);
  if (source == DimensionSource::Design) return QObject::tr("from design");
  if (source == DimensionSource::Unseen) return QObject::tr("unknown");
  return QObject::tr("%1 mm (frame fit)").arg((fitted - design) * 1000.0, 0, 'f', 1);
}

}  // namespace

// The size is the cut's own (its walls' points in the slab); the frame's fitted rectangle, drawn
// too, is named as such: across a change of section the two differ.
QString CrossSectionView::caption() const {
  QString s = tr("%1 m ahead, slab \u00b1%2 mm, %3 points")
                  .arg(section_.station_m, 0, 'f', 2)
                  .arg(section_.half_thickness_m * 1000.0, 0, 'f', 0)
                  .arg(section_.points.size());
  s += tr("\ncut: width %1, height %2").arg(metres(section_.cut_width_m), metres(section_.cut_height_m));
  if (!section_.fitted)
    return s + (section_.no_fit_reason.empty()
                    ? tr("\nno fitted rectangle")
                    : tr("\nno fitted rectangle: %1").arg(QString::fromStdString(section_.no_fit_reason)));
  s += tr("\nframe fit: %1 \u00d7 %2 m").arg(section_.fitted->width(), 0, 'f', 3).arg(section_.fitted->height(), 0, 'f', 3);
  if (section_.design) {
    s += tr("\ndesign %1 \u00d7 %2 m: width %3, height %4")
             .arg(section_.design->width(), 0, 'f', 3)
             .arg(section_.design->height(), 0, 'f', 3)
             .arg(deviation(section_.cut_width_m, section_.fitted->width(), section_.width_source,
                            section_.design->width()))
             .arg(deviation(section_.cut_height_m, section_.fitted->height(), section_.height_source,
                            section_.design->height()));
  }
  return s;
}

void CrossSectionView::paintEvent(QPaintEvent*) {
  QPainter p(this);
  p.fillRect(rect(), qcolor(scene::kBackground));
  p.setRenderHint(QPainter::Antialiasing, true);
  const QRectF area = plot_rect();

  // Grid every 0.1 m, labelled every 0.5 m, or every 1 or 2 m where labels would touch.
  p.setFont(QFont(font().family(), 8));
  const Eigen::Vector2d lo = to_section(area.bottomLeft()), hi = to_section(area.topRight());
  const double px_per_tenth = std::abs(to_widget({0.1, 0}).x() - to_widget({0, 0}).x());
  int every = 5;  // tenths of a metre between labels
  while (every < 20 && every * px_per_tenth < 34) every *= 2;
  for (int k = static_cast<int>(std::ceil(lo.x() * 10)); k <= static_cast<int>(std::floor(hi.x() * 10)); ++k) {
    const double x = to_widget({k / 10.0, 0}).x();
    p.setPen(QPen(QColor(255, 255, 255, k % 5 == 0 ? 70 : 28), 1));
    p.drawLine(QPointF(x, area.top()), QPointF(x, area.bottom()));
    if (k % every == 0) {
      p.setPen(QColor(200, 200, 200));
      p.drawText(QRectF(x - 30, area.bottom() + 2, 60, 14), Qt::AlignCenter, QString::number(k / 10.0, 'f', 1));
    }
  }
  for (int k = static_cast<int>(std::ceil(lo.y() * 10)); k <= static_cast<int>(std::floor(hi.y() * 10)); ++k) {
    const double y = to_widget({0, k / 10.0}).y();
    p.setPen(QPen(QColor(255, 255, 255, k % 5 == 0 ? 70 : 28), 1));
    p.drawLine(QPointF(area.left(), y), QPointF(area.right(), y));
    if (k % (every * px_per_tenth < 16 ? 2 * every : every) == 0) {
      p.setPen(QColor(200, 200, 200));
      p.drawText(QRectF(0, y - 7, kMargin - 4, 14), Qt::AlignRight | Qt::AlignVCenter, QString::number(k / 10.0, 'f', 1));
    }
  }
  p.setPen(QColor(200, 200, 200));
  p.drawText(QRectF(area.right() - 120, area.bottom() + 16, 120, 14), Qt::AlignRight, tr("across (m), right \u2192"));

  p.setBrush(Qt::NoBrush);
  auto rect_of = [&](const SectionRect& r) {
    return QRectF(to_widget({r.left, r.top}), to_widget({r.right, r.bottom}));
  };
  if (section_.design) {
    p.setPen(QPen(QColor(235, 235, 235), 1.5, Qt::DashLine));
    p.drawRect(rect_of(*section_.design));
  }
  if (section_.fitted) {
    p.setPen(QPen(qcolor(scene::kBoundaryBlue), 2.0));
    p.drawRect(rect_of(*section_.fitted));
  }
  // Points, by wall class, over the rectangles: the data stays visible where it meets them.
  p.setPen(Qt::NoPen);
  for (const SectionPoint& pt : section_.points) {
    p.setBrush(qcolor(scene::wall_class_color(pt.cls)));
    p.drawEllipse(to_widget(pt.at), 1.4, 1.4);
  }
  p.setBrush(Qt::NoBrush);

  // The measurement.
  if (!picks_.empty()) {
    p.setPen(QPen(QColor(255, 255, 255), 2));
    p.setBrush(QColor(255, 255, 255));
    for (const auto& at : picks_) p.drawEllipse(to_widget(at), 3.5, 3.5);
    if (auto m = measured_m()) {
      const QPointF a = to_widget(picks_[0]), b = to_widget(picks_[1]);
      p.drawLine(a, b);
      p.setFont(QFont(font().family(), 10, QFont::Bold));
      const QString text = tr("%1 mm").arg(*m * 1000.0, 0, 'f', 1);
      const QPointF mid = (a + b) / 2 + QPointF(6, -6);
      p.setPen(QColor(0, 0, 0));
      p.drawText(mid + QPointF(1, 1), text);
      p.setPen(QColor(255, 255, 255));
      p.drawText(mid, text);
    }
  }

  p.setFont(font());
  p.setPen(QColor(230, 230, 230));
  const int caption_h = caption_height();
  p.drawText(QRectF(8, height() - caption_h, width() - 16, caption_h),
             Qt::AlignLeft | Qt::AlignVCenter | Qt::TextWordWrap, caption());
}

}  // namespace tunnelmap::ui
