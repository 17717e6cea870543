#pragma once
// A whole girder walked through its manholes, as `simulate --girder L --diaphragm-spacing S`
// draws it: the field preset without its manhole plate, one stop per frame from 0.5 m to
// L - 0.5 m.
#include "core/sim/sim_config.h"

namespace tunnelmap::testing {

SimConfig girder_walk_config(double length_m, double spacing_m, int frames);

}  // namespace tunnelmap::testing
