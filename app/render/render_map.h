#pragma once
// `tunnelmap-render DATASET --map`: the station map of a posed dataset (the same map as
// `tunnelmap-cli map`), drawn as its swept section rectangles; with `--mesh FILE` the fused mesh
// is the surface and the map lies over it as the outlines of its zones.
#include <vtkPolyData.h>
#include <vtkRenderer.h>

#include "app/render/render_options.h"

namespace tunnelmap::render {

int run_station_map(const RenderOptions& opt);

// Adds the outlines of `zones` (the map's zone triangles) in the zones' colours, lines of constant
// screen width pulled towards the camera: the mesh they lie on stays visible; shown only while
// `visible`.
void add_zone_outlines(vtkRenderer* renderer, vtkPolyData* zones, bool visible);

}  // namespace tunnelmap::render
