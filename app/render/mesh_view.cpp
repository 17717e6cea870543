#include "app/render/mesh_view.h"

#include <vtkActor.h>
#include <vtkCoordinate.h>
#include <vtkActorCollection.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkLightKit.h>
#include <vtkSmartPointer.h>

#include <algorithm>

namespace tunnelmap::render {

namespace {
constexpr double kAmbient = 0.35, kDiffuse = 0.75;

void soften(vtkActor* actor) {
  actor->GetProperty()->SetAmbient(kAmbient);
  actor->GetProperty()->SetDiffuse(kDiffuse);
}
}  // namespace

void light_mesh(vtkRenderer* renderer, vtkPolyData* mesh) {
  renderer->RemoveAllLights();
  auto kit = vtkSmartPointer<vtkLightKit>::New();
  kit->SetKeyLightIntensity(0.9);
  kit->AddLightsToRenderer(renderer);
  vtkActorCollection* actors = renderer->GetActors();
  actors->InitTraversal();
  while (vtkActor* actor = actors->GetNextActor())
    if (actor->GetMapper() && actor->GetMapper()->GetInputDataObject(0, 0) == mesh) soften(actor);
}

void add_boundary_bands(vtkRenderer* renderer, vtkPolyData* bands, bool visible) {
  if (!bands || bands->GetNumberOfCells() == 0) return;
  auto mapper = vtkSmartPointer<vtkPolyDataMapper>::New();
  mapper->SetInputData(bands);
  mapper->SetColorModeToDirectScalars();
  mapper->SetRelativeCoincidentTopologyPolygonOffsetParameters(-2.0, -40.0);
  auto actor = vtkSmartPointer<vtkActor>::New();
  actor->SetMapper(mapper);
  soften(actor);
  actor->SetVisibility(visible);
  renderer->AddActor(actor);
}

scene::PixelBox projected_box(vtkRenderer* renderer, vtkPolyData* mesh, int width, int height) {
  scene::PixelBox box;
  if (!mesh || mesh->GetNumberOfPoints() == 0) return box;
  auto coord = vtkSmartPointer<vtkCoordinate>::New();
  coord->SetCoordinateSystemToWorld();
  for (vtkIdType i = 0; i < mesh->GetNumberOfPoints(); ++i) {
    double p[3];
    mesh->GetPoint(i, p);
    coord->SetValue(p);
    const int* d = coord->GetComputedDisplayValue(renderer);
    box.add(d[0], height - 1 - d[1]);
  }
  return box;
}

}  // namespace tunnelmap::render
