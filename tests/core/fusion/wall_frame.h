#pragma once
// A fronto-parallel wall at depth `z` (camera = world), uniform colour (200, 100, 50), in a
// 160 x 120 frame: the simplest input whose fused surface is known exactly.
#include "core/frame/depth_frame.h"

namespace tunnelmap::testing {

inline DepthFrame flat_wall(double z) {
  DepthFrame f;
  f.intrinsics = Intrinsics::primesense_vga();
  f.intrinsics.fx = f.intrinsics.fy = 570.3 / 4;
  f.intrinsics.cx = 79.5;
  f.intrinsics.cy = 59.5;
  f.width = f.intrinsics.width = 160;
  f.height = f.intrinsics.height = 120;
  f.depth_units_per_m = 1000.0;
  f.depth.assign(160 * 120, float(z * 1000.0));
  f.rgb.assign(160 * 120 * 3, 0);
  for (std::size_t i = 0; i < f.rgb.size(); i += 3) {
    f.rgb[i] = 200;
    f.rgb[i + 1] = 100;
    f.rgb[i + 2] = 50;
  }
  return f;
}

}  // namespace tunnelmap::testing
