#include "ui/scene/scene_legend.h"

#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkTextProperty.h>
#include <vtkUnsignedCharArray.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "ui/scene/scene_colors.h"

namespace tunnelmap::scene {

namespace {
// A square swatch coloured through its own cell scalars, so the entry's text can stay white
// (blue text on the dark background was hard to read).
vtkSmartPointer<vtkPolyData> square_symbol(const Rgb& color) {
  auto points = vtkSmartPointer<vtkPoints>::New();
  points->InsertNextPoint(0, 0, 0);
  points->InsertNextPoint(1, 0, 0);
  points->InsertNextPoint(1, 1, 0);
  points->InsertNextPoint(0, 1, 0);
  auto polys = vtkSmartPointer<vtkCellArray>::New();
  const vtkIdType quad[] = {0, 1, 2, 3};
  polys->InsertNextCell(4, quad);
  auto poly = vtkSmartPointer<vtkPolyData>::New();
  poly->SetPoints(points);
  poly->SetPolys(polys);
  auto rgb = vtkSmartPointer<vtkUnsignedCharArray>::New();
  rgb->SetNumberOfComponents(3);
  rgb->InsertNextTuple3(color[0] * 255.0, color[1] * 255.0, color[2] * 255.0);
  poly->GetCellData()->SetScalars(rgb);
  return poly;
}
}  // namespace

int legend_row_px(int height) { return std::clamp(static_cast<int>(std::lround(height * 0.022)), 16, 20); }

SceneLegend::SceneLegend(vtkRenderer* renderer) {
  actor_ = vtkSmartPointer<vtkLegendBoxActor>::New();
  actor_->GetPositionCoordinate()->SetCoordinateSystemToNormalizedViewport();
  actor_->GetPosition2Coordinate()->SetCoordinateSystemToNormalizedViewport();
  actor_->UseBackgroundOff();  // see set_background()
  actor_->ScalarVisibilityOn();  // swatches take their own colour, text the entry's
  actor_->GetEntryTextProperty()->SetColor(kLegendText[0], kLegendText[1], kLegendText[2]);
  actor_->GetEntryTextProperty()->ShadowOff();
  renderer->AddViewProp(actor_);
  set_layers(LegendLayers{true, true, true, true});
  fit(1280, 720);
}

void SceneLegend::set_layers(const LegendLayers& shown) {
  struct Entry {
    const char* text;
    Rgb color;
  };
  std::vector<Entry> entries;
  if (shown.planes)
    for (WallClass c : {WallClass::Left, WallClass::Right, WallClass::Top, WallClass::Bottom,
                        WallClass::Unassigned})
      entries.push_back({wall_class_label(c), wall_class_color(c)});
  if (shown.boundary) entries.push_back({"boundary", kBoundaryBlue});
  if (shown.traversable) entries.push_back({"traversable", kTraversableRed});
  if (shown.forbidden) entries.push_back({"forbidden", kForbiddenAmber});
  actor_->SetNumberOfEntries(static_cast<int>(entries.size()));
  for (std::size_t i = 0; i < entries.size(); ++i) {
    double text_color[3] = {kLegendText[0], kLegendText[1], kLegendText[2]};
    // Leading spaces: the swatch is drawn over the start of the entry's text box.
    actor_->SetEntry(static_cast<int>(i), square_symbol(entries[i].color),
                     (std::string("  ") + entries[i].text).c_str(), text_color);
  }
  refresh_visibility();
}

void SceneLegend::set_visible(bool visible) {
  visible_ = visible;
  refresh_visibility();
}

void SceneLegend::refresh_visibility() { actor_->SetVisibility(visible_ && entries() > 0); }

void SceneLegend::set_background(bool on) {
  actor_->SetUseBackground(on);
  actor_->SetBackgroundColor(kBackground[0], kBackground[1], kBackground[2]);
  actor_->SetBackgroundOpacity(0.9);
}

void SceneLegend::fit(int width, int height, const std::vector<ScreenBox>& labels) {
  if (width <= 0 || height <= 0) return;
  constexpr int kMargin = 8;
  const int row = legend_row_px(height);
  box_w_ = std::min(width / 2, row * 8);  // "unassigned" plus its swatch
  box_h_ = std::min(height - kMargin, row * std::max(1, entries()) + 6);
  // The width label sits at the middle of the floor's edge, about 150 px wide: in a view
  // narrower than twice the box plus that, a box in the lower-right corner would cover it.
  const bool top_first = width < 2 * box_w_ + 200;
  const bool corners[4][2] = {{top_first, false}, {!top_first, false}, {false, true}, {true, true}};  // {top, left}
  int fewest = -1;
  for (const auto& c : corners) {
    const double x0 = c[1] ? kMargin : width - kMargin - box_w_;
    const double y0 = c[0] ? height - kMargin - box_h_ : kMargin;
    const ScreenBox candidate{x0, y0, x0 + box_w_, y0 + box_h_};
    int covered = 0;
    for (const ScreenBox& label : labels) covered += candidate.overlaps(label);
    if (fewest >= 0 && covered >= fewest) continue;
    fewest = covered, at_top_ = c[0], at_left_ = c[1], box_ = candidate;
  }
  actor_->GetPositionCoordinate()->SetValue(box_.x0 / width, box_.y0 / height);
  actor_->GetPosition2Coordinate()->SetValue(static_cast<double>(box_w_) / width, static_cast<double>(box_h_) / height);
}

}  // namespace tunnelmap::scene
