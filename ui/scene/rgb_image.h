#pragma once
// An 8-bit RGB image (top row first) grabbed from a render window, with PNG I/O. Used by the
// GUI's screenshot export, tunnelmap-render and the screenshot tests.
#include <cstdint>
#include <string>
#include <vector>

#include <vtkRenderWindow.h>

namespace tunnelmap::scene {

struct RgbImage {
  int width = 0;
  int height = 0;
  std::vector<std::uint8_t> rgb;  // width*height*3, row-major, top row first

  bool empty() const { return width <= 0 || height <= 0; }
  const std::uint8_t* at(int x, int y) const { return &rgb[(static_cast<std::size_t>(y) * width + x) * 3]; }
};

// Reads back the last rendered frame (back buffer) of `window`.
RgbImage grab_window(vtkRenderWindow* window);

// Atomic PNG write; throws InputError naming the file on failure.
void save_png(const RgbImage& image, const std::string& path);
// Throws InputError when the file is missing or not an image.
RgbImage load_png(const std::string& path);

}  // namespace tunnelmap::scene
