// girder_poses.csv: one row per frame of every girder, the parts of an error empty where the
// girder's frame is unknown (never 0).
#include "core/evaluation/girder_poses_csv.h"

#include <gtest/gtest.h>

#include <sstream>
#include <string>

namespace tunnelmap {
namespace {

TEST(GirderPosesCsv, OneRowPerFrameAndUnknownPartsLeftEmpty) {
  GirderResult drifted;
  drifted.draw.index = 3;
  drifted.draw.drifted = true;
  FramePoseError f;
  f.frame = 0, f.station_m = 1.25, f.error_mm = 5.0, f.along_mm = 3.0, f.across_mm = -4.0, f.vertical_mm = 0.0;
  f.rotation_deg = 0.1, f.roll_deg = 0.0, f.pitch_deg = -0.1, f.heading_deg = 0.0, f.split = true;
  drifted.score.frame_pose_errors.push_back(f);
  f.frame = 1, f.split = false;
  drifted.score.frame_pose_errors.push_back(f);
  GirderResult without_truth;  // scored without true poses: no rows
  without_truth.draw.index = 4;
  std::istringstream csv(girder_poses_csv({drifted, without_truth}));
  std::string header, first, second, extra;
  std::getline(csv, header);
  std::getline(csv, first);
  std::getline(csv, second);
  EXPECT_EQ(header, "girder,drifted,frame,station_m,error_mm,along_mm,across_mm,vertical_mm,rotation_deg,roll_deg,"
                    "pitch_deg,heading_deg");
  EXPECT_EQ(first, "3,1,0,1.2500,5.000,3.000,-4.000,0.000,0.1000,0.0000,-0.1000,0.0000");
  EXPECT_EQ(second, "3,1,1,1.2500,5.000,,,,0.1000,,,");
  EXPECT_FALSE(std::getline(csv, extra));
}

}  // namespace
}  // namespace tunnelmap
