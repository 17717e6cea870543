#pragma once
// Command line of tunnelmap-render (also reached as `tunnelmap-cli render ...`).
#include <string>
#include <vector>

#include "app/cli/input_options.h"
#include "ui/scene/camera_presets.h"
#include "ui/scene/scene_geometry.h"
#include "ui/scene/scene_layers.h"

namespace tunnelmap::render {

struct RenderOptions {
  // INPUT and the input options of `detect`: --params, --set, --intrinsics, --depth-scale, --up,
  // --max-time-diff, --world-up.
  cli::InputOptions in;
  std::string screenshot;
  scene::ViewPreset view = scene::ViewPreset::Along;
  int width = 1280, height = 720;
  std::vector<scene::Layer> layers;  // default: everything
  std::size_t frame = 0;
  bool map = false;                  // draw the dataset's station map instead of one frame
  std::string mesh;                  // with map: the fused mesh PLY drawn under the map
  bool no_pose_refinement = false;   // with map: the poses as given
  bool cutaway = false;              // a map: without its roof and right wall, to look inside
  int max_points = scene::kDefaultDisplayPoints;  // point-layer decimation, as in the GUI
};

// "1280x720" -> width/height; throws std::invalid_argument.
void parse_size(const std::string& text, int& width, int& height);

}  // namespace tunnelmap::render
