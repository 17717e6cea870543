#include "ui/mesh_level_of_detail.h"

#include <vtkBinnedDecimation.h>
#include <vtkCellArray.h>
#include <vtkFloatArray.h>
#include <vtkIdTypeArray.h>
#include <vtkInformation.h>
#include <vtkInformationObjectBaseKey.h>
#include <vtkObjectFactory.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkUnsignedCharArray.h>

#include <algorithm>
#include <cmath>
#include <numeric>

namespace tunnelmap::ui {

namespace {

// Holds the pieces in the mesh's own information, so they live and die with the polydata the
// view keeps.
class LevelOfDetailObject : public vtkObject {
 public:
  static LevelOfDetailObject* New();
  vtkTypeMacro(LevelOfDetailObject, vtkObject);
  MeshLevelOfDetail lod;
};
vtkStandardNewMacro(LevelOfDetailObject);

// Never deleted: polydata may outlive any static that would own it.
vtkInformationObjectBaseKey* level_of_detail_key() {
  static auto* key = new vtkInformationObjectBaseKey("LEVEL_OF_DETAIL", "tunnelmap::ui");
  return key;
}

// The triangles of `mesh` listed in `triangles` (point id triples) with their points and colours.
vtkSmartPointer<vtkPolyData> sub_mesh(vtkPolyData* mesh, const std::vector<vtkIdType>& triangles,
                                      std::vector<vtkIdType>& new_id) {
  vtkUnsignedCharArray* rgb = vtkUnsignedCharArray::SafeDownCast(mesh->GetPointData()->GetArray("RGB"));
  if (rgb && rgb->GetNumberOfComponents() != 3) rgb = nullptr;
  auto points = vtkSmartPointer<vtkPoints>::New();
  points->SetDataTypeToFloat();
  auto colors = vtkSmartPointer<vtkUnsignedCharArray>::New();
  colors->SetName("RGB");
  colors->SetNumberOfComponents(3);
  auto connectivity = vtkSmartPointer<vtkIdTypeArray>::New();
  connectivity->SetNumberOfValues(static_cast<vtkIdType>(triangles.size()));
  for (std::size_t i = 0; i < triangles.size(); ++i) {
    const vtkIdType old = triangles[i];
    if (new_id[static_cast<std::size_t>(old)] < 0) {
      new_id[static_cast<std::size_t>(old)] = points->InsertNextPoint(mesh->GetPoint(old));
      if (rgb) colors->InsertNextTypedTuple(rgb->GetPointer(3 * old));
    }
    connectivity->SetValue(static_cast<vtkIdType>(i), new_id[static_cast<std::size_t>(old)]);
  }
  for (const vtkIdType old : triangles) new_id[static_cast<std::size_t>(old)] = -1;  // for the next piece
  auto cells = vtkSmartPointer<vtkCellArray>::New();
  cells->SetData(3, connectivity);
  auto poly = vtkSmartPointer<vtkPolyData>::New();
  poly->SetPoints(points);
  poly->SetPolys(cells);
  if (rgb) poly->GetPointData()->SetScalars(colors);
  return poly;
}

vtkSmartPointer<vtkPolyData> decimated(vtkPolyData* piece) {
  auto filter = vtkSmartPointer<vtkBinnedDecimation>::New();
  filter->SetInputData(piece);
  double b[6];
  piece->GetBounds(b);
  int divisions[3];
  for (int k = 0; k < 3; ++k)
    divisions[k] = std::max(1, static_cast<int>(std::ceil((b[2 * k + 1] - b[2 * k]) / kLevelOfDetailBinM)));
  filter->AutoAdjustNumberOfDivisionsOff();  // the bins as given (and no log line per piece)
  filter->SetNumberOfDivisions(divisions);
  filter->SetPointGenerationModeToBinAverages();
  filter->ProducePointDataOn();
  filter->Update();
  return filter->GetOutput();
}

// Every triangle's point ids, by the piece its centroid falls in.
std::vector<std::vector<vtkIdType>> triangles_by_piece(vtkPolyData* mesh, int axis, double from, std::size_t pieces) {
  std::vector<std::vector<vtkIdType>> by_piece(pieces);
  vtkCellArray* polys = mesh->GetPolys();
  vtkIdType n = 0;
  const vtkIdType* ids = nullptr;
  for (polys->InitTraversal(); polys->GetNextCell(n, ids);) {
    if (n != 3) continue;
    double c = 0.0;
    for (int k = 0; k < 3; ++k) c += mesh->GetPoint(ids[k])[axis];
    const auto piece = static_cast<std::size_t>(
        std::clamp((c / 3.0 - from) / kLevelOfDetailPieceM, 0.0, double(pieces - 1)));
    by_piece[piece].insert(by_piece[piece].end(), ids, ids + 3);
  }
  return by_piece;
}

// Appends `piece`'s points (mapped by `T`), colours and triangles.
void append_moved(vtkPolyData* piece, const Eigen::Isometry3d& T, vtkPoints* points, vtkUnsignedCharArray* colors,
                  vtkIdTypeArray* connectivity) {
  const vtkIdType offset = points->GetNumberOfPoints();
  vtkUnsignedCharArray* rgb = vtkUnsignedCharArray::SafeDownCast(piece->GetPointData()->GetArray("RGB"));
  for (vtkIdType i = 0; i < piece->GetNumberOfPoints(); ++i) {
    double p[3];
    piece->GetPoint(i, p);
    const Eigen::Vector3d q = T * Eigen::Vector3d(p[0], p[1], p[2]);
    points->InsertNextPoint(q.data());
    if (rgb) {
      unsigned char c[3];
      for (int k = 0; k < 3; ++k) c[k] = static_cast<unsigned char>(rgb->GetComponent(i, k));
      colors->InsertNextTypedTuple(c);
    } else {
      const unsigned char grey[3] = {180, 180, 180};
      colors->InsertNextTypedTuple(grey);
    }
  }
  vtkCellArray* polys = piece->GetPolys();
  vtkIdType n = 0;
  const vtkIdType* ids = nullptr;
  for (polys->InitTraversal(); polys->GetNextCell(n, ids);)
    if (n == 3)
      for (int k = 0; k < 3; ++k) connectivity->InsertNextValue(ids[k] + offset);
}

vtkSmartPointer<vtkPolyData> joined(const std::vector<vtkPolyData*>& pieces, const Eigen::Isometry3d& T) {
  auto points = vtkSmartPointer<vtkPoints>::New();
  points->SetDataTypeToFloat();
  auto colors = vtkSmartPointer<vtkUnsignedCharArray>::New();
  colors->SetName("RGB");
  colors->SetNumberOfComponents(3);
  auto connectivity = vtkSmartPointer<vtkIdTypeArray>::New();
  for (vtkPolyData* p : pieces) append_moved(p, T, points, colors, connectivity);
  auto cells = vtkSmartPointer<vtkCellArray>::New();
  cells->SetData(3, connectivity);
  auto poly = vtkSmartPointer<vtkPolyData>::New();
  poly->SetPoints(points);
  poly->SetPolys(cells);
  poly->GetPointData()->SetScalars(colors);
  return poly;
}

}  // namespace

vtkSmartPointer<vtkPolyData> with_level_of_detail(vtkPolyData* mesh, const PieceProgress& progress) {
  if (!mesh || mesh->GetNumberOfPolys() < kLevelOfDetailMinTriangles) return mesh;
  double b[6];
  mesh->GetBounds(b);
  auto holder = vtkSmartPointer<LevelOfDetailObject>::New();
  MeshLevelOfDetail& lod = holder->lod;
  for (int k = 1; k < 3; ++k)
    if (b[2 * k + 1] - b[2 * k] > b[2 * lod.axis + 1] - b[2 * lod.axis]) lod.axis = k;
  const double from = b[2 * lod.axis];
  const auto pieces =
      static_cast<std::size_t>(std::max(1.0, std::ceil((b[2 * lod.axis + 1] - from) / kLevelOfDetailPieceM)));
  const std::vector<std::vector<vtkIdType>> by_piece = triangles_by_piece(mesh, lod.axis, from, pieces);
  std::vector<vtkIdType> new_id(static_cast<std::size_t>(mesh->GetNumberOfPoints()), -1);
  std::vector<vtkPolyData*> overview;
  for (std::size_t i = 0; i < pieces; ++i) {
    if (progress && !progress(static_cast<int>(i), static_cast<int>(pieces))) return nullptr;
    if (by_piece[i].empty()) continue;
    lod.from_m.push_back(from + double(i) * kLevelOfDetailPieceM);
    lod.to_m.push_back(lod.from_m.back() + kLevelOfDetailPieceM);
    lod.full.push_back(sub_mesh(mesh, by_piece[i], new_id));
    lod.coarse.push_back(decimated(lod.full.back()));
    overview.push_back(lod.coarse.back());
  }
  vtkSmartPointer<vtkPolyData> out = joined(overview, Eigen::Isometry3d::Identity());
  out->GetInformation()->Set(level_of_detail_key(), holder);
  return out;
}

const MeshLevelOfDetail* level_of_detail(vtkPolyData* mesh) {
  if (!mesh) return nullptr;
  auto* holder = LevelOfDetailObject::SafeDownCast(mesh->GetInformation()->Get(level_of_detail_key()));
  return holder ? &holder->lod : nullptr;
}

vtkSmartPointer<vtkPolyData> near_full_far_coarse(const MeshLevelOfDetail& lod, const Eigen::Isometry3d& world_to_camera) {
  const Eigen::Vector3d looked_at = world_to_camera.inverse() * Eigen::Vector3d(0.0, 0.0, kLevelOfDetailLookAheadM);
  const double at = looked_at[lod.axis];
  std::vector<std::size_t> order(lod.full.size());
  std::iota(order.begin(), order.end(), std::size_t(0));
  auto distance = [&](std::size_t i) { return std::max({0.0, lod.from_m[i] - at, at - lod.to_m[i]}); };
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return distance(a) < distance(b); });
  std::vector<vtkPolyData*> shown;
  long long budget = kLevelOfDetailNearTriangles;
  for (std::size_t i : order) {
    const long long triangles = lod.full[i]->GetNumberOfPolys();
    const bool full = triangles <= budget;
    if (full) budget -= triangles;
    else budget = 0;  // nearer pieces first: once one is decimated, so are all farther ones
    shown.push_back(full ? lod.full[i] : lod.coarse[i]);
  }
  return joined(shown, world_to_camera);
}

}  // namespace tunnelmap::ui
