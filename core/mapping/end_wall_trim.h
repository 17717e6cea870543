#pragma once
// No girder lies beyond its end wall. A station there is made by the wall's corner: the side
// walls' samples reach the end wall, and a few millimetres of pose error along the girder put
// the last of them past it, into a station of their own, "measured".
#include <array>
#include <vector>

#include "core/mapping/station_map.h"

namespace tunnelmap {

// Drops the stations whose bin lies wholly beyond an end wall of `map.girder` (its first or last
// plate of kind "end_wall") and ends the sections at the stations kept; a section wholly beyond
// goes, with its entry of `section_walls` (one per section; std::logic_error otherwise). The
// sections' sizes and frame counts are left as they were (a corner's station or two among
// many). Whether anything was dropped: the girder's compartments and centreline are then to be
// found again.
bool trim_beyond_end_walls(StationMap& map, std::vector<std::array<double, 4>>& section_walls);

}  // namespace tunnelmap
