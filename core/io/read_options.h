#pragma once
// Options shared by all input readers (from --depth-scale and --intrinsics).
#include <optional>

#include "core/frame/intrinsics.h"

namespace tunnelmap {

struct ReadOptions {
  double depth_units_per_m = 1000.0;     // depth PNG units per metre (millimetres by default)
  std::optional<Intrinsics> intrinsics;  // FX,FY,CX,CY given by the user; width/height from the image
};

// PrimeSense VGA intrinsics scaled to an image of the given size (used when none are given).
Intrinsics default_intrinsics(int width, int height);

// The user's intrinsics (if any) with width/height taken from the image, else the default.
Intrinsics intrinsics_for_image(const ReadOptions& opt, int width, int height);

}  // namespace tunnelmap
