#include "tests/support/girder_walk_config.h"

namespace tunnelmap::testing {

SimConfig girder_walk_config(double length_m, double spacing_m, int frames) {
  SimConfig c = SimConfig::from_preset("field");
  c.manhole_distances_m.clear();
  c.girder_length_m = length_m;
  c.diaphragm_spacing_m = spacing_m;
  c.frames = frames;
  SimWalk w;
  w.start_x_m = 0.5;
  w.end_x_m = length_m - 0.5;
  w.stops = frames;
  w.pose = SimCameraPose{0.0, 0.5, 0.0, 0.0, 0.0};
  w.through_openings = true;
  c.walk = w;
  return c;
}

}  // namespace tunnelmap::testing
