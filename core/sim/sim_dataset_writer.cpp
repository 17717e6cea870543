#include "core/sim/sim_dataset_writer.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <random>
#include <nlohmann/json.hpp>
#include <opencv2/imgcodecs.hpp>

#include "core/io/dataset_json_writer.h"
#include "core/io/output_folder.h"
#include "core/kinematics/robot_json.h"
#include "core/sim/sim_config_json.h"
#include "core/sim/sim_girder.h"
#include "core/sim/tunnel_simulator.h"
#include "core/util/error.h"
#include "core/util/image_file.h"

namespace tunnelmap {

namespace fs = std::filesystem;
using nlohmann::json;

namespace {

// Where things fall in a camera of orientation `R` (camera-to-world; the world's up is +Z), as
// an IMU at rest reads it: tilted by N(0, sigma_deg^2) about each of two axes across it,
// seeded by the dataset's seed and the frame.
Eigen::Vector3d imu_gravity(const Eigen::Matrix3d& R, double sigma_deg, unsigned seed, std::size_t frame) {
  const Eigen::Vector3d g = R.transpose() * -Eigen::Vector3d::UnitZ();
  std::mt19937_64 rng(static_cast<std::uint64_t>(seed) * 1000003ULL + frame);
  std::normal_distribution<double> tilt(0.0, sigma_deg * M_PI / 180.0);
  const Eigen::Vector3d a = g.unitOrthogonal(), b = g.cross(a);
  // Drawn one by one: the order of a call's arguments is the compiler's.
  const double about_a = tilt(rng);
  const double about_b = tilt(rng);
  return (Eigen::AngleAxisd(about_a, a) * Eigen::AngleAxisd(about_b, b) * g).normalized();
}

// The sections the cameras can see: every span met between the smallest camera x and the
// largest, each widened by the sensor range, clipped to that extent.
json sections_json(const TunnelSimulator& sim, double min_cam_x, double max_cam_x) {
  const double lo = min_cam_x - sim.config().max_depth_m, hi = max_cam_x + sim.config().max_depth_m;
  json out = json::array();
  for (const sim::SimSpan& s : sim.sections().spans()) {
    if (s.to_x <= lo || s.from_x >= hi) continue;
    out.push_back({{"from_x_m", std::max(s.from_x, lo)},
                   {"to_x_m", std::min(s.to_x, hi)},
                   {"width_m", s.width_m},
                   {"height_m", s.height_m}});
  }
  return out;
}

// The girder's truth (docs/simulator.md#ground-truth-of-the-girder) over stations lo..hi.
json girder_json(const TunnelSimulator& sim, double lo, double hi) {
  const SimConfig& c = sim.config();
  const sim::SimAlignment& align = sim.geometry().alignment();
  const sim::SimSections& layout = sim.sections();
  auto centre = [&](double s) {
    return align.to_world(Eigen::Vector3d(s, 0.0, 0.5 * layout.at(s).height_m));
  };
  json line = json::array();
  constexpr double kStep = 0.1;
  const long first = static_cast<long>(std::ceil(lo / kStep - 1e-9));
  const long last = static_cast<long>(std::floor(hi / kStep + 1e-9));
  for (long i = first; i <= last; ++i) {
    const double s = i * kStep;
    line.push_back({{"station_m", s}, {"point", dataset_vector_json(centre(s))}});
  }
  json plates = json::array();
  std::vector<double> cuts{lo};
  for (const sim::TunnelGeometry::PlateInfo& p : sim.geometry().plates()) {
    if (p.station > lo && p.station < hi) cuts.push_back(p.station);
    plates.push_back({{"station_m", p.station},
                      {"kind", p.manhole_plate ? "manhole_plate" : "diaphragm"},
                      {"surface_id", p.id},
                      {"point", dataset_vector_json(p.centreline_world)},
                      {"normal", dataset_vector_json(p.normal_world)},
                      {"manhole",
                       {{"center", dataset_vector_json(p.centre_world)},
                        {"width_m", c.manhole_width_m},
                        {"height_m", c.manhole_height_m},
                        {"shape", c.manhole_shape},
                        {"centre_z_m", p.centre_z}}}});
    if (c.manhole_shape == "rounded_rectangle")
      plates.back()["manhole"]["corner_radius_m"] = c.manhole_corner_radius_m;
  }
  // Compartments between plates, split where the cross-section changes.
  for (double x : layout.joints_x())
    if (x > lo && x < hi) cuts.push_back(x);
  cuts.push_back(hi);
  std::sort(cuts.begin(), cuts.end());
  json rooms = json::array();
  for (std::size_t i = 1; i < cuts.size(); ++i) {
    if (cuts[i] - cuts[i - 1] < 1e-9) continue;
    const sim::SimSpan& span = layout.at(0.5 * (cuts[i - 1] + cuts[i]));
    rooms.push_back({{"from_m", cuts[i - 1]},
                     {"to_m", cuts[i]},
                     {"width_m", span.width_m},
                     {"height_m", span.height_m}});
  }
  json g = {{"station_step_m", kStep},
            {"from_m", lo},
            {"to_m", hi},
            {"curve_radius_m", c.curve_radius_m},
            {"gradient_pct", c.gradient_pct},
            {"cross_fall_deg", c.cross_fall_deg},
            {"centreline", line},
            {"diaphragms", plates},
            {"compartments", rooms}};
  if (c.girder_length_m) g["length_m"] = *c.girder_length_m;
  if (c.transition_m > 0.0) {
    g["transition_m"] = c.transition_m;
    g["transition_start_m"] = c.transition_start_m;
  }
  if (c.vertical_radius_m != 0.0) g["vertical_radius_m"] = c.vertical_radius_m;
  if (!c.stiffeners.empty()) {
    json st = json::array();
    for (const SimStiffener& s : c.stiffeners)
      st.push_back({{"wall", sim_wall_name(s.wall)},
                    {"position_m", s.position_m},
                    {"height_m", c.stiffener_height_m},
                    {"thickness_m", c.stiffener_thickness_m}});
    g["stiffeners"] = st;
  }
  return g;
}

}  // namespace

void write_sim_dataset(const std::string& out_dir, const SimConfig& config) {
  write_sim_dataset(out_dir, config, nullptr);
}

void write_sim_dataset(const std::string& out_dir, const SimConfig& config,
                       const SimProgress& progress) {
  const TunnelSimulator sim(config);  // validates before touching the disk
  StagedFolder out(out_dir);  // a new, empty or earlier simulated folder; whole or nothing
  const fs::path root = out.path();
  make_folder(root / "depth");
  make_folder(root / "rgb");
  make_folder(root / "gt");

  const Intrinsics K = Intrinsics::primesense_vga();
  json frames = json::array();
  json robot_json;  // null without an arm
  // The girder's truth: with any layout feature (the constant tunnel keeps its bytes).
  const bool girder = !config.sections.empty() || !sim::diaphragm_stations(config).empty() ||
                      config.walk || config.girder_length_m || config.curved() ||
                      !config.stiffeners.empty();
  double first_x = 0.0, min_x = 0.0, max_x = 0.0;  // camera x of the rendered frames
  for (int i = 0; i < sim.frame_count(); ++i) {
    const SimFrame f = sim.render(i);
    // Station of the camera (world x on a straight girder; the group's station on a curve).
    const double cam_x =
        config.curved() ? sim.group_x(f.pose_group) : f.frame.pose->translation().x();
    if (i == 0) first_x = min_x = max_x = cam_x;
    min_x = std::min(min_x, cam_x);
    max_x = std::max(max_x, cam_x);
    const int w = f.frame.width, h = f.frame.height;
    cv::Mat depth(h, w, CV_16UC1), gt(h, w, CV_16UC1), bgr(h, w, CV_8UC3);
    for (int v = 0; v < h; ++v)
      for (int u = 0; u < w; ++u) {
        const std::size_t k = static_cast<std::size_t>(v) * w + u;
        depth.at<std::uint16_t>(v, u) = static_cast<std::uint16_t>(f.frame.depth[k]);
        gt.at<std::uint16_t>(v, u) = f.surface_id[k];
        const std::uint8_t* rgb = &f.frame.rgb[k * 3];
        bgr.at<cv::Vec3b>(v, u) = cv::Vec3b(rgb[2], rgb[1], rgb[0]);  // OpenCV writes BGR
      }
    const std::string name = dataset_frame_file(static_cast<std::size_t>(i), ".png");
    write_image_file((root / "depth" / name).string(), depth);
    const std::string rgb_name = name.substr(0, name.rfind('.')) + "." + config.rgb_format;
    write_image_file((root / "rgb" / rgb_name).string(), bgr);
    write_image_file((root / "gt" / name).string(), gt);

    json fj = {{"depth", "depth/" + name},
               {"rgb", "rgb/" + rgb_name},
               {"gt_surfaces", "gt/" + name},
               {"timestamp", f.frame.timestamp_s},
               {"pose_group", f.pose_group}};
    if (f.arm) {
      // Joints only: readers get the pose by forward kinematics, sag included as an error.
      fj["joints"] = f.arm->joints;
      fj["robot_base"] = dataset_pose_json(f.reported_base);  // drifted like odometry, if drift is on
      fj["pose_true"] = dataset_pose_json(*f.frame.pose);
      if (!robot_json.is_object()) {
        RobotModel robot = robot_preset(config.arm_preset);
        robot.base = f.arm->base;
        robot_json = robot_to_json(robot);
      }
    } else {
      fj["pose"] = dataset_pose_json(f.reported_pose);  // the frame's pose, or with drift the drifted one
      if (config.has_drift() || girder) fj["pose_true"] = dataset_pose_json(*f.frame.pose);
    }
    if (f.distance_to_manhole_m) fj["distance_to_manhole_m"] = *f.distance_to_manhole_m;
    if (config.imu_gravity_deg > 0.0) {
      const Eigen::Vector3d g = imu_gravity(f.frame.pose->linear(), config.imu_gravity_deg, config.seed, i);
      fj["gravity"] = dataset_vector_json(g);
    }
    frames.push_back(fj);
    if (progress) progress(i, sim.frame_count(), (out.target() / "depth" / name).string());
  }

  const bool sectioned = !config.sections.empty();
  json surfaces = json::array();
  for (const SimSurface& s : sim.surfaces()) {
    json sj = {{"id", s.id},
               {"name", s.name},
               {"wall", s.wall},
               {"zone", s.zone},
               {"normal", dataset_vector_json(s.normal_world)},
               {"offset_m", s.offset_world}};
    if (sectioned && s.section >= 0) sj["section"] = s.section;
    surfaces.push_back(sj);
  }
  // The cross-section at the first camera (the only one without sections).
  json gt = {{"width_m", sim.width_at(first_x)},
             {"height_m", sim.height_at(first_x)},
             {"rivet_id", kSimRivetId},
             {"surfaces", surfaces}};
  if (sim.manhole_x()) gt["manhole_x_m"] = *sim.manhole_x();
  // Only for the new layouts, so datasets of the constant tunnel keep their exact bytes.
  if (sectioned || !config.diaphragm_x_m.empty() || config.walk) {
    gt["sections"] = sections_json(sim, min_x, max_x);
    gt["diaphragms_x_m"] = sim.diaphragms_x();
  }
  if (girder) {
    // Stations of the whole girder, else those the cameras can see.
    const double lo = config.girder_length_m ? 0.0 : min_x - config.max_depth_m;
    const double hi = config.girder_length_m ? *config.girder_length_m : max_x + config.max_depth_m;
    gt["girder"] = girder_json(sim, lo, hi);
  }

  json dataset = dataset_document(K, 1000.0, Eigen::Vector3d::UnitZ(), std::move(frames));
  dataset["ground_truth"] = gt;
  dataset["simulator"] = sim_config_to_json(config);
  if (robot_json.is_object()) dataset["robot"] = robot_json;
  write_dataset_json(root, dataset);
  out.commit();
}

}  // namespace tunnelmap
