#pragma once
// The VTK part both meshers share: flying edges over a TSDF image and the copy of one contour
// vertex (position, normal towards free space, colour) into a TriangleMesh.
#include <vtkImageData.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>

#include <Eigen/Core>
#include <cstdint>
#include <functional>

#include "core/fusion/triangle_mesh.h"
#include "mesh/tsdf_mesher.h"

namespace tunnelmap {

// An image of `dims` samples wrapping the caller's buffers (not copied, not freed: they must
// outlive the image): "tsdf" scalars and 3-component "rgb".
vtkSmartPointer<vtkImageData> wrap_tsdf_image(const Eigen::Vector3i& dims, const Eigen::Vector3d& origin,
                                              double spacing, const float* tsdf, const std::uint8_t* rgb);

// The zero level set with gradient normals and interpolated colours.
vtkSmartPointer<vtkPolyData> zero_level_set(vtkImageData* image);

// Appends contour point `id` to `mesh`, its position mapped by `offset + scale * p`.
void append_contour_vertex(vtkPolyData* poly, vtkIdType id, const Eigen::Vector3d& offset, double scale,
                           TriangleMesh& mesh);

// What becomes of a contour triangle, by the cell it lies in.
enum class CellVerdict { Foreign, Unseen, Kept };  // another extraction's / dropped / kept

// Copies the contour's triangles whose cell (corner in sample units of `poly`'s image, which
// has its origin at 0 and spacing 1) `verdict` keeps into `mesh`, each vertex once, positions
// mapped by `offset + scale * p`; `on_new_vertex(id)` runs for each vertex added. Counts the
// kept and dropped ones in `stats` (foreign ones are not counted).
void copy_kept_triangles(vtkPolyData* poly, const std::function<CellVerdict(const Eigen::Vector3i&)>& verdict,
                         const Eigen::Vector3d& offset, double scale, TriangleMesh& mesh, MeshStats& stats,
                         const std::function<void(vtkIdType)>& on_new_vertex = nullptr);

}  // namespace tunnelmap
