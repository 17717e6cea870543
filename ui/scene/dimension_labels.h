#pragma once
// The tunnel's width and height written on its boundary, half way along the visible extent: the
// width on the floor (the roof without a floor) left of its middle, the height on the left wall
// (the right one without it). Left-justified text, so it runs into the tunnel. A dimension from the context or the design says so ("width 0.820 m (context)").
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>

#include "core/tunnel/tunnel_map.h"
#include "ui/scene/camera_presets.h"

namespace tunnelmap::scene {

// One vertex per label with the string array "label"; empty when the map is not detected. A
// dimension that runs along `view`'s line of sight is left out: seen from the top the height
// edge shrinks to a point and its text sat on the width's, and seen from the side the width's.
vtkSmartPointer<vtkPolyData> make_dimension_labels(const TunnelMap& map, ViewPreset view = ViewPreset::Along);

}  // namespace tunnelmap::scene
