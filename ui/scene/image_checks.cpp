#include "ui/scene/image_checks.h"

#include <algorithm>
#include <cstdlib>
#include <functional>
#include <unordered_set>

namespace tunnelmap::scene {

namespace {
PixelBox find(const RgbImage& img, int x0, int y0, int x1, int y1,
              const std::function<bool(int, int, int)>& match) {
  PixelBox box;
  if (img.empty()) return box;
  if (x1 < 0 || x1 >= img.width) x1 = img.width - 1;
  if (y1 < 0 || y1 >= img.height) y1 = img.height - 1;
  box.x0 = img.width;
  box.y0 = img.height;
  for (int y = std::max(0, y0); y <= y1; ++y)
    for (int x = std::max(0, x0); x <= x1; ++x) {
      const std::uint8_t* p = img.at(x, y);
      if (!match(p[0], p[1], p[2])) continue;
      ++box.count;
      box.x0 = std::min(box.x0, x);
      box.y0 = std::min(box.y0, y);
      box.x1 = std::max(box.x1, x);
      box.y1 = std::max(box.y1, y);
    }
  if (box.count == 0) box = PixelBox();
  return box;
}
}  // namespace

PixelBox find_boundary_blue(const RgbImage& img, int x0, int y0, int x1, int y1) {
  return find(img, x0, y0, x1, y1, [](int r, int g, int b) { return b > 200 && r < 40 && g < 110; });
}

PixelBox find_traversable_red(const RgbImage& img, int x0, int y0, int x1, int y1) {
  // The fill at kZoneFillOpacity over the background reads about (110, 25, 27); the map mesh's
  // lit red about (150-255, <60, <60). No other colour of the scene has such a hue.
  return find(img, x0, y0, x1, y1, [](int r, int g, int b) { return r > 90 && g * 10 < r * 4 && b * 10 < r * 4; });
}

int distinct_colors(const RgbImage& img) {
  std::unordered_set<int> seen;
  for (std::size_t i = 0; i + 2 < img.rgb.size(); i += 3)
    seen.insert((img.rgb[i] >> 4) << 8 | (img.rgb[i + 1] >> 4) << 4 | (img.rgb[i + 2] >> 4));
  return static_cast<int>(seen.size());
}

ImageDiff compare_images(const RgbImage& a, const RgbImage& b, int pixel_tolerance) {
  if (a.width != b.width || a.height != b.height || a.empty()) return {255.0, 1.0};
  double sum = 0.0;
  std::size_t over = 0;
  const std::size_t n = static_cast<std::size_t>(a.width) * a.height;
  for (std::size_t i = 0; i < n; ++i) {
    int worst = 0;
    for (int k = 0; k < 3; ++k) {
      const int d = std::abs(int(a.rgb[i * 3 + k]) - int(b.rgb[i * 3 + k]));
      sum += d;
      worst = std::max(worst, d);
    }
    if (worst > pixel_tolerance) ++over;
  }
  return {sum / (3.0 * n), static_cast<double>(over) / n};
}

}  // namespace tunnelmap::scene
