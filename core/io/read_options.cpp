#include "core/io/read_options.h"

namespace tunnelmap {

Intrinsics default_intrinsics(int width, int height) {
  Intrinsics k;
  k.fx = k.fy = 570.3 * width / 640.0;
  k.cx = (width - 1) / 2.0;
  k.cy = (height - 1) / 2.0;
  k.width = width;
  k.height = height;
  return k;
}

Intrinsics intrinsics_for_image(const ReadOptions& opt, int width, int height) {
  if (!opt.intrinsics) return default_intrinsics(width, height);
  Intrinsics k = *opt.intrinsics;
  k.width = width;
  k.height = height;
  return k;
}

}  // namespace tunnelmap
