#pragma once
// Command line of tunnelmap-render (also reached as `tunnelmap-cli render ...`).
#include <string>
#include <vector>

#include "ui/scene/camera_presets.h"
#include "ui/scene/scene_geometry.h"
#include "ui/scene/scene_layers.h"

namespace tunnelmap::render {

struct RenderOptions {
  std::string input;
  std::string screenshot;
  scene::ViewPreset view = scene::ViewPreset::Along;
  int width = 1280, height = 720;
  std::vector<scene::Layer> layers;  // default: everything
  std::string params_file;
  std::vector<std::string> sets;     // KEY=VALUE
  std::size_t frame = 0;
  double depth_scale = 1000.0;
  int max_points = scene::kDefaultDisplayPoints;  // point-layer decimation, as in the GUI
};

// "1280x720" -> width/height; throws std::invalid_argument.
void parse_size(const std::string& text, int& width, int& height);

}  // namespace tunnelmap::render
