#pragma once
// TunnelSimulator: renders depth (16-bit mm), registered RGB and a ground-truth surface-id
// image of a simulated steel tunnel as seen by a PrimeSense-class VGA depth camera.
// render(i) is deterministic for (config, i): all randomness comes from std::mt19937 streams
// seeded from config.seed, the frame index and the image row.
#include <Eigen/Geometry>
#include <cstdint>
#include <optional>
#include <utility>
#include <vector>

#include "core/frame/depth_frame.h"
#include "core/sim/sim_arm.h"
#include "core/sim/sim_config.h"
#include "core/sim/sim_sections.h"
#include "core/sim/tunnel_geometry.h"

namespace tunnelmap {

struct SimFrame {
  DepthFrame frame;                       // depth in mm (depth_units_per_m = 1000), rgb, pose
  std::vector<std::uint16_t> surface_id;  // width*height; true surface even where dropped out
  int pose_group = 0;
  std::optional<double> distance_to_manhole_m;
  std::optional<SimArmState> arm;  // joints, FK pose, true pose (arm_preset set)
  // What the dataset tells a reader: with drift the drifted pose, else frame.pose (with an
  // arm: the forward kinematics of the joints from the (drifted) base, i.e. without sag).
  Eigen::Isometry3d reported_pose = Eigen::Isometry3d::Identity();
  // With an arm: the robot base the dataset gives ("robot_base"), drifted when drift is on.
  Eigen::Isometry3d reported_base = Eigen::Isometry3d::Identity();
};

// One pose group's odometry error: reported = [rotation * R | t + translation] for a true
// camera (or robot base) pose [R | t].
struct SimDrift {
  Eigen::Matrix3d rotation = Eigen::Matrix3d::Identity();
  Eigen::Vector3d translation = Eigen::Vector3d::Zero();
  Eigen::Isometry3d apply(const Eigen::Isometry3d& T) const;
};

class TunnelSimulator {
 public:
  // Validates the config (throws ParameterError).
  explicit TunnelSimulator(SimConfig config);

  int frame_count() const { return config_.frames; }
  SimFrame render(int index) const;
  Eigen::Isometry3d pose(int index) const;  // camera-to-world, with the frame's jitter (and sag)
  // Arm state of a frame (nullopt without arm_preset). pose(i) == arm_state(i)->true_pose.
  std::optional<SimArmState> arm_state(int index) const;
  // The pose a reader of the dataset gets (SimFrame::reported_pose), without rendering.
  Eigen::Isometry3d reported_pose(int index) const;
  // Odometry drift of a pose group (identity without drift; group 0 has none) and the
  // distance the camera travelled from group 0 to it (sum of nominal station-to-station steps).
  const SimDrift& drift(int group) const;
  double travelled_m(int group) const { return travelled_.empty() ? 0.0 : travelled_[group]; }
  const std::vector<SimSurface>& surfaces() const { return geometry_.surfaces(); }
  const SimSurface* surface(int id) const;  // nullptr for 0, rivets and unknown ids

  const SimConfig& config() const { return config_; }
  int group_count() const { return groups_; }
  int pose_group(int index) const;          // contiguous blocks of frames
  // Nominal camera X of a pose group (a walk's station), before jitter.
  double group_x(int group) const;
  // The group's camera looks back along the girder (SimWalk::look_back).
  bool looks_back(int group) const { return !looks_back_.empty() && looks_back_.at(group); }
  // Without a walk: the group's distance; with one: the plate's distance from the frame's
  // station, when the station is in front of the plate.
  std::optional<double> distance_to_manhole(int index) const;
  std::optional<double> manhole_x() const { return manhole_x_; }  // world X of the plate
  const sim::TunnelGeometry& geometry() const { return geometry_; }

  // The true outermost width / height of the cross-section at world x (a joint's x belongs to
  // the section after it), and the joints' x in order (empty without sections).
  double width_at(double x) const { return sections_.at(x).width_m; }
  double height_at(double x) const { return sections_.at(x).height_m; }
  std::vector<double> joints_x() const { return sections_.joints_x(); }
  const sim::SimSections& sections() const { return sections_; }
  // World X of every transverse plate with the manhole opening (manhole plate and
  // diaphragms), in increasing order.
  std::vector<double> diaphragms_x() const;

  // Neutral orientation: camera z -> world +X, camera x -> world -Y, camera y -> world -Z,
  // then turned by yaw (about world Z), pitch (nose up) and roll (about the viewing axis).
  static Eigen::Matrix3d camera_rotation(double roll_deg, double pitch_deg, double yaw_deg);

 private:
  static std::optional<double> compute_manhole_x(const SimConfig& c);
  static std::optional<double> compute_end_x(const SimConfig& c);
  Eigen::Isometry3d wanted_pose(int index) const;  // nominal + jitter
  // Group g's camera pose with a jitter (x, y, z in m; roll, pitch, yaw in degrees).
  Eigen::Isometry3d group_pose(int g, const double jitter[6]) const;
  void make_drift();
  // The (pose, robot base) the dataset reports for a frame of `group` rendered at T.
  std::pair<Eigen::Isometry3d, Eigen::Isometry3d> reported(
      int group, const Eigen::Isometry3d& T, const std::optional<SimArmState>& arm) const;
  // `ideal` (ToF): receives every pixel's noise-free depth (0 = nothing hit), else nullptr.
  void render_rows(int index, const Eigen::Isometry3d& T, int row_begin, int row_step,
                   SimFrame& out, std::vector<float>* ideal) const;
  void flying_pixels(int index, const std::vector<float>& ideal, SimFrame& out) const;

  SimConfig config_;
  sim::SimSections sections_;
  std::optional<double> manhole_x_;
  sim::TunnelGeometry geometry_;
  int groups_ = 1;
  std::vector<double> plates_x_;    // diaphragms_x()
  std::vector<bool> looks_back_;    // per group: turned round (SimWalk::look_back)
  std::vector<SimDrift> drift_;     // per group; empty without drift
  std::vector<double> travelled_;   // per group; empty without drift
};

}  // namespace tunnelmap
