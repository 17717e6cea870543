#pragma once
// The scene's legend: one entry per colour on screen, only for the layers shown, in a box sized
// in pixels (rows of 16-20 px) so that its text stays readable however small the view is.
// VTK's legend box scales its text to the box; a box that is a fixed fraction of the view made
// 6 px text in a small window.
#include <vtkLegendBoxActor.h>
#include <vtkRenderer.h>
#include <vtkSmartPointer.h>

namespace tunnelmap::scene {

struct LegendLayers {
  bool planes = false, boundary = false, traversable = false, forbidden = false;
};

class SceneLegend {
 public:
  explicit SceneLegend(vtkRenderer* renderer);

  void set_layers(const LegendLayers& shown);
  void set_visible(bool visible);
  void set_background(bool on);
  // Places the box in the lower-right corner of a `width` x `height` viewport (pixels), or in
  // the upper-right one when the view is too narrow for it to clear the width label.
  void fit(int width, int height);
  bool at_top() const { return at_top_; }

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
  bool at_top_ = false;
};

// Row height of the legend for a viewport `height` pixels high.
int legend_row_px(int height);

}  // namespace tunnelmap::scene
