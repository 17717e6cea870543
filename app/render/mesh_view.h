#pragma once
// How tunnelmap-render shows a mesh: lighting that reaches every face, and where the mesh lands
// in the image (for the summary line and the tests).
#include <vtkPolyData.h>
#include <vtkRenderer.h>

#include "ui/scene/image_checks.h"

namespace tunnelmap::render {

// A key, fill, back and head light (vtkLightKit) instead of the single headlight, and some
// ambient light on the actor drawing `mesh`: walls seen at a grazing angle (inside the tunnel)
// stay readable instead of going black.
void light_mesh(vtkRenderer* renderer, vtkPolyData* mesh);

// Adds the map's boundary bands as their own actor, pulled towards the camera so the zones they
// share a plane with never hide them; shown only while `visible`.
void add_boundary_bands(vtkRenderer* renderer, vtkPolyData* bands, bool visible);

// Pixel box (top row 0) of the mesh's points as the renderer's camera projects them into a
// `width` x `height` image; count = number of points.
scene::PixelBox projected_box(vtkRenderer* renderer, vtkPolyData* mesh, int width, int height);

}  // namespace tunnelmap::render
