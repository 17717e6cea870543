#pragma once
// The 2D view: the depth image (grey, near = bright) with the plane label overlay coloured by
// wall class. Hovering reports depth and plane id at the pixel under the cursor.
#include <QImage>
#include <QWidget>
#include <vector>

#include "ui/scene/measurement.h"
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

  // Measure tool (View > Measure in 3D, shared with the 3D view): while on, a left click picks
  // the 3D point of the clicked pixel (the nearest pixel with depth within 3 px); two picks
  // give their distance in space, drawn over the image. As in the 3D view, the next pick
  // starts another measurement and the earlier ones stay drawn until cleared.
  void set_measuring(bool on);
  bool measuring() const { return measuring_; }
  bool pick_pixel(int u, int v);  // what a click on pixel (u, v) does; false without depth
  const scene::Measurement& measurement() const;  // the latest (empty if none)
  const std::vector<scene::Measurement>& measurements() const { return measurements_; }  // oldest first
  void clear_measurement();  // all of them
  QPoint widget_point(int u, int v) const;  // the centre of pixel (u, v) on screen

 signals:
  void hovered(const QString& text);
  void measurementChanged(const QString& text);  // "1234.5 mm", "first point picked", ""

 protected:
  void paintEvent(QPaintEvent*) override;
  void mouseMoveEvent(QMouseEvent* e) override;
  void mousePressEvent(QMouseEvent* e) override;

 private:
  QRect image_rect() const;

  QImage image_;
  std::shared_ptr<const scene::ProcessedFrame> frame_;
  bool measuring_ = false;
  std::vector<scene::Measurement> measurements_;
  std::vector<QPoint> picked_pixels_;  // (u, v) of each pick of every measurement, in order
};

}  // namespace tunnelmap::ui
