#include "ui/scene/tunnel_scene.h"

#include <vtkStringArray.h>

#include <vtkCallbackCommand.h>
#include <vtkCaptionActor2D.h>
#include <vtkCellArray.h>
#include <vtkCoordinate.h>
#include <vtkLabeledDataMapper.h>
#include <vtkLightKit.h>
#include <vtkPointData.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkStringArray.h>
#include <vtkTextProperty.h>

#include <algorithm>
#include <string>

#include "ui/scene/dimension_labels.h"
#include "ui/scene/scene_colors.h"

namespace tunnelmap::scene {

namespace {
int idx(Layer l) { return static_cast<int>(l); }

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
  actors_[idx(Layer::Grid)] = make_actor(&kGridGrey, 1.0, 1.5, true);
  for (auto& a : actors_)
    if (a) renderer_->AddActor(a);
  // Zones are translucent fills: the wall's points stay visible through them.
  for (Layer zones : {Layer::Traversable, Layer::Forbidden})
    actors_[idx(zones)]->GetProperty()->SetOpacity(kZoneFillOpacity);
  add_zone_outlines();
  grid_labels_ = add_labels(kLegendText, 16);
  dimension_labels_ = add_labels(kLegendText, 18);
  measurement_label_ = add_labels(kMeasureWhite, 18);
  measurement_actor_ = make_actor(&kMeasureWhite, 9.0, 3.0, true);
  // Always in front: a measurement is read, not hidden by the surface it lies on.
  measurement_actor_->GetMapper()->SetRelativeCoincidentTopologyLineOffsetParameters(0, -66000);
  measurement_actor_->GetMapper()->SetRelativeCoincidentTopologyPointOffsetParameter(-66000);
  measurement_actor_->GetProperty()->RenderPointsAsSpheresOn();
  renderer_->AddActor(measurement_actor_);
  actors_[idx(Layer::Grid)]->GetMapper()->SetRelativeCoincidentTopologyLineOffsetParameters(-2.0, -20.0);
  // A key, fill and back light: a mesh seen at a grazing angle stays readable (lit layers only;
  // points, zones and lines are drawn unlit in their exact colours).
  auto kit = vtkSmartPointer<vtkLightKit>::New();
  kit->AddLightsToRenderer(renderer_);
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

