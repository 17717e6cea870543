#include "ui/scene/tunnel_scene.h"

#include <vtkCaptionActor2D.h>
#include <vtkCellArray.h>
#include <vtkPointData.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkTextProperty.h>

#include "ui/scene/cloud_polydata.h"
#include "ui/scene/frustum_polydata.h"
#include "ui/scene/scene_colors.h"
#include "ui/scene/tunnel_polydata.h"

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
    legend_->SetEntry(static_cast<int>(i), symbol, entries[i].text, c);
  }
  legend_->GetPositionCoordinate()->SetCoordinateSystemToNormalizedViewport();
  legend_->GetPositionCoordinate()->SetValue(0.84, 0.02);
  legend_->GetPosition2Coordinate()->SetCoordinateSystemToNormalizedViewport();
  legend_->GetPosition2Coordinate()->SetValue(0.15, 0.32);
  legend_->UseBackgroundOff();
  legend_->GetEntryTextProperty()->SetColor(0.95, 0.95, 0.95);
  legend_->GetEntryTextProperty()->ShadowOff();
  renderer_->AddViewProp(legend_);
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
  if (rebuild_cloud) set_input(Layer::Cloud, make_cloud_polydata(data));
  set_input(Layer::Planes, make_planes_polydata(data));
  set_input(Layer::Mesh, data.mesh ? data.mesh.Get() : vtkSmartPointer<vtkPolyData>::New().Get());
  map_ = data.map ? *data.map : TunnelMap();
  set_input(Layer::Boundary, make_boundary_polydata(map_));
  set_input(Layer::Traversable, make_zones_polydata(map_, ZoneKind::Traversable));
  set_input(Layer::Forbidden, make_zones_polydata(map_, ZoneKind::Forbidden));
  Intrinsics k = data.frame ? data.frame->intrinsics
                            : (data.cloud ? data.cloud->intrinsics : Intrinsics::primesense_vga());
  set_input(Layer::Frustum, make_frustum_polydata(k, 0.3));
  if (data.mesh) {
    // A mesh that carries colours shows them; otherwise a neutral grey.
    auto* mapper = actors_[idx(Layer::Mesh)]->GetMapper();
    mapper->SetScalarVisibility(data.mesh->GetPointData()->GetScalars() != nullptr);
  }
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

vtkIdType TunnelScene::layer_size(Layer layer) const {
  const auto& actor = actors_[idx(layer)];
  if (!actor) return 0;
  auto* poly = vtkPolyData::SafeDownCast(actor->GetMapper()->GetInputDataObject(0, 0));
  if (!poly) return 0;
  return layer == Layer::Cloud || layer == Layer::Planes ? poly->GetNumberOfPoints()
                                                          : poly->GetNumberOfCells();
}

}  // namespace tunnelmap::scene
