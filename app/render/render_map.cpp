#include "app/render/render_map.h"

#include <unistd.h>

#include <vtkActor.h>
#include <vtkActorCollection.h>
#include <vtkFeatureEdges.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>

#include <filesystem>
#include <iostream>

#include "app/render/map_mesh.h"
#include "app/render/mesh_view.h"
#include "app/render/osmesa_window.h"
#include "core/export/map_ply.h"
#include "core/io/dataset.h"
#include "core/io/ply_mesh_reader.h"
#include "core/mapping/dataset_mapping.h"
#include "core/util/error.h"
#include "ui/scene/mesh_polydata.h"
#include "ui/scene/tunnel_scene.h"

namespace tunnelmap::render {

namespace {

// The map goes through a PLY so that it is drawn exactly as `map --ply` files are; the folder
// is removed whatever happens.
class TempFolder {
 public:
  TempFolder()
      : path_(std::filesystem::temp_directory_path() / ("tunnelmap-render-" + std::to_string(getpid()))) {
    std::filesystem::create_directories(path_);
  }
  ~TempFolder() {
    std::error_code ec;
    std::filesystem::remove_all(path_, ec);
  }
  std::string file(const std::string& name) const { return (path_ / name).string(); }

 private:
  std::filesystem::path path_;
};

MapMesh station_map_mesh(const RenderOptions& opt, StationMap* summary) {
  const Dataset ds = read_dataset(opt.in.input, opt.in.read_options());
  Pipeline pipeline = opt.in.pipeline();
  const DatasetMapping dm = map_dataset(ds, pipeline, !opt.no_pose_refinement);
  const StationMap& m = dm.mapped.stations;
  if (!m.ok || m.section_maps.empty()) throw InputError(opt.in.input, "no map to draw: " + m.reason);
  *summary = m;
  TempFolder tmp;
  const std::string ply = tmp.file("map.ply");
  write_sectioned_map_ply(ply, m.section_maps, pipeline.params().to_json(), plate_outlines(m));
  return load_map_mesh(ply, opt.cutaway);
}

void cull_back_faces(vtkRenderer* renderer, vtkPolyData* mesh) {
  vtkActorCollection* actors = renderer->GetActors();
  actors->InitTraversal();
  while (vtkActor* actor = actors->GetNextActor())
    if (actor->GetMapper() && actor->GetMapper()->GetInputDataObject(0, 0) == mesh)
      actor->GetProperty()->BackfaceCullingOn();
}

}  // namespace

void add_zone_outlines(vtkRenderer* renderer, vtkPolyData* zones, bool visible) {
  if (!zones || zones->GetNumberOfCells() == 0) return;
  auto edges = vtkSmartPointer<vtkFeatureEdges>::New();
  edges->SetInputData(zones);
  edges->BoundaryEdgesOn();
  edges->FeatureEdgesOff();
  edges->ManifoldEdgesOff();
  edges->NonManifoldEdgesOff();
  edges->ColoringOff();  // keep the zones' own colours
  auto mapper = vtkSmartPointer<vtkPolyDataMapper>::New();
  mapper->SetInputConnection(edges->GetOutputPort());
  mapper->SetColorModeToDirectScalars();
  mapper->SetRelativeCoincidentTopologyLineOffsetParameters(-2.0, -60.0);
  auto actor = vtkSmartPointer<vtkActor>::New();
  actor->SetMapper(mapper);
  actor->GetProperty()->SetLineWidth(3.0f);  // screen pixels: readable at any distance
  actor->GetProperty()->SetLighting(false);
  actor->SetVisibility(visible);
  renderer->AddActor(actor);
}

int run_station_map(const RenderOptions& opt) {
  if (is_mesh_input(opt.in.input))
    throw ParameterError("--map draws the map of a posed dataset; a PLY is drawn as it is, without --map");
  StationMap stations;
  const MapMesh map = station_map_mesh(opt, &stations);
  std::size_t mesh_triangles = 0;
  vtkSmartPointer<vtkPolyData> fused;
  if (!opt.mesh.empty()) {
    const PlyMesh mesh = read_ply_mesh(opt.mesh);
    if (mesh.triangles.empty()) throw InputError(opt.mesh, "has no triangles to show (expected a fused mesh PLY)");
    fused = scene::mesh_polydata(mesh);
    mesh_triangles = mesh.triangles.size();
  }

  OsMesaWindow window(opt.width, opt.height);
  scene::TunnelScene scene;
  scene::SceneGeometry geometry;
  for (auto* layer : {&geometry.cloud, &geometry.planes, &geometry.boundary, &geometry.traversable,
                      &geometry.forbidden, &geometry.frustum})
    *layer = vtkSmartPointer<vtkPolyData>::New();
  geometry.mesh = fused ? fused : map.poly;
  geometry.map = map.frame;
  scene.set_geometry(geometry);
  scene.show_only(opt.layers.empty() ? std::vector<scene::Layer>{scene::Layer::Mesh} : opt.layers);
  const bool mesh_visible = scene.layer_visible(scene::Layer::Mesh);
  if (fused) {
    add_zone_outlines(scene.renderer(), map.poly, mesh_visible);
    // Faces turned away are culled: from outside, the near walls open onto the far ones' insides.
    cull_back_faces(scene.renderer(), fused);
  } else {
    add_boundary_bands(scene.renderer(), map.boundary, mesh_visible);
  }
  light_mesh(scene.renderer(), geometry.mesh);
  window.add_renderer(scene.renderer());
  scene.apply_view(opt.view);
  if (opt.view == scene::ViewPreset::Side || opt.view == scene::ViewPreset::Top)
    scene::fit_view_to_map(scene.renderer(), map.frame);
  const scene::RgbImage image = window.render();
  scene::save_png(image, opt.screenshot);

  std::cout << opt.screenshot << ": " << image.width << "x" << image.height << ", view "
            << scene::view_name(opt.view) << ", station map " << stations.stations.size() << " stations, "
            << stations.sections.size() << " section(s) over "
            << stations.sections.back().to_m - stations.sections.front().from_m << " m";
  if (fused) std::cout << ", fused mesh " << mesh_triangles << " triangles";
  const scene::PixelBox box = projected_box(scene.renderer(), map.poly, image.width, image.height);
  if (box.count > 0) std::cout << ", map box " << box.x0 << "," << box.y0 << " " << box.x1 << "," << box.y1;
  std::cout << "\n";
  return 0;
}

}  // namespace tunnelmap::render
