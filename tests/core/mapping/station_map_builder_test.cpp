// The plates a posed walk maps include those seen only by frames that found no cross-section of
// their own: a plate just behind another, seen through that one's manhole.
#include "core/mapping/station_map_builder.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>

#include <vector>

#include "core/mapping/mapping_notes.h"
#include "core/mapping/posed_sequence.h"
#include "tests/support/family_girder.h"

namespace tunnelmap {
namespace {

// Frames `frames` of the girder detected and mapped with their true poses as given (no
// refinement); `detected` (when given) receives whether each found a cross-section.
MappedSequence map_frames_as_posed(const testing::FamilyGirder& girder, const std::vector<int>& frames,
                                   std::vector<bool>* detected = nullptr) {
  std::vector<TunnelMap> maps;
  std::vector<FrameWalls> walls;
  std::vector<Eigen::Isometry3d> poses;
  for (int f : frames) {
    const FrameResult r = girder.detect(f);
    maps.push_back(r.map);
    if (detected) detected->push_back(r.map.detected);
    walls.emplace_back();
    extract_frame_walls(r, walls.back());
    poses.push_back(girder.sim().pose(f));
  }
  return map_posed_sequence(maps, walls, poses, Eigen::Vector3d::UnitZ(), girder.params(), /*refine=*/false);
}

// Girder 17 of the evaluation's family of seed 10 (field box girder, 1.01 x 1.21 m, elliptic
// 0.41 x 0.62 m manholes): the preset's manhole plate stands at x = 5.00 m, 0.32 m behind the
// diaphragm at 4.68 m, its opening in line with the diaphragm's. Frames 10 and 11, 0.8 m before
// the diaphragm, see it as a ring through the diaphragm's manhole; the diaphragm fills their
// view, so they find no cross-section. Frames 12 and 13, 0.13 m before the diaphragm, see the
// plate only in their corners at 0.45 m, too little for a face. Frames 6-15, exact poses.
TEST(StationMapPlates, APlateOnlyFramesWithoutACrossSectionSawIsMappedWithItsManhole) {
  const testing::FamilyGirder girder(10, 17);
  const double diaphragm_x = 4.6777, plate_x = 5.0, manhole_w = 0.4118, manhole_h = 0.6230;
  std::vector<int> frames;
  for (int f = 6; f <= 15; ++f) frames.push_back(f);
  std::vector<bool> detected;
  const MappedSequence mapped = map_frames_as_posed(girder, frames, &detected);
  EXPECT_FALSE(detected[10 - 6]);
  EXPECT_FALSE(detected[11 - 6]);
  const StationMap& map = mapped.stations;
  const auto world_x = [&](const Diaphragm& d) { return d.point.x(); };
  std::vector<const Diaphragm*> near;
  for (const Diaphragm& d : map.girder.diaphragms)
    if (std::abs(world_x(d) - 4.85) < 0.5) near.push_back(&d);
  ASSERT_EQ(near.size(), 2u);
  EXPECT_NEAR(world_x(*near[0]), diaphragm_x, 0.005);
  EXPECT_NEAR(world_x(*near[1]), plate_x, 0.005);
  EXPECT_EQ(near[1]->seen_by_frames, 2);
  ASSERT_TRUE(near[1]->manhole) << near[1]->manhole_reason;
  EXPECT_NEAR(near[1]->manhole->width_m, manhole_w, 0.015);
  EXPECT_NEAR(near[1]->manhole->height_m, manhole_h, 0.015);

  // Their pose still needs a rescan for the cross-section, and says which plates it saw.
  const int frame_10 = 10 - 6;  // its index in the mapped walk
  const auto saw_frame_10 = [&](const PoseGroupStatus& p) {
    return std::find(p.frames.begin(), p.frames.end(), frame_10) != p.frames.end();
  };
  const auto pose = std::find_if(map.poses.begin(), map.poses.end(), saw_frame_10);
  ASSERT_NE(pose, map.poses.end());
  EXPECT_TRUE(pose->rescan);
  char plate[64];
  std::snprintf(plate, sizeof plate, "a plate at station %.3f m", near[1]->station_m);
  EXPECT_NE(pose->message.find("; its frames saw "), std::string::npos) << pose->message;
  EXPECT_NE(pose->message.find(plate), std::string::npos) << pose->message;
  for (const PoseGroupStatus& p : map.poses) EXPECT_TRUE(p.rescan || p.message == "ok") << p.message;
}

// Girder 10 of the family of seed 10 walked looking back once per compartment (field preset:
// 6 m range, plates every 4.08 m). The look back in the second compartment, 5.9 m from the start
// wall, sees that wall through the first diaphragm's manhole at the edge of the range: its far
// pixels are dropped, the near ones kept, and it came out 22 mm too near. Mapped with the stops
// either side of it (exact poses), the start wall is left out; the diaphragm is placed.
TEST(StationMapPlates, APlateSeenOnlyAtTheEdgeOfTheRangeIsNotMappedTooNear) {
  GirderRanges ranges;
  ranges.look_back_fraction = 1.0;
  const testing::FamilyGirder girder(10, 10, ranges);
  int back = -1;
  for (int g = 0; g < girder.sim().group_count() && back < 0; ++g)
    if (girder.sim().looks_back(g)) back = g;
  ASSERT_GT(back, 0);
  std::vector<int> frames;
  for (int f = 0; f < girder.sim().frame_count(); ++f)
    if (std::abs(girder.sim().pose_group(f) - back) <= 1) frames.push_back(f);
  const MappedSequence mapped = map_frames_as_posed(girder, frames);
  const std::vector<double> plates_x = girder.sim().diaphragms_x();
  int diaphragms = 0;
  const Diaphragm* first = nullptr;
  for (const Diaphragm& d : mapped.stations.girder.diaphragms) {
    EXPECT_GT(d.point.x(), 1.0) << "a plate at " << d.point.x() << " m";
    if (std::abs(d.point.x() - plates_x.front()) < 0.5) {
      ++diaphragms;
      first = &d;
      EXPECT_NEAR(d.point.x(), plates_x.front(), 0.005);
    }
  }
  ASSERT_EQ(diaphragms, 1);
  // The start wall is said to be left out, where those views put it: up to a few centimetres
  // too near the camera that looked back at it, on this straight girder.
  const std::vector<PlateBeyondRange>& far = mapped.stations.girder.plates_beyond_range;
  ASSERT_EQ(far.size(), 1u);
  const double start_wall_m = first->station_m - plates_x.front();
  EXPECT_GT(far[0].station_m, start_wall_m);
  EXPECT_LT(far[0].station_m, start_wall_m + 0.05);
  for (int f : far[0].frames) EXPECT_EQ(girder.sim().pose_group(frames[static_cast<std::size_t>(f)]), back) << f;
  const std::vector<std::string> notes = plates_beyond_range_notes(far);
  ASSERT_EQ(notes.size(), 1u);
  EXPECT_NE(notes[0].find("seen only near the end of the depth range"), std::string::npos) << notes[0];
}

}  // namespace
}  // namespace tunnelmap
