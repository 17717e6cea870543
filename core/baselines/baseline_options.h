#pragma once
// The baseline methods' parameters (ransac.*, qhull.*; stage Baselines), declared once, and the
// options ransac_lse_planes and qhull_tunnel take. The baselines share the cloud range and the
// template window (tunnel.*) with PG&C; these are their own knobs.
#include <cstdint>

#include "core/params/parameter_key.h"

namespace tunnelmap {

class Parameters;

namespace baseline_keys {
inline constexpr ParameterKey<int> ransac_iterations{
    "ransac.iterations", "", 100, 1, 100000, 1, Stage::Baselines, "R&L iterations",
    "Whole RANSAC + LSE segmentations with different random streams; the lowest squared error wins (paper: 100)"};
inline constexpr ParameterKey<int> ransac_sample_step{
    "ransac.sample_step", "px", 1, 1, 64, 1, Stage::Baselines, "R&L pixel step",
    "R&L uses every N-th pixel in u and v (1: the whole frame, as the paper)"};
inline constexpr ParameterKey<double> ransac_distance_mm{
    "ransac.distance_mm", "mm", 15.0, 1.0, 100.0, 0.5, Stage::Baselines, "R&L inlier band",
    "Max point-to-plane distance of a RANSAC inlier (the paper's point-to-plane distance, 15 mm)"};
inline constexpr ParameterKey<int> ransac_max_planes{
    "ransac.max_planes", "", 8, 1, 100, 1, Stage::Baselines, "R&L planes",
    "Planes extracted per RANSAC + LSE segmentation"};
inline constexpr ParameterKey<int> ransac_min_plane_points{
    "ransac.min_plane_points", "points", 40, 3, 100000, 1, Stage::Baselines, "R&L min points",
    "Fewest sampled inliers of a plane; a plane with fewer ends the extraction"};
inline constexpr ParameterKey<int> ransac_max_trials{
    "ransac.max_trials", "", 1000, 1, 100000, 10, Stage::Baselines, "R&L max trials",
    "Most RANSAC hypotheses per plane (fewer when the confidence is reached first)"};
inline constexpr ParameterKey<double> ransac_confidence{
    "ransac.confidence", "", 0.99, 0.5, 0.9999, 0.0001, Stage::Baselines, "R&L confidence",
    "Probability that the adaptive trial count draws at least one all-inlier sample"};
inline constexpr ParameterKey<int> qhull_sample_step{
    "qhull.sample_step", "px", 1, 1, 64, 1, Stage::Baselines, "Qhull pixel step",
    "Qhull uses every N-th pixel in u and v (1: all points)"};
inline constexpr ParameterKey<int> qhull_min_points{
    "qhull.min_points", "points", 1000, 4, 100000, 10, Stage::Baselines, "Qhull min points",
    "Fewer valid points than this: too_few_points"};
inline constexpr ParameterKey<double> qhull_yaw_range_deg{
    "qhull.yaw_range_deg", "deg", 35.0, 0.0, 90.0, 1.0, Stage::Baselines, "Qhull yaw range",
    "Axis search about up, around the camera's forward direction"};
inline constexpr ParameterKey<double> qhull_tilt_range_deg{
    "qhull.tilt_range_deg", "deg", 20.0, 0.0, 90.0, 1.0, Stage::Baselines, "Qhull tilt range",
    "Axis search towards up"};
}  // namespace baseline_keys

struct RansacLseOptions {
  int iterations = baseline_keys::ransac_iterations.default_value;  // whole segmentations
  int sample_step = baseline_keys::ransac_sample_step.default_value;  // every step-th pixel in u and v
  double distance_m = mm_to_m(baseline_keys::ransac_distance_mm.default_value);  // inlier band
  int max_planes = baseline_keys::ransac_max_planes.default_value;  // planes per segmentation
  int min_plane_points = baseline_keys::ransac_min_plane_points.default_value;  // sampled points
  int max_trials = baseline_keys::ransac_max_trials.default_value;  // hypotheses per plane (adaptive)
  double confidence = baseline_keys::ransac_confidence.default_value;
  std::uint32_t seed = 1;  // not a parameter: fixed, so results are reproducible
};
bool operator==(const RansacLseOptions& a, const RansacLseOptions& b);

struct QhullOptions {
  int sample_step = baseline_keys::qhull_sample_step.default_value;  // every step-th pixel (1 = all)
  int min_points = baseline_keys::qhull_min_points.default_value;    // fewer: "too_few_points"
  double yaw_range_deg = baseline_keys::qhull_yaw_range_deg.default_value;    // axis search about up
  double tilt_range_deg = baseline_keys::qhull_tilt_range_deg.default_value;  // axis search towards up
};
bool operator==(const QhullOptions& a, const QhullOptions& b);

struct BaselineOptions {
  RansacLseOptions ransac;
  QhullOptions qhull;
};
bool operator==(const BaselineOptions& a, const BaselineOptions& b);
inline bool operator!=(const BaselineOptions& a, const BaselineOptions& b) { return !(a == b); }

BaselineOptions baseline_options(const Parameters& p);
ParameterGroup baseline_parameter_group();  // table rows and rules, in table order

}  // namespace tunnelmap
