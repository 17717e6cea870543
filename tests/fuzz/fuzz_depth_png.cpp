// libFuzzer target: the image loaders of core/io/depth_png (header checks, chunk walk, OpenCV
// decode), from memory: depth PNG, colour image (PNG/JPEG) and label PNG on the same bytes.
#include <cstdint>
#include <cstdlib>
#include <vector>

#include "core/io/depth_png.h"
#include "core/io/input_options.h"
#include "core/util/error.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace tunnelmap;
  const std::vector<std::uint8_t> bytes(data, data + size);
  const auto in_range = [](int w, int h) { return w > 0 && h > 0 && w <= kMaxImageSide && h <= kMaxImageSide; };
  try {
    const DepthFrame f = decode_depth_png(bytes, "fuzz.png", ReadOptions{});
    if (!in_range(f.width, f.height) || f.depth.size() != static_cast<std::size_t>(f.width) * f.height)
      std::abort();
  } catch (const InputError&) {
  }
  int w = 0, h = 0;
  try {
    const auto rgb = decode_rgb_image(bytes, "fuzz.rgb", w, h, input_keys::max_image_pixels.default_value);
    if (!in_range(w, h) || rgb.size() != static_cast<std::size_t>(w) * h * 3) std::abort();
  } catch (const InputError&) {
  }
  try {
    const auto labels = decode_label_png(bytes, "fuzz.labels.png", w, h, input_keys::max_image_pixels.default_value);
    if (!in_range(w, h) || labels.size() != static_cast<std::size_t>(w) * h) std::abort();
  } catch (const InputError&) {
  }
  return 0;
}
