#include "ui/scene/tunnel_scene.h"

#include <vtkCaptionActor2D.h>
#include <vtkCellArray.h>
#include <vtkCoordinate.h>
#include <vtkPointData.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkTextProperty.h>

#include <algorithm>
#include <string>

#include "ui/scene/scene_colors.h"

namespace tunnelmap::scene {

namespace {
int idx(Layer l) { return static_cast<int>(l); }

vtkSmartPointer<vtkPolyData> square_symbol() {
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
  return poly;
}

void color_axis_label(vtkCaptionActor2D* caption) {
  caption->GetCaptionTextProperty()->SetColor(0.9, 0.9, 0.9);
  caption->GetCaptionTextProperty()->ShadowOff();
}
}  // namespace

TunnelScene::TunnelScene() {
  renderer_ = vtkSmartPointer<vtkRenderer>::New();
  renderer_->SetBackground(kBackground[0], kBackground[1], kBackground[2]);
  visible_.fill(true);

  actors_[idx(Layer::Cloud)] = make_actor(nullptr, 2.0, 1.0, true);
  actors_[idx(Layer::Mesh)] = make_actor(nullptr, 1.0, 1.0, false);
  actors_[idx(Layer::Planes)] = make_actor(nullptr, 3.0, 1.0, true);
  actors_[idx(Layer::Boundary)] = make_actor(&kBoundaryBlue, 1.0, 4.0, true);
  actors_[idx(Layer::Traversable)] = make_actor(&kTraversableRed, 1.0, 1.0, true);
  actors_[idx(Layer::Forbidden)] = make_actor(&kForbiddenAmber, 1.0, 1.0, true);
  actors_[idx(Layer::Frustum)] = make_actor(&kFrustumGrey, 1.0, 2.0, true);
  for (auto& a : actors_)
    if (a) renderer_->AddActor(a);
  // VTK pushes polygons back by a slope-scaled offset (factor 2) so that lines win over them;
  // seen at a grazing angle along a wall that offset reaches centimetres and the wall's own
  // points would hide its zones. Cancel it and pull zones slightly forward instead.
  for (Layer zones : {Layer::Traversable, Layer::Forbidden}) {
    auto* mapper = actors_[idx(zones)]->GetMapper();
    mapper->SetRelativeCoincidentTopologyPolygonOffsetParameters(-3.0, -3.0);
  }
  // Points are pulled forward by a depth offset that grows with distance; at a few metres it
  // exceeds the zones' 5 mm lift. Cancel it so geometry decides.
  for (Layer points : {Layer::Cloud, Layer::Planes})
    actors_[idx(points)]->GetMapper()->SetRelativeCoincidentTopologyPointOffsetParameter(2.0);

  axes_ = vtkSmartPointer<vtkAxesActor>::New();
  axes_->SetTotalLength(0.2, 0.2, 0.2);
  axes_->SetShaftTypeToLine();
  axes_->AxisLabelsOff();  // caption text scales badly at tunnel size
  axes_->SetConeRadius(0.3);
  // Pale axis colours: saturated red/blue are reserved for zones and boundary.
  axes_->GetXAxisShaftProperty()->SetColor(0.95, 0.6, 0.6);
  axes_->GetXAxisTipProperty()->SetColor(0.95, 0.6, 0.6);
  axes_->GetYAxisShaftProperty()->SetColor(0.6, 0.95, 0.6);
  axes_->GetYAxisTipProperty()->SetColor(0.6, 0.95, 0.6);
  axes_->GetZAxisShaftProperty()->SetColor(0.65, 0.65, 0.95);
  axes_->GetZAxisTipProperty()->SetColor(0.65, 0.65, 0.95);
  color_axis_label(axes_->GetXAxisCaptionActor2D());
  color_axis_label(axes_->GetYAxisCaptionActor2D());
  color_axis_label(axes_->GetZAxisCaptionActor2D());
  renderer_->AddActor(axes_);

  build_legend();
  clear();
}

vtkSmartPointer<vtkActor> TunnelScene::make_actor(const Rgb* color, double point_size,
                                                  double line_width, bool unlit) {
  auto mapper = vtkSmartPointer<vtkPolyDataMapper>::New();
  mapper->SetInputData(vtkSmartPointer<vtkPolyData>::New());
  if (color) {
    mapper->ScalarVisibilityOff();
  } else {
    mapper->SetColorModeToDirectScalars();
    mapper->ScalarVisibilityOn();
  }
  auto actor = vtkSmartPointer<vtkActor>::New();
  actor->SetMapper(mapper);
  vtkProperty* prop = actor->GetProperty();
  if (color) prop->SetColor((*color)[0], (*color)[1], (*color)[2]);
  prop->SetPointSize(point_size);
  prop->SetLineWidth(line_width);
  if (unlit) prop->LightingOff();  // exact colours, whatever the light
  return actor;
}

void TunnelScene::build_legend() {
  legend_ = vtkSmartPointer<vtkLegendBoxActor>::New();
  auto symbol = square_symbol();
  struct Entry {
    const char* text;
    Rgb color;
  };
  std::vector<Entry> entries;
  for (WallClass c : {WallClass::Left, WallClass::Right, WallClass::Top, WallClass::Bottom,
                      WallClass::Unassigned})
    entries.push_back({wall_class_label(c), wall_class_color(c)});
  entries.push_back({"boundary", kBoundaryBlue});
  entries.push_back({"traversable", kTraversableRed});
  entries.push_back({"forbidden", kForbiddenAmber});
  legend_->SetNumberOfEntries(static_cast<int>(entries.size()));
  for (std::size_t i = 0; i < entries.size(); ++i) {
    double c[3] = {entries[i].color[0], entries[i].color[1], entries[i].color[2]};
    // Leading spaces: the swatch is drawn over the start of the entry's text box.
    legend_->SetEntry(static_cast<int>(i), symbol, (std::string("  ") + entries[i].text).c_str(), c);
  }
  legend_->GetPositionCoordinate()->SetCoordinateSystemToNormalizedViewport();
  legend_->GetPositionCoordinate()->SetValue(0.84, 0.02);
  legend_->GetPosition2Coordinate()->SetCoordinateSystemToNormalizedViewport();
  legend_->GetPosition2Coordinate()->SetValue(0.15, 0.32);
  legend_->UseBackgroundOff();  // see set_legend_background()
  legend_->GetEntryTextProperty()->SetColor(0.95, 0.95, 0.95);
  legend_->GetEntryTextProperty()->ShadowOff();
  renderer_->AddViewProp(legend_);
}

void TunnelScene::set_legend_background(bool on) {
  legend_->SetUseBackground(on);
  legend_->SetBackgroundColor(kBackground[0], kBackground[1], kBackground[2]);
  legend_->SetBackgroundOpacity(0.9);
}

void TunnelScene::set_input(Layer layer, vtkPolyData* poly) {
  auto& actor = actors_[idx(layer)];
  actor->GetMapper()->SetInputDataObject(poly);
}

void TunnelScene::clear() {
  for (auto& a : actors_)
    if (a) a->GetMapper()->SetInputDataObject(vtkSmartPointer<vtkPolyData>::New());
  map_ = TunnelMap();
}

void TunnelScene::update(const SceneData& data, bool rebuild_cloud) {
  GeometryOptions options;
  options.max_points = max_points_;
  options.cloud = rebuild_cloud;
  set_geometry(build_geometry(data, options));
}

void TunnelScene::set_geometry(const SceneGeometry& g) {
  if (g.cloud) set_input(Layer::Cloud, g.cloud);
  set_input(Layer::Planes, g.planes);
  set_input(Layer::Boundary, g.boundary);
  set_input(Layer::Traversable, g.traversable);
  set_input(Layer::Forbidden, g.forbidden);
  set_input(Layer::Frustum, g.frustum);
  if (g.mesh) set_mesh(g.mesh);
  map_ = g.map;
  // Decimated point layers draw larger points so surfaces stay closed on screen.
  actors_[idx(Layer::Cloud)]->GetProperty()->SetPointSize(std::max(2, g.stride));
  actors_[idx(Layer::Planes)]->GetProperty()->SetPointSize(g.stride + 1);
}

void TunnelScene::set_mesh(vtkPolyData* mesh) {
  vtkSmartPointer<vtkPolyData> poly = mesh;
  if (!poly) poly = vtkSmartPointer<vtkPolyData>::New();
  set_input(Layer::Mesh, poly);
  // A mesh that carries colours shows them; otherwise a neutral grey.
  actors_[idx(Layer::Mesh)]->GetMapper()->SetScalarVisibility(poly->GetPointData()->GetScalars() != nullptr);
}

void TunnelScene::set_layer_visible(Layer layer, bool visible) {
  visible_[idx(layer)] = visible;
  if (layer == Layer::Axes)
    axes_->SetVisibility(visible);
  else if (layer == Layer::Legend)
    legend_->SetVisibility(visible);
  else
    actors_[idx(layer)]->SetVisibility(visible);
}

void TunnelScene::show_only(const std::vector<Layer>& layers) {
  for (Layer l : all_layers()) set_layer_visible(l, false);
  for (Layer l : layers) set_layer_visible(l, true);
}

vtkPolyData* TunnelScene::layer_polydata(Layer layer) const {
  const auto& actor = actors_[idx(layer)];
  return actor ? vtkPolyData::SafeDownCast(actor->GetMapper()->GetInputDataObject(0, 0)) : nullptr;
}

PixelBox TunnelScene::projected_boundary(int width, int height) const {
  PixelBox box;
  if (!map_.detected) return box;
  auto coord = vtkSmartPointer<vtkCoordinate>::New();
  coord->SetCoordinateSystemToWorld();
  for (const Wall& wall : map_.walls) {
    if (!wall.found) continue;
    for (const auto& c : wall.boundary) {
      if (!c.allFinite()) continue;
      coord->SetValue(c.x(), c.y(), c.z());
      const int* d = coord->GetComputedDisplayValue(renderer_);
      box.add(d[0], height - 1 - d[1]);
    }
  }
  if (box.count == 0) box = PixelBox();
  return box;
}

vtkIdType TunnelScene::layer_size(Layer layer) const {
  const auto& actor = actors_[idx(layer)];
  if (!actor) return 0;
  auto* poly = vtkPolyData::SafeDownCast(actor->GetMapper()->GetInputDataObject(0, 0));
  if (!poly) return 0;
  return layer == Layer::Cloud || layer == Layer::Planes ? poly->GetNumberOfPoints()
                                                          : poly->GetNumberOfCells();
}

}  // namespace tunnelmap::scene
