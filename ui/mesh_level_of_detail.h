#pragma once
// A long mesh for the 3D view (a fused 100 m girder has ~13 M triangles, more than a software
// renderer draws in a frame): cut into pieces along its longest axis, each kept at full
// resolution and decimated (VTK's vtkBinnedDecimation, colours averaged per bin). The view of a
// frame shows the pieces nearest its camera at full resolution, up to a triangle budget, and
// the others decimated, so that a redraw costs the same whatever the girder's length.
#include <Eigen/Geometry>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>

#include <functional>
#include <vector>

namespace tunnelmap::ui {

constexpr long long kLevelOfDetailMinTriangles = 1000000;  // smaller meshes are shown whole
constexpr double kLevelOfDetailPieceM = 0.5;       // piece length along the mesh's long axis
constexpr double kLevelOfDetailBinM = 0.12;        // decimation bin edge (far pieces)
constexpr long long kLevelOfDetailNearTriangles = 150000;  // full-resolution budget per view
constexpr double kLevelOfDetailLookAheadM = 1.2;  // full resolution first where the camera looks

struct MeshLevelOfDetail {
  int axis = 0;                           // the world axis the pieces follow
  std::vector<double> from_m, to_m;       // each piece's range along it
  std::vector<vtkSmartPointer<vtkPolyData>> full, coarse;  // world frame, float points, "RGB"
};

// Told the pieces cut so far and how many there are; false stops the work (cancelled).
using PieceProgress = std::function<bool(int done, int total)>;

// `mesh` itself when it has fewer than kLevelOfDetailMinTriangles triangles; else the
// decimated pieces as one polydata (the overview of the whole girder) carrying the pieces, for
// level_of_detail() to find. Normals are not kept (a moved mesh is lit from its faces). Null
// when `progress` returned false.
vtkSmartPointer<vtkPolyData> with_level_of_detail(vtkPolyData* mesh, const PieceProgress& progress = {});

// The pieces `mesh` carries, or null.
const MeshLevelOfDetail* level_of_detail(vtkPolyData* mesh);

// The pieces nearest the point kLevelOfDetailLookAheadM in front of the camera (along the
// axis) at full resolution while the budget lasts, the others decimated, as one polydata in
// the camera frame.
vtkSmartPointer<vtkPolyData> near_full_far_coarse(const MeshLevelOfDetail& lod, const Eigen::Isometry3d& world_to_camera);

}  // namespace tunnelmap::ui
