#include "core/evaluation/girder_poses_csv.h"

#include <cstdio>

namespace tunnelmap {

std::string girder_poses_csv(const std::vector<GirderResult>& results) {
  std::string out =
      "girder,drifted,frame,station_m,error_mm,along_mm,across_mm,vertical_mm,rotation_deg,roll_deg,pitch_deg,"
      "heading_deg\n";
  char row[320];
  for (const GirderResult& r : results)
    for (const FramePoseError& f : r.score.frame_pose_errors) {
      std::snprintf(row, sizeof(row), "%d,%d,%d,%.4f,%.3f,", r.draw.index, r.draw.drifted ? 1 : 0, f.frame, f.station_m,
                    f.error_mm);
      out += row;
      // The parts are empty where the girder's frame is unknown.
      if (f.split)
        std::snprintf(row, sizeof(row), "%.3f,%.3f,%.3f,%.4f,%.4f,%.4f,%.4f\n", f.along_mm, f.across_mm, f.vertical_mm,
                      f.rotation_deg, f.roll_deg, f.pitch_deg, f.heading_deg);
      else
        std::snprintf(row, sizeof(row), ",,,%.4f,,,\n", f.rotation_deg);
      out += row;
    }
  return out;
}

}  // namespace tunnelmap
