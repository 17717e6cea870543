#include "ui/depth_view_widget.h"

#include <QMouseEvent>
#include <QPainter>
#include <algorithm>
#include <cmath>
#include <unordered_map>
#include <vector>

#include "ui/scene/scene_colors.h"

namespace tunnelmap::ui {

DepthViewWidget::DepthViewWidget(QWidget* parent) : QWidget(parent) {
  setMouseTracking(true);
  setMinimumSize(240, 180);
}

void DepthViewWidget::clear() {
  frame_.reset();
  image_ = QImage();
  update();
}

QImage depth_label_image(const scene::ProcessedFrame& processed) {
  const DepthFrame& f = processed.frame;
  QImage image(f.width, f.height, QImage::Format_RGB888);
  float lo = INFINITY, hi = -INFINITY;
  for (float d : f.depth)
    if (d > 0 && std::isfinite(d)) lo = std::min(lo, d), hi = std::max(hi, d);
  const float span = hi > lo ? hi - lo : 1.0f;
  const PlaneSegments& planes = processed.result.planes;
  const bool labels = planes.labels.size() == f.depth.size();
  std::unordered_map<int, scene::Rgb> colour;
  for (std::size_t k = 0; k < planes.planes.size(); ++k) {
    WallClass c = k < processed.result.map.plane_classes.size() ? processed.result.map.plane_classes[k]
                                                                 : WallClass::Unassigned;
    colour[planes.planes[k].id] = scene::wall_class_color(c);
  }
  for (int v = 0; v < f.height; ++v) {
    uchar* line = image.scanLine(v);
    for (int u = 0; u < f.width; ++u) {
      const std::size_t i = static_cast<std::size_t>(v) * f.width + u;
      const float d = f.depth[i];
      double g = (d > 0 && std::isfinite(d)) ? 0.25 + 0.75 * (1.0 - (d - lo) / span) : 0.0;
      double rgb[3] = {g, g, g};
      if (labels && planes.labels[i] > 0) {
        auto it = colour.find(planes.labels[i]);
        if (it != colour.end())
          for (int k = 0; k < 3; ++k) rgb[k] = 0.45 * g + 0.55 * it->second[k];  // tinted overlay
      }
      for (int k = 0; k < 3; ++k) line[u * 3 + k] = static_cast<uchar>(std::clamp(rgb[k], 0.0, 1.0) * 255);
    }
  }
  return image;
}

void DepthViewWidget::show_frame(std::shared_ptr<const scene::ProcessedFrame> processed, QImage image) {
  frame_ = std::move(processed);
  if (!frame_) return clear();
  image_ = image.isNull() ? depth_label_image(*frame_) : std::move(image);
  update();
}

QRect DepthViewWidget::image_rect() const {
  if (image_.isNull()) return {};
  QSize s = image_.size().scaled(size(), Qt::KeepAspectRatio);
  return QRect(QPoint((width() - s.width()) / 2, (height() - s.height()) / 2), s);
}

void DepthViewWidget::paintEvent(QPaintEvent*) {
  QPainter p(this);
  p.fillRect(rect(), QColor(30, 30, 34));
  if (image_.isNull()) {
    p.setPen(Qt::gray);
    p.drawText(rect().adjusted(8, 8, -8, -8), Qt::AlignCenter | Qt::TextWordWrap,
               tr("Open a depth PNG, PCD, dataset folder or folder of depth PNGs"));
    return;
  }
  p.drawImage(image_rect(), image_);
  if (picked_pixels_.empty()) return;
  p.setRenderHint(QPainter::Antialiasing, true);
  p.setPen(QPen(Qt::white, 2));
  p.setBrush(Qt::white);
  for (const QPoint& uv : picked_pixels_) p.drawEllipse(QPointF(widget_point(uv.x(), uv.y())), 3.5, 3.5);
  p.setFont(QFont(font().family(), 10, QFont::Bold));
  // Measurement k's picks are picked_pixels_[2k] and [2k + 1].
  for (std::size_t k = 0; k < measurements_.size() && 2 * k + 1 < picked_pixels_.size(); ++k) {
    if (!measurements_[k].distance_m()) continue;
    const QPoint a = widget_point(picked_pixels_[2 * k].x(), picked_pixels_[2 * k].y());
    const QPoint b = widget_point(picked_pixels_[2 * k + 1].x(), picked_pixels_[2 * k + 1].y());
    p.setPen(QPen(Qt::white, 2));
    p.drawLine(a, b);
    const QString text = QString::fromStdString(measurements_[k].label());
    const QPoint mid = (a + b) / 2 + QPoint(6, -6);
    p.setPen(Qt::black);
    p.drawText(mid + QPoint(1, 1), text);
    p.setPen(Qt::white);
    p.drawText(mid, text);
  }
}

QPoint DepthViewWidget::widget_point(int u, int v) const {
  const QRect r = image_rect();
  if (r.isEmpty()) return {};
  return QPoint(r.x() + static_cast<int>((u + 0.5) * r.width() / image_.width()),
                r.y() + static_cast<int>((v + 0.5) * r.height() / image_.height()));
}

void DepthViewWidget::set_measuring(bool on) {
  measuring_ = on;
  setCursor(on ? Qt::CrossCursor : Qt::ArrowCursor);
}

const scene::Measurement& DepthViewWidget::measurement() const {
  static const scene::Measurement none;
  return measurements_.empty() ? none : measurements_.back();
}

void DepthViewWidget::clear_measurement() {
  if (picked_pixels_.empty()) return;
  measurements_.clear();
  picked_pixels_.clear();
  update();
  emit measurementChanged(QString());
}

bool DepthViewWidget::pick_pixel(int u, int v) {
  if (!frame_) return false;
  const OrganizedCloud& c = frame_->result.cloud;
  // The clicked pixel, else the nearest one with a point within 3 px (depth has holes).
  int best_u = -1, best_v = -1, best_r2 = 1 << 30;
  for (int dv = -3; dv <= 3; ++dv)
    for (int du = -3; du <= 3; ++du) {
      const int uu = u + du, vv = v + dv;
      if (uu < 0 || vv < 0 || uu >= c.width || vv >= c.height) continue;
      if (!OrganizedCloud::valid(c.points[c.index(uu, vv)])) continue;
      if (du * du + dv * dv < best_r2) best_r2 = du * du + dv * dv, best_u = uu, best_v = vv;
    }
  if (best_u < 0) return false;
  scene::add_pick(measurements_, c.points[c.index(best_u, best_v)].cast<double>());
  picked_pixels_.push_back(QPoint(best_u, best_v));
  update();
  const scene::Measurement& last = measurements_.back();
  emit measurementChanged(last.distance_m() ? QString::fromStdString(last.label()) : tr("first point picked"));
  return true;
}

void DepthViewWidget::mousePressEvent(QMouseEvent* e) {
  const QRect r = image_rect();
  if (!measuring_ || e->button() != Qt::LeftButton || r.isEmpty() || !r.contains(e->pos()))
    return QWidget::mousePressEvent(e);
  pick_pixel((e->pos().x() - r.x()) * image_.width() / r.width(), (e->pos().y() - r.y()) * image_.height() / r.height());
}

QString DepthViewWidget::describe_pixel(int u, int v) const {
  if (!frame_ || u < 0 || v < 0 || u >= frame_->frame.width || v >= frame_->frame.height) return {};
  const DepthFrame& f = frame_->frame;
  const std::size_t i = static_cast<std::size_t>(v) * f.width + u;
  const float d = f.depth[i];
  QString text = tr("u %1, v %2: ").arg(u).arg(v);
  text += (d > 0 && std::isfinite(d)) ? tr("depth %1 m").arg(f.depth_m(u, v), 0, 'f', 3) : tr("no depth");
  const PlaneSegments& planes = frame_->result.planes;
  if (planes.labels.size() == f.depth.size() && planes.labels[i] > 0) {
    const int id = planes.labels[i];
    QString cls = "unassigned";
    for (std::size_t k = 0; k < planes.planes.size(); ++k)
      if (planes.planes[k].id == id && k < frame_->result.map.plane_classes.size())
        cls = scene::wall_class_label(frame_->result.map.plane_classes[k]);
    text += tr(", plane %1 (%2)").arg(id).arg(cls);
  }
  return text;
}

void DepthViewWidget::mouseMoveEvent(QMouseEvent* e) {
  const QRect r = image_rect();
  if (r.isEmpty() || !r.contains(e->pos())) return;
  const int u = (e->pos().x() - r.x()) * image_.width() / r.width();
  const int v = (e->pos().y() - r.y()) * image_.height() / r.height();
  const QString text = describe_pixel(u, v);
  setToolTip(text);
  emit hovered(text);
}

}  // namespace tunnelmap::ui
