#pragma once
// The toggleable layers of the 3D scene, with the names used by --layers and the GUI.
#include <string>
#include <vector>

namespace tunnelmap::scene {

enum class Layer { Cloud, Mesh, Planes, Boundary, Traversable, Forbidden, Frustum, Axes, Legend, Grid };
constexpr int kLayerCount = 10;

const std::vector<Layer>& all_layers();
const char* layer_name(Layer l);   // "cloud", "mesh", "planes", ...
const char* layer_title(Layer l);  // "Point cloud", ... (menus)

// Comma-separated names ("cloud,planes,boundary" or "all"); throws std::invalid_argument naming
// the unknown layer.
std::vector<Layer> parse_layers(const std::string& list);

}  // namespace tunnelmap::scene
