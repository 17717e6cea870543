#pragma once
// The 2D view: the depth image (grey, near = bright) with the plane label overlay coloured by
// wall class. Hovering reports depth and plane id at the pixel under the cursor.
#include <QImage>
#include <QWidget>

#include "ui/scene/processed_frame.h"

namespace tunnelmap::ui {

// The depth image with the label overlay; any thread (QImage only, no widgets).
QImage depth_label_image(const scene::ProcessedFrame& processed);

class DepthViewWidget : public QWidget {
  Q_OBJECT
 public:
  explicit DepthViewWidget(QWidget* parent = nullptr);

  // `image` from depth_label_image() (built off the GUI thread); null: built here.
  void show_frame(std::shared_ptr<const scene::ProcessedFrame> processed, QImage image = {});
  void clear();
  const QImage& image() const { return image_; }
  // "u 120, v 80: depth 1.234 m, plane 3 (left)" or empty outside the image.
  QString describe_pixel(int u, int v) const;

 signals:
  void hovered(const QString& text);

 protected:
  void paintEvent(QPaintEvent*) override;
  void mouseMoveEvent(QMouseEvent* e) override;

 private:
  QRect image_rect() const;

  QImage image_;
  std::shared_ptr<const scene::ProcessedFrame> frame_;
};

}  // namespace tunnelmap::ui
