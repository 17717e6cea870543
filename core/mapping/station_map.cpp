#include "core/mapping/station_map.h"

namespace tunnelmap {

std::vector<const Station*> StationMap::out_of_tolerance() const {
  std::vector<const Station*> out;
  for (const Station& s : stations)
    if (s.out_of_tolerance) out.push_back(&s);
  return out;
}

}  // namespace tunnelmap
