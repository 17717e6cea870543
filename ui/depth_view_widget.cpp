#include "ui/depth_view_widget.h"

#include <QMouseEvent>
#include <QPainter>
#include <algorithm>
#include <cmath>
#include <unordered_map>

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
    p.drawText(rect(), Qt::AlignCenter, tr("Open a depth PNG, PCD or dataset folder"));
    return;
  }
  p.drawImage(image_rect(), image_);
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
