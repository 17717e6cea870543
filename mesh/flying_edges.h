#pragma once
// The VTK part both meshers share: flying edges over a TSDF image and the copy of one contour
// vertex (position, normal towards free space, colour) into a TriangleMesh.
#include <vtkImageData.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>

#include <Eigen/Core>
#include <cstdint>

#include "core/fusion/triangle_mesh.h"

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

// The corner (lowest sample) of the cell holding the triangle, in the image's sample units.
Eigen::Vector3i triangle_cell(vtkPolyData* poly, const vtkIdType* ids, const Eigen::Vector3d& origin,
                              double spacing);

}  // namespace tunnelmap
