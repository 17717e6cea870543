#pragma once
// What to rescan along the girder: stretches of stations whose width or height no frame
// measured (filled from the neighbouring stations or the design, or unseen). A stretch matters
// when a whole section could hide in it (at least the shortest section long) or when a joint
// the map placed between views lies in it: its position is then only known to the stretch.
// Past a plate a forward-looking camera sees the roof and floor beside it only from 1-2 m on,
// so such stretches are where the robot must look again (docs/tunnel-map.md, "What to rescan").
#include <string>
#include <vector>

#include "core/mapping/station_map.h"

namespace tunnelmap {

enum class StationDimension { Width, Height };
const char* station_dimension_name(StationDimension d);  // "width", "height"

struct RescanStretch {
  double from_m = 0.0, to_m = 0.0;  // the unmeasured stations' bins, first start to last end
  StationDimension dimension = StationDimension::Height;  // the one no frame measured there
  bool joint_inside = false;  // a joint placed between views lies in it
  std::string reason;         // one line for people
};

// Width stretches and height stretches, in order of `from_m`.
std::vector<RescanStretch> rescan_stretches(const StationMap& map);

}  // namespace tunnelmap
