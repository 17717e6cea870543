#include "ui/scene/scene_geometry.h"

#include "ui/scene/cloud_polydata.h"
#include "ui/scene/frustum_polydata.h"
#include "ui/scene/station_grid.h"
#include "ui/scene/tunnel_polydata.h"

namespace tunnelmap::scene {

SceneGeometry build_geometry(const SceneData& data, const GeometryOptions& options) {
  SceneGeometry g;
  g.stride = data.cloud ? display_stride(data.cloud->width, data.cloud->height, options.max_points) : 1;
  if (options.cloud) g.cloud = make_cloud_polydata(data, g.stride);
  g.planes = make_planes_polydata(data, g.stride);
  g.mesh = data.mesh;
  if (data.map) g.map = *data.map;
  g.boundary = make_boundary_polydata(g.map);
  g.traversable = make_zones_polydata(g.map, ZoneKind::Traversable);
  g.forbidden = make_zones_polydata(g.map, ZoneKind::Forbidden);
  const StationGrid grid = make_station_grid(g.map);
  g.grid = grid.lines;
  g.grid_labels = grid.labels;
  const Intrinsics k = data.frame ? data.frame->intrinsics
                                  : (data.cloud ? data.cloud->intrinsics : Intrinsics::primesense_vga());
  g.frustum = make_frustum_polydata(k, 0.3);
  return g;
}

}  // namespace tunnelmap::scene
