#pragma once
// girder_poses.csv of the whole-girder evaluation: every frame's pose against the truth, one
// row per frame of every girder, to see where along a girder the map bends (the report's
// distributions say how much, not where).
#include <string>
#include <vector>

#include "core/evaluation/girder_protocol.h"

namespace tunnelmap {

// Header: girder,drifted,frame,station_m,error_mm,along_mm,across_mm,vertical_mm,rotation_deg,
// roll_deg,pitch_deg,heading_deg (see FramePoseError); the parts along, across and vertically
// are empty where the girder's frame is unknown. A girder scored without true poses has no rows.
std::string girder_poses_csv(const std::vector<GirderResult>& results);

}  // namespace tunnelmap
