#include "ui/scene/scene_layers.h"

#include <sstream>
#include <stdexcept>

namespace tunnelmap::scene {

const std::vector<Layer>& all_layers() {
  static const std::vector<Layer> layers = {Layer::Cloud,     Layer::Mesh,        Layer::Planes,
                                            Layer::Boundary,  Layer::Traversable, Layer::Forbidden,
                                            Layer::Frustum,   Layer::Axes,        Layer::Legend,
                                            Layer::Grid};
  return layers;
}

const char* layer_name(Layer l) {
  switch (l) {
    case Layer::Cloud: return "cloud";
    case Layer::Mesh: return "mesh";
    case Layer::Planes: return "planes";
    case Layer::Boundary: return "boundary";
    case Layer::Traversable: return "traversable";
    case Layer::Forbidden: return "forbidden";
    case Layer::Frustum: return "frustum";
    case Layer::Axes: return "axes";
    case Layer::Legend: return "legend";
    case Layer::Grid: return "grid";
  }
  return "?";
}

const char* layer_title(Layer l) {
  switch (l) {
    case Layer::Cloud: return "Point cloud";
    case Layer::Mesh: return "RGB-D mesh";
    case Layer::Planes: return "Planes (by wall class)";
    case Layer::Boundary: return "Tunnel boundary";
    case Layer::Traversable: return "Traversable zones";
    case Layer::Forbidden: return "Forbidden zones";
    case Layer::Frustum: return "Camera frustum";
    case Layer::Axes: return "Axes";
    case Layer::Legend: return "Legend";
    case Layer::Grid: return "Distance grid";
  }
  return "?";
}

std::vector<Layer> parse_layers(const std::string& list) {
  if (list == "all") return all_layers();
  std::vector<Layer> out;
  std::stringstream in(list);
  std::string name;
  while (std::getline(in, name, ',')) {
    if (name.empty()) continue;
    bool found = false;
    for (Layer l : all_layers())
      if (name == layer_name(l)) {
        out.push_back(l);
        found = true;
      }
    if (!found) {
      std::string known;
      for (Layer l : all_layers()) known += std::string(known.empty() ? "" : ", ") + layer_name(l);
      throw std::invalid_argument("unknown layer '" + name + "' (known: " + known + ", all)");
    }
  }
  return out;
}

}  // namespace tunnelmap::scene
