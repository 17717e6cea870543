#include "app/render/render_options.h"

#include <stdexcept>

namespace tunnelmap::render {

void parse_size(const std::string& text, int& width, int& height) {
  const auto x = text.find('x');
  try {
    std::size_t used_w = 0, used_h = 0;
    if (x == std::string::npos) throw std::invalid_argument("");
    const std::string w = text.substr(0, x), h = text.substr(x + 1);
    width = std::stoi(w, &used_w);
    height = std::stoi(h, &used_h);
    if (used_w != w.size() || used_h != h.size()) throw std::invalid_argument("");
  } catch (const std::exception&) {
    throw std::invalid_argument("--size expects WIDTHxHEIGHT (e.g. 1280x720), got '" + text + "'");
  }
  if (width < 16 || height < 16 || width > 8192 || height > 8192)
    throw std::invalid_argument("--size " + text + " is out of range (16..8192 per side)");
}

}  // namespace tunnelmap::render
