#pragma once
// A distance grid on the tunnel floor (the roof when no floor was found): a line across the
// wall every `step_m` along the axis, labelled with its distance ahead of the camera every
// `label_every` lines. Drawn in perspective it gives every view a true scale, which a 2D scale
// bar cannot (its length would hold at one depth only).
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>

#include "core/tunnel/tunnel_map.h"

namespace tunnelmap::scene {

struct StationGrid {
  vtkSmartPointer<vtkPolyData> lines;   // one line cell per station
  vtkSmartPointer<vtkPolyData> labels;  // one vertex per labelled station, string array "label"
};

// In the map's frame, whose origin is the camera (the per-frame scene). Empty polydata when the
// map has no floor or roof, or when it is not detected.
StationGrid make_station_grid(const TunnelMap& map, double step_m = 0.5, int label_every = 2);

}  // namespace tunnelmap::scene
