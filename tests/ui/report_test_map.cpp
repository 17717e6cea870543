#include "tests/ui/report_test_map.h"

#include <cmath>

namespace tunnelmap::test {

namespace {

struct SectionSpec {
  double from, to, width, height;
  int frames;
};

// S2 is 7 mm wider than the design (inside the tolerance); S3 is 2 mm narrower.
const SectionSpec kSections[] = {{0.0, 8.4, 0.8212, 1.3018, 14},
                                 {8.4, 15.6, 0.8270, 1.2962, 12},
                                 {15.6, 24.0, 0.8180, 1.3051, 16}};

}  // namespace

StationMap make_report_station_map() {
  StationMap m;
  m.ok = true;
  m.status = "ok";
  m.options.station_step_m = 0.10;
  m.options.design_width_m = 0.82;
  m.options.design_height_m = 1.30;
  m.options.tolerance_mm = 10.0;
  m.origin = Eigen::Vector3d(1.0, 2.0, 0.5);
  m.axis = Eigen::Vector3d::UnitX();
  m.up = Eigen::Vector3d::UnitZ();
  m.frames = 42;
  m.frames_used = 35;
  for (const SectionSpec& s : kSections) {
    Section sec;
    sec.from_m = s.from;
    sec.to_m = s.to;
    sec.width_m = s.width;
    sec.height_m = s.height;
    sec.frames = s.frames;
    m.sections.push_back(sec);
  }
  for (int i = 0; i < 240; ++i) {
    Station st;
    st.station_m = 0.05 + 0.1 * i;
    const SectionSpec& s = kSections[st.station_m < 8.4 ? 0 : (st.station_m < 15.6 ? 1 : 2)];
    // Millimetre-scale ripple, as real plates show.
    st.width_m = s.width + 0.0012 * std::sin(1.7 * i);
    st.height_m = s.height + 0.0010 * std::cos(1.3 * i);
    st.width_source = st.height_source = DimensionSource::Measured;
    st.frames = 2 + i % 3;
    // A bulge of the side plates around 11.1 m (+13.5 mm).
    if (i >= 110 && i <= 112) st.width_m = 0.8335;
    // A low roof at 19.45 m (-13 mm).
    if (i == 194) st.height_m = 1.2870;
    // The roof was out of view at 4.05-4.45 m: heights from the neighbours.
    if (i >= 40 && i <= 44) st.height_source = DimensionSource::Context;
    // The last two stations' roof only from the design.
    if (i >= 238) {
      st.height_source = DimensionSource::Design;
      st.height_m = 1.30;
    }
    st.width_dev_mm = (st.width_m - 0.82) * 1000.0;
    st.height_dev_mm = (st.height_m - 1.30) * 1000.0;
    st.out_of_tolerance = std::abs(*st.width_dev_mm) > 10.0 || std::abs(*st.height_dev_mm) > 10.0;
    st.wall_m[0] = 0.5 * st.width_m + 0.001;
    st.wall_m[1] = 0.5 * st.width_m - 0.001;
    st.wall_m[2] = 0.5 * st.height_m;
    st.wall_m[3] = 0.5 * st.height_m;
    m.stations.push_back(st);
  }
  // Six poses, one every 4 m, seven frames each; pose 3 saw no tunnel.
  for (int g = 0; g < 6; ++g) {
    PoseGroupStatus p;
    p.group = g;
    for (int f = 0; f < 7; ++f) p.frames.push_back(7 * g + f);
    p.camera_to_world = Eigen::Isometry3d::Identity();
    p.camera_to_world.translation() = m.origin + m.axis * (2.0 + 4.0 * g) + Eigen::Vector3d(0, 0.05, 0.1);
    p.rescan = g == 3;
    p.detected_frames = p.rescan ? 0 : 7;
    p.status = p.rescan ? "too_few_planes" : "ok";
    p.message = p.rescan ? "move and rescan: too_few_planes (only the floor was in view)" : "ok";
    m.poses.push_back(p);
  }
  return m;
}

}  // namespace tunnelmap::test
