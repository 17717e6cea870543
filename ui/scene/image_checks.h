#pragma once
// Pixel statistics the screenshot tests and `tunnelmap-render --check` rely on.
#include "ui/scene/rgb_image.h"

namespace tunnelmap::scene {

struct PixelBox {
  int count = 0;
  int x0 = 0, y0 = 0, x1 = -1, y1 = -1;  // inclusive bounding box of the matching pixels

  void add(int x, int y) {
    if (count == 0) x0 = x1 = x, y0 = y1 = y;
    x0 = x < x0 ? x : x0;
    x1 = x > x1 ? x : x1;
    y0 = y < y0 ? y : y0;
    y1 = y > y1 ? y : y1;
    ++count;
  }
};

// Boundary blue as drawn by TunnelScene (unlit, so exact up to antialiasing), and traversable
// red: its opaque outline or its translucent fill over the dark background (a red hue bright
// enough not to be background); `x0..x1`/`y0..y1` restrict the search (whole image by default).
PixelBox find_boundary_blue(const RgbImage& img, int x0 = 0, int y0 = 0, int x1 = -1, int y1 = -1);
PixelBox find_traversable_red(const RgbImage& img, int x0 = 0, int y0 = 0, int x1 = -1, int y1 = -1);

// Number of distinct colours after quantising to 4 bits per channel: a blank image has 1.
int distinct_colors(const RgbImage& img);

// Mean absolute per-channel difference (0..255) and the fraction of pixels differing by more
// than `pixel_tolerance` in any channel. Images of different sizes: {255, 1}.
struct ImageDiff {
  double mean_abs = 0.0;
  double fraction_over = 0.0;
};
ImageDiff compare_images(const RgbImage& a, const RgbImage& b, int pixel_tolerance);

}  // namespace tunnelmap::scene
