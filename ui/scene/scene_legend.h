#pragma once
// The scene's legend: one entry per colour on screen, only for the layers shown, in a box sized
// in pixels (rows of 16-20 px) so that its text stays readable however small the view is.
// VTK's legend box scales its text to the box; a box that is a fixed fraction of the view made
// 6 px text in a small window.
#include <vtkLegendBoxActor.h>
#include <vtkRenderer.h>
#include <vtkSmartPointer.h>

#include <vector>

namespace tunnelmap::scene {

// A text label's extent on screen, in display pixels (origin lower-left).
struct ScreenBox {
  double x0 = 0, y0 = 0, x1 = 0, y1 = 0;
  bool overlaps(const ScreenBox& o) const { return x0 < o.x1 && o.x0 < x1 && y0 < o.y1 && o.y0 < y1; }
};

struct LegendLayers {
  bool planes = false, boundary = false, traversable = false, forbidden = false;
};

class SceneLegend {
 public:
  explicit SceneLegend(vtkRenderer* renderer);

  void set_layers(const LegendLayers& shown);
  void set_visible(bool visible);
  void set_background(bool on);
  // Places the box in a corner of a `width` x `height` viewport (pixels): the one that covers
  // the fewest of `labels`; among equals the lower-right, or the upper-right when the view is
  // too narrow for the box to clear the width label, then the left corners.
  void fit(int width, int height, const std::vector<ScreenBox>& labels = {});
  bool at_top() const { return at_top_; }
  bool at_left() const { return at_left_; }
  ScreenBox box() const { return box_; }  // after the last fit()

  int entries() const { return actor_->GetNumberOfEntries(); }
  vtkLegendBoxActor* actor() const { return actor_; }
  // The box's pixel size after the last fit().
  int box_width() const { return box_w_; }
  int box_height() const { return box_h_; }

 private:
  void refresh_visibility();

  vtkSmartPointer<vtkLegendBoxActor> actor_;
  bool visible_ = true;
  int box_w_ = 0, box_h_ = 0;
  bool at_top_ = false, at_left_ = false;
  ScreenBox box_;
};

// Row height of the legend for a viewport `height` pixels high.
int legend_row_px(int height);

}  // namespace tunnelmap::scene