  legend_ = std::make_unique<SceneLegend>(renderer_);
  // The legend's box is sized in pixels: refit it to the viewport before every render.
  auto fit = vtkSmartPointer<vtkCallbackCommand>::New();
  fit->SetClientData(this);
  fit->SetCallback([](vtkObject* caller, unsigned long, void* self, void*) {
    auto* renderer = static_cast<vtkRenderer*>(caller);
    auto* scene = static_cast<TunnelScene*>(self);
    const int* size = renderer->GetSize();
    scene->legend_->fit(size[0], size[1], scene->label_boxes());
  });
  fit_observer_ = renderer_->AddObserver(vtkCommand::StartEvent, fit);
  clear();
  refresh_visibility();
}

TunnelScene::~TunnelScene() { renderer_->RemoveObserver(fit_observer_); }

void TunnelScene::add_zone_outlines() {
  auto outline = [&](Layer zones, const Rgb& color) {
    auto mapper = vtkSmartPointer<vtkPolyDataMapper>::New();
    mapper->SetInputDataObject(actors_[idx(zones)]->GetMapper()->GetInputDataObject(0, 0));
    mapper->ScalarVisibilityOff();
    mapper->SetRelativeCoincidentTopologyLineOffsetParameters(-3.0, -6.0);
    auto actor = vtkSmartPointer<vtkActor>::New();
    actor->SetMapper(mapper);
    vtkProperty* prop = actor->GetProperty();
    prop->SetRepresentationToWireframe();  // a quad's wireframe is its outline
    prop->SetColor(color[0], color[1], color[2]);
    prop->SetLineWidth(2.5f);  // pixels, whatever the distance
    prop->LightingOff();
    renderer_->AddActor(actor);
    return actor;
  };
  traversable_outline_ = outline(Layer::Traversable, kTraversableRed);
  forbidden_outline_ = outline(Layer::Forbidden, kForbiddenAmber);
}

// Where the visible text labels (distance grid, width and height) are on screen, so that the
// legend can keep clear of them. Their extent is estimated from the text, about 0.6 of the font
// size per character, on either side of the point (whichever way the mapper justifies it).
std::vector<ScreenBox> TunnelScene::label_boxes() const {
  std::vector<ScreenBox> boxes;
  for (const vtkSmartPointer<vtkActor2D>& actor : {grid_labels_, dimension_labels_}) {
    if (!actor->GetVisibility()) continue;
    auto* mapper = static_cast<vtkLabeledDataMapper*>(actor->GetMapper());
    auto* poly = vtkPolyData::SafeDownCast(mapper->GetInputDataObject(0, 0));
    auto* text = poly ? vtkStringArray::SafeDownCast(poly->GetPointData()->GetAbstractArray("label")) : nullptr;
    if (!text) continue;
    const double font = mapper->GetLabelTextProperty()->GetFontSize();
    for (vtkIdType i = 0; i < poly->GetNumberOfPoints(); ++i) {
      double p[3];
      poly->GetPoint(i, p);
      renderer_->SetWorldPoint(p[0], p[1], p[2], 1.0);
      renderer_->WorldToDisplay();
      const double* d = renderer_->GetDisplayPoint();
      if (d[2] < 0.0 || d[2] > 1.0) continue;  // behind the camera or clipped: not drawn
      const double half_w = 0.6 * font * static_cast<double>(text->GetValue(i).size()) + 4.0, half_h = 1.2 * font;
      boxes.push_back({d[0] - half_w, d[1] - half_h, d[0] + half_w, d[1] + half_h});
    }
  }
  return boxes;
}

vtkSmartPointer<vtkActor2D> TunnelScene::add_labels(const Rgb& color, int font_size) {
  auto mapper = vtkSmartPointer<vtkLabeledDataMapper>::New();
  mapper->SetInputDataObject(vtkSmartPointer<vtkPolyData>::New());
  mapper->SetLabelModeToLabelFieldData();
  mapper->SetFieldDataName("label");
  vtkTextProperty* text = mapper->GetLabelTextProperty();
  text->SetColor(color[0], color[1], color[2]);
  text->SetFontSize(font_size);  // pixels: the same size at any distance
  text->ShadowOn();              // readable over the wall's points
  text->BoldOn();
  auto actor = vtkSmartPointer<vtkActor2D>::New();
  actor->SetMapper(mapper);
  renderer_->AddActor2D(actor);
  return actor;
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

std::optional<Eigen::Vector3d> TunnelScene::pick_at(double x, double y) {
  const auto p = pick_point(renderer_, x, y);
  if (p) {
    std::vector<Measurement> all = measurements_;
    add_pick(all, *p);
    set_measurements(all);
  }
  return p;
}

const Measurement& TunnelScene::measurement() const {
  static const Measurement none;
  return measurements_.empty() ? none : measurements_.back();
}

void TunnelScene::set_measurements(const std::vector<Measurement>& measurements) {
  measurements_ = measurements;
  measurement_actor_->GetMapper()->SetInputDataObject(measurement_polydata(measurements_));
  measurement_label_->GetMapper()->SetInputDataObject(measurement_label(measurements_));
}

void TunnelScene::set_legend_background(bool on) { legend_->set_background(on); }

void TunnelScene::set_input(Layer layer, vtkPolyData* poly) {
  auto& actor = actors_[idx(layer)];
  actor->GetMapper()->SetInputDataObject(poly);
  if (layer == Layer::Traversable) traversable_outline_->GetMapper()->SetInputDataObject(poly);
  if (layer == Layer::Forbidden) forbidden_outline_->GetMapper()->SetInputDataObject(poly);
}

void TunnelScene::clear() {
  for (Layer l : all_layers())
    if (actors_[idx(l)]) set_input(l, vtkSmartPointer<vtkPolyData>::New());
  grid_labels_->GetMapper()->SetInputDataObject(vtkSmartPointer<vtkPolyData>::New());
  dimension_labels_->GetMapper()->SetInputDataObject(vtkSmartPointer<vtkPolyData>::New());
  set_measurements({});
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
  set_input(Layer::Grid, g.grid ? g.grid.Get() : vtkSmartPointer<vtkPolyData>::New().Get());
  grid_labels_->GetMapper()->SetInputDataObject(g.grid_labels ? g.grid_labels.Get()
                                                              : vtkSmartPointer<vtkPolyData>::New().Get());
  if (g.mesh) set_mesh(g.mesh);
  map_ = g.map;
  // Two labels, built here: which ones depends on the view (dimension_labels.h).
  dimension_labels_->GetMapper()->SetInputDataObject(make_dimension_labels(map_, view_));
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
  // Some ambient light: faces turned from every light do not go black.
  actors_[idx(Layer::Mesh)]->GetProperty()->SetAmbient(0.35);
  actors_[idx(Layer::Mesh)]->GetProperty()->SetDiffuse(0.75);
}

void TunnelScene::set_layer_visible(Layer layer, bool visible) {
  visible_[idx(layer)] = visible;
  refresh_visibility();
}

bool TunnelScene::layer_shown(Layer layer) const {
  if ((layer == Layer::Frustum || layer == Layer::Axes) && view_ == ViewPreset::Along) return false;
  return visible_[idx(layer)];
}

void TunnelScene::refresh_visibility() {
  for (Layer l : all_layers())
    if (actors_[idx(l)]) actors_[idx(l)]->SetVisibility(layer_shown(l));
  traversable_outline_->SetVisibility(layer_shown(Layer::Traversable));
  forbidden_outline_->SetVisibility(layer_shown(Layer::Forbidden));
  grid_labels_->SetVisibility(layer_shown(Layer::Grid));
  dimension_labels_->SetVisibility(layer_shown(Layer::Boundary));
  axes_->SetVisibility(layer_shown(Layer::Axes));
  legend_->set_visible(layer_shown(Layer::Legend));
  legend_->set_layers({layer_shown(Layer::Planes), layer_shown(Layer::Boundary), layer_shown(Layer::Traversable),
                       layer_shown(Layer::Forbidden)});
}

void TunnelScene::apply_view(ViewPreset view) {
  view_ = view;
  refresh_visibility();
  dimension_labels_->GetMapper()->SetInputDataObject(make_dimension_labels(map_, view_));
  scene::apply_view(renderer_, view, map_);
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
