#pragma once
// A hand-built processed frame for UI tests that must not depend on the pipeline's numbers:
// a camera on the axis of an ideal box tunnel (width x height, along +z), its depth image,
// cloud, one plane per wall with labels, and a TunnelMap with boundary and zones.
#include "ui/scene/processed_frame.h"

namespace tunnelmap::test {

scene::ProcessedFrame make_synthetic_tunnel(double width_m = 1.0, double height_m = 0.8,
                                            double length_m = 3.0);

}  // namespace tunnelmap::test
