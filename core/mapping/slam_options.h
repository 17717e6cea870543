#pragma once
// Parameters of localisation and mapping against the girder's structure (slam.*), declared
// once, and the options StructureSlam takes. See docs/tunnel-map.md.
#include <Eigen/Core>
#include <cmath>

#include "core/normals/cloud_options.h"
#include "core/params/parameter_key.h"

namespace tunnelmap {

class Parameters;

namespace slam_keys {
inline constexpr ParameterKey<double> odometry_mm_per_sqrt_m{
    "slam.odometry_mm_per_sqrt_m", "mm", 10.0, 0.1, 1000.0, 0.1, Stage::Map, "Odometry drift (translation)",
    "Standard deviation of the odometry's position error per square root of metre travelled"};
inline constexpr ParameterKey<double> odometry_deg_per_sqrt_m{
    "slam.odometry_deg_per_sqrt_m", "deg", 0.2, 0.001, 10.0, 0.001, Stage::Map, "Odometry drift (rotation)",
    "Standard deviation of the odometry's heading error per square root of metre travelled"};
inline constexpr ParameterKey<bool> odometry_in_world{
    "slam.odometry_in_world", "", true, 0, 1, 1, Stage::Map, "Position drift in the world",
    "1: the odometry's position and heading drift as two random walks, position in the world frame "
    "(as the simulator draws them); 0: its position error is in the robot's frame, so a heading "
    "error carries each step sideways (dead reckoning)"};
inline constexpr ParameterKey<double> band_m{
    "slam.band_m", "m", 1.0, 0.2, 10.0, 0.1, Stage::Map, "Wall band",
    "Length along the girder over which one wall is one plane landmark"};
inline constexpr ParameterKey<double> wall_continuity_mm{
    "slam.wall_continuity_mm", "mm", 2.0, 0.0, 100.0, 0.1, Stage::Map, "Wall continuity",
    "How far a wall may step across a diaphragm, plate distortion and welds included: the walls "
    "run on through the plates, which ties the map's height and sideways position from one "
    "compartment to the next (applied by the final optimisation, never to the poses while the "
    "walk runs, and only when the measurements alone demand a correction); 0 leaves each "
    "compartment free"};
inline constexpr ParameterKey<double> wall_turn_deg{
    "slam.wall_turn_deg", "deg", 0.05, 0.0, 10.0, 0.01, Stage::Map, "Wall roll",
    "How far a side wall may roll about the girder's axis across a diaphragm (a change of "
    "cross-fall, plate distortion), measured against the world's up: it ties each "
    "compartment's roll to the last, which nothing else across a plate does but the odometry "
    "(applied with the wall continuity, slam.wall_continuity_mm); 0 leaves it free"};
inline constexpr ParameterKey<double> compartment_turn_deg{
    "slam.compartment_turn_deg", "deg", 0.01, 0.0, 10.0, 0.005, Stage::Map, "Turn between compartments",
    "How far a compartment's walls may point off the turn of its neighbours: a girder follows "
    "straights, arcs and transition curves, whose curvature is constant or changes evenly, "
    "whether its walls curve or kink at the plates. Of four neighbouring compartments the second "
    "lies on the quadratic through the others' directions; where the map then turns evenly, the "
    "middle of three also lies between the outer two (applied by the final optimisation, with "
    "the wall continuity); 0 leaves each compartment's direction to the odometry"};
inline constexpr ParameterKey<double> max_wall_depth_m{
    "slam.max_wall_depth_m", "m", 4.0, 0.5, 20.0, 0.1, Stage::Map, "Wall range",
    "Wall points farther from the camera than this do not localise it"};
inline constexpr ParameterKey<double> max_plate_depth_m{
    "slam.max_plate_depth_m", "m", 5.0, 0.5, 20.0, 0.1, Stage::Map, "Plate range",
    "Plates across the girder farther than this do not localise the camera; nearer, their "
    "weight follows the depth's steps (slam.depth_step_mm). A far plate seen through the "
    "manhole of a near one ties the two along the girder"};
inline constexpr ParameterKey<double> plate_gate_m{
    "slam.plate_gate_m", "m", 0.3, 0.02, 2.0, 0.01, Stage::Map, "Plate gate",
    "Farthest a plate may lie along the girder from a known plate and be that plate; nearer, the "
    "reach is four standard deviations of the odometry's drift since that plate was last seen "
    "(at least 5 cm). Keep it well below half the diaphragm spacing"};
inline constexpr ParameterKey<double> point_sigma_mm{
    "slam.point_sigma_mm", "mm", 1.5, 0.05, 100.0, 0.05, Stage::Map, "Depth noise at 1 m",
    "Standard deviation of one depth point at 1 m; it grows with the square of the depth"};
inline constexpr ParameterKey<double> patch_floor_mm{
    "slam.patch_floor_mm", "mm", 0.3, 0.01, 100.0, 0.01, Stage::Map, "Patch floor",
    "Smallest uncertainty of a patch's position at 1 m, however many points it has "
    "(calibration); it grows with the square of the depth. The depth's steps add their own "
    "(slam.depth_step_mm)"};
inline constexpr ParameterKey<bool> localise{
    "slam.localise", "", false, 0, 1, 1, Stage::Map, "Localise while running",
    "1: while a posed sequence runs (detect, the GUI, a live camera) each frame is localised "
    "against the structure mapped so far and takes its context with that pose; 0: frames keep "
    "their given poses (map and fuse still optimise them)"};
inline constexpr ParameterKey<double> depth_step_mm{
    "slam.depth_step_mm", "mm", 2.9, 0.0, 50.0, 0.1, Stage::Map, "Depth step at 1 m",
    "The sensor's depth resolution at 1 m: a structured-light camera quantises depth in steps "
    "of z^2 / (f b s) (PrimeSense class: 2.9 mm at 1 m); 0 for a camera without steps "
    "(time of flight). A patch that spans few steps keeps their error"};
inline constexpr ParameterKey<double> correction_sigmas{
    "slam.correction_sigmas", "sigma", 3.0, 0.0, 100.0, 0.5, Stage::Map, "Evidence for a correction",
    "The poses are corrected only when the structure disagrees with them by more than its "
    "measurements' noise explains: the cost the correction removes must exceed its chi-square "
    "expectation by this many standard deviations; otherwise the given poses are kept (0: always "
    "correct)"};
inline constexpr ParameterKey<double> gravity_deg{
    "slam.gravity_deg", "deg", 0.1, 0.001, 10.0, 0.01, Stage::Map, "IMU gravity",
    "Standard deviation of a frame's gravity direction (an IMU's accelerometer at rest, the "
    "dataset frame's \"gravity\"): it holds the camera's tilt to the world's up, which the walls "
    "leave to the odometry's slow drift over a long girder. Frames without gravity are not held"};
inline constexpr ParameterKey<int> window_groups{
    "slam.window_groups", "poses", 12, 2, 1000, 1, Stage::Map, "Window",
    "Pose groups re-estimated after each new frame while the sequence runs (the batch "
    "optimisation at the end re-estimates all)"};
inline constexpr ParameterKey<int> window_iterations{
    "slam.window_iterations", "", 3, 1, 50, 1, Stage::Map, "Window iterations",
    "Solver iterations per new frame while the sequence runs: each frame starts from the "
    "previous frame's estimate, so a few iterations keep up with the walk at a bounded time "
    "per frame (the batch optimisation at the end runs to convergence)"};
}  // namespace slam_keys

struct SlamOptions {
  double odometry_m_per_sqrt_m = mm_to_m(slam_keys::odometry_mm_per_sqrt_m.default_value);
  double odometry_deg_per_sqrt_m = slam_keys::odometry_deg_per_sqrt_m.default_value;
  bool odometry_in_world = slam_keys::odometry_in_world.default_value;
  double band_m = slam_keys::band_m.default_value;
  double wall_continuity_m = mm_to_m(slam_keys::wall_continuity_mm.default_value);
  double wall_turn_rad = slam_keys::wall_turn_deg.default_value * M_PI / 180.0;
  double compartment_turn_rad = slam_keys::compartment_turn_deg.default_value * M_PI / 180.0;
  double max_continuity_gap_m = 5.0;  // no tie across a longer unseen stretch of wall
  double max_wall_depth_m = slam_keys::max_wall_depth_m.default_value;
  double max_plate_depth_m = slam_keys::max_plate_depth_m.default_value;
  double plate_gate_m = slam_keys::plate_gate_m.default_value;
  double point_sigma_m = mm_to_m(slam_keys::point_sigma_mm.default_value);
  double patch_floor_m = mm_to_m(slam_keys::patch_floor_mm.default_value);
  double depth_step_m = mm_to_m(slam_keys::depth_step_mm.default_value);
  double correction_sigmas = slam_keys::correction_sigmas.default_value;
  double gravity_rad = slam_keys::gravity_deg.default_value * M_PI / 180.0;
  int window_groups = slam_keys::window_groups.default_value;
  int window_iterations = slam_keys::window_iterations.default_value;
  bool localise = slam_keys::localise.default_value;
  // The posed frames' world up (the dataset's): a wall's roll across a plate is measured
  // against it.
  Eigen::Vector3d world_up = Eigen::Vector3d::UnitZ();
  // cloud.max_range_m: depth beyond it never reaches a plate, so a plate near it is biased.
  double cloud_max_range_m = cloud_keys::max_range_m.default_value;
  // Odometry of pose groups that did not move still has this much uncertainty.
  double min_odometry_m = 0.0005;
  double min_odometry_deg = 0.01;
  int min_patch_points = 200;  // fewer points in a band or plate say little
  // A wall's zones are layers of its landmark: a patch within `layer_tolerance_m` of a layer
  // (after the frame's shift along the wall's normal, at most `max_layer_shift_m` and changing
  // by at most `max_layer_slope` per metre) is that layer.
  double layer_tolerance_m = 0.003;
  double max_layer_shift_m = 0.05;
  double max_layer_slope = 0.02;  // shift per metre along the girder (a heading error of ~1 deg)
  // A direction whose landmark information is below this fraction of the strongest is
  // left to odometry (reported as degenerate).
  double degenerate_ratio = 1e-4;
};

bool operator==(const SlamOptions& a, const SlamOptions& b);
inline bool operator!=(const SlamOptions& a, const SlamOptions& b) { return !(a == b); }

SlamOptions slam_options(const Parameters& params);
ParameterGroup slam_parameter_group();  // table rows, in table order

}  // namespace tunnelmap
