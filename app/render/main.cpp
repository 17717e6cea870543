// tunnelmap-render: renders the GUI's 3D scene of one processed frame, a dataset's station map
// (--map, optionally over a fused mesh), or a map mesh PLY, to a PNG through OSMesa, with no X
// server and no DISPLAY. `tunnelmap-cli render ARGS...` execs this
// binary.
// Exit codes as tunnelmap-cli: 0 ok, 2 bad usage, 3 bad input, 4 internal/rendering error.
#include <CLI/CLI.hpp>
#include <iostream>
#include <vtkAutoInit.h>

#include "app/render/map_mesh.h"
#include "app/render/mesh_view.h"
#include "app/render/osmesa_window.h"
#include "app/render/render_map.h"
#include "app/render/render_options.h"
#include "core/io/frame_source.h"
#include "core/util/error.h"
#include "ui/scene/processed_frame.h"
#include "ui/scene/tunnel_scene.h"

namespace {

using namespace tunnelmap;

// A map mesh PLY: the mesh layer only (unless --layers says otherwise), framed by the tunnel the
// mesh's walls describe, with a light kit so that no face turned from the camera goes black.
int run_mesh(const render::RenderOptions& opt) {
  const render::MapMesh mesh = render::load_map_mesh(opt.in.input, opt.cutaway);
  render::OsMesaWindow window(opt.width, opt.height);
  scene::TunnelScene scene;
  scene::SceneGeometry geometry;
  for (auto* layer : {&geometry.cloud, &geometry.planes, &geometry.boundary, &geometry.traversable,
                      &geometry.forbidden, &geometry.frustum})
    *layer = vtkSmartPointer<vtkPolyData>::New();
  geometry.mesh = mesh.poly;
  geometry.map = mesh.frame;
  scene.set_geometry(geometry);
  scene.show_only(opt.layers.empty() ? std::vector<scene::Layer>{scene::Layer::Mesh} : opt.layers);
  render::add_boundary_bands(scene.renderer(), mesh.boundary, scene.layer_visible(scene::Layer::Mesh));
  render::light_mesh(scene.renderer(), mesh.poly);
  window.add_renderer(scene.renderer());
  scene.apply_view(opt.view);
  // Seen from outside, a long map is a thin bar in the middle of the bounding sphere's view.
  if (opt.view == scene::ViewPreset::Side || opt.view == scene::ViewPreset::Top)
    scene::fit_view_to_map(scene.renderer(), mesh.frame);
  const scene::RgbImage image = window.render();
  scene::save_png(image, opt.screenshot);
  const TunnelMap& f = mesh.frame;
  std::cout << opt.screenshot << ": " << image.width << "x" << image.height << ", view "
            << scene::view_name(opt.view) << ", map mesh " << mesh.triangles << " triangles (length "
            << f.extent_max_m - f.extent_min_m << " m, width " << f.width_m << " m, height " << f.height_m
            << " m)";
  const scene::PixelBox box = render::projected_box(scene.renderer(), mesh.poly, image.width, image.height);
  if (box.count > 0) std::cout << ", mesh box " << box.x0 << "," << box.y0 << " " << box.x1 << "," << box.y1;
  std::cout << "\n";
  return 0;
}

int run(const render::RenderOptions& opt) {
  if (opt.map) return render::run_station_map(opt);
  if (!opt.mesh.empty()) throw ParameterError("--mesh goes with --map (a mesh PLY alone is drawn as INPUT)");
  if (opt.cutaway && !render::is_mesh_input(opt.in.input))
    throw ParameterError("--cutaway opens a map (a map PLY, or --map); one frame's scene has none to open");
  if (render::is_mesh_input(opt.in.input)) return run_mesh(opt);
  auto source = open_input(opt.in.input, opt.in.read_options());
  RunSettings settings;  // parameters and camera up, as `detect` takes them
  settings.params = opt.in.parameters();
  settings.camera_up = opt.in.camera_up();
  scene::ProcessedFrame processed;
  run_frame(*source, opt.frame, settings, processed);

  render::OsMesaWindow window(opt.width, opt.height);
  scene::TunnelScene scene;
  scene.set_max_display_points(opt.max_points);
  scene.update(processed.scene_data());
  if (!opt.layers.empty()) scene.show_only(opt.layers);
  window.add_renderer(scene.renderer());
  scene.apply_view(opt.view);
  const scene::RgbImage image = window.render();
  scene::save_png(image, opt.screenshot);
  const TunnelMap& map = processed.result.map;
  std::cout << opt.screenshot << ": " << image.width << "x" << image.height << ", view "
            << scene::view_name(opt.view) << ", tunnel " << map.status;
  if (map.detected) {  // a partial map may leave a dimension unknown
    std::cout << " (width ";
    if (map.has_width()) std::cout << map.width_m << " m"; else std::cout << "unknown";
    std::cout << ", height ";
    if (map.has_height()) std::cout << map.height_m << " m"; else std::cout << "unknown";
    std::cout << ")";
  }
  std::cout << ", " << processed.result.planes.planes.size() << " planes";
  // Where the tunnel is in the image: lets tests check map colours lie inside it.
  const scene::PixelBox box = scene.projected_boundary(image.width, image.height);
  if (box.count > 0)
    std::cout << ", boundary box " << box.x0 << "," << box.y0 << " " << box.x1 << "," << box.y1;
  std::cout << "\n";
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  render::RenderOptions opt;
  CLI::App app{"Renders the 3D inspection scene of one frame, the station map of a posed dataset (--map), or a mesh PLY, to a PNG, headless "
               "(OSMesa)",
               "tunnelmap-render"};
  std::string view = "along", size = "1280x720", layers;
  cli::add_input_options(&app, opt.in);  // INPUT: also a map or fused mesh PLY, drawn as it is
  app.add_option("--screenshot", opt.screenshot, "Output PNG")->required();
  auto* view_option = app.add_option("--view", view, "Camera: along | side | top | reset | oblique "
                                     "(default: along; oblique for a mesh PLY)");
  app.add_option("--size", size, "Image size WIDTHxHEIGHT")->capture_default_str();
  app.add_option("--layers", layers,
                 "Comma-separated layers: cloud,mesh,planes,boundary,traversable,forbidden,"
                 "frustum,axes,legend,grid (default: all)");
  app.add_option("--frame", opt.frame, "Frame index in a sequence")->capture_default_str();
  app.add_option("--max-points", opt.max_points,
                 "Point layers keep at most this many pixels each, as in the GUI (0: all)")
      ->capture_default_str();
  app.add_flag("--map", opt.map,
               "Draw the station map of a posed dataset (as `tunnelmap-cli map` builds it) instead of one frame");
  app.add_option("--mesh", opt.mesh, "With --map: a fused mesh PLY (`fuse --ply`) drawn under the map");
  app.add_flag("--no-pose-refinement", opt.no_pose_refinement, "With --map: the poses as given");
  app.add_flag("--cutaway", opt.cutaway,
               "A map (a map PLY or --map): leave out the roof and the right wall, so that the floor, the left "
               "wall and the plates with their manholes show from above");
  try {
    app.parse(argc, argv);
    opt.view = scene::parse_view(view);
    if (view_option->count() == 0 && (opt.map || render::is_mesh_input(opt.in.input)))
      opt.view = scene::ViewPreset::Oblique;
    render::parse_size(size, opt.width, opt.height);
    if (!layers.empty()) opt.layers = scene::parse_layers(layers);
  } catch (const CLI::ParseError& e) {
    return app.exit(e);
  } catch (const std::invalid_argument& e) {
    std::cerr << "tunnelmap-render: " << e.what() << "\n";
    return 2;
  }
  try {
    return run(opt);
  } catch (const ParameterError& e) {
    std::cerr << "tunnelmap-render: " << e.what() << "\n";
    return 2;
  } catch (const InputError& e) {
    std::cerr << "tunnelmap-render: " << e.what() << "\n";
    return 3;
  } catch (const std::exception& e) {
    std::cerr << "tunnelmap-render: " << e.what() << "\n";
    return 4;
  }
}
