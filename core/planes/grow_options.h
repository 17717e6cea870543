#pragma once
// Stage 3's parameters (grow.*), declared once, and the options extract_planes takes.
#include "core/params/parameter_key.h"

namespace tunnelmap {

class Parameters;

namespace grow_keys {
inline constexpr ParameterKey<double> angle_deg{
    "grow.angle_deg", "deg", 4.0, 0.5, 30.0, 0.1, Stage::Planes, "Normal angle (lambda)",
    "Max angle between a point's normal and the plane's mean normal (eq. 2, paper: 4 deg)"};
inline constexpr ParameterKey<double> distance_mm{
    "grow.distance_mm", "mm", 15.0, 1.0, 100.0, 0.5, Stage::Planes, "Point-to-plane (epsilon)",
    "Max point-to-plane distance to join a plane (eq. 2, paper: 15 mm)"};
inline constexpr ParameterKey<double> candidate_distance_mm{
    "grow.candidate_distance_mm", "mm", 40.0, 5.0, 300.0, 1.0, Stage::Planes, "Candidate distance",
    "Max 3D distance from a region point to a candidate neighbour (paper: 40 mm)"};
inline constexpr ParameterKey<int> neighbourhood_n{
    "grow.neighbourhood_n", "px", 5, 3, 9, 2, Stage::Planes, "Neighbourhood n",
    "Candidates are the n*n-1 pixels around a region point; odd (paper: n = 5)"};
inline constexpr ParameterKey<int> min_points{
    "grow.min_points", "points", 40, 3, 100000, 1, Stage::Planes, "Min points",
    "Fewest points that constitute a plane (paper: 40)"};
inline constexpr ParameterKey<double> min_area_m2{
    "grow.min_area_m2", "m2", 0.004, 0.0, 1.0, 0.001, Stage::Planes, "Min area",
    "Smallest allowable plane area (paper: 0.004 m2)"};
inline constexpr ParameterKey<bool> refit_normal{
    "grow.refit_normal", "", true, 0, 1, 1, Stage::Planes, "Refit normal (PCA)",
    "1: report each plane's least-squares normal from its points; 0: the grown mean normal (eq. 3)"};
inline constexpr ParameterKey<int> grid_step{
    "grow.grid_step", "px", 2, 1, 4, 1, Stage::Planes, "Growing grid step",
    "With cell size 0: 1 grows over every pixel exactly as the paper; k > 1 (default 2, 2-3x faster, same "
    "accuracy): grow on every k-th pixel and row, then assign each remaining pixel to a neighbouring "
    "sample's plane by the same distance and angle tests"};
inline constexpr ParameterKey<bool> edge_on_pass{
    "grow.edge_on_pass", "", true, 0, 1, 1, Stage::Planes, "Edge-on pass",
    "With grid step > 1: 1 grows every pixel from the unlabelled pixels where grid neighbours lie beyond "
    "the candidate distance (surfaces seen nearly edge-on, e.g. wall edge bands down the tunnel); with "
    "cells: 1 grows single pixels from the unlabelled cells where a 5x5 window is seen edge-on; 0: off"};
inline constexpr ParameterKey<int> cell_px{
    "grow.cell_px", "px", 8, 0, 32, 1, Stage::Planes, "Growing cell size",
    "k >= 4 (default 8): grow over k x k pixel cells joined by the eq. 2 tests on their least-squares "
    "planes, then assign the pixels of cells at plane borders one by one (no per-pixel normals, 4-7x "
    "faster); 0: grow on the pixel grid (grid step) with integral-image normals"};
}  // namespace grow_keys

struct GrowOptions {
  double angle_deg = grow_keys::angle_deg.default_value;                         // lambda, eq. 2
  double distance_m = mm_to_m(grow_keys::distance_mm.default_value);             // epsilon, eq. 2
  double candidate_distance_m = mm_to_m(grow_keys::candidate_distance_mm.default_value);
  int neighbourhood_n = grow_keys::neighbourhood_n.default_value;                // n*n-1 candidates
  int min_points = grow_keys::min_points.default_value;
  double min_area_m2 = grow_keys::min_area_m2.default_value;
  bool refit_normal = grow_keys::refit_normal.default_value;  // least-squares normal of the grown points
  int grid_step = grow_keys::grid_step.default_value;  // every k-th pixel, then assign the rest (1 = the paper)
  bool edge_on_pass = grow_keys::edge_on_pass.default_value;  // every-pixel growing where the grid cannot connect
  int cell_px = grow_keys::cell_px.default_value;  // 0: pixel grid; k: k x k cells (cell_growing.h)
  bool compute_contours = true;  // not a parameter: callers that draw no contours turn it off
};
bool operator==(const GrowOptions& a, const GrowOptions& b);
inline bool operator!=(const GrowOptions& a, const GrowOptions& b) { return !(a == b); }

GrowOptions grow_options(const Parameters& p);
// Whether extract_planes reads the cloud's per-pixel normals: the cell-based order does not, so
// callers skip the normals stage (1.5 ms per VGA frame) for it.
inline bool needs_point_normals(const GrowOptions& o) { return o.cell_px == 0; }
ParameterGroup grow_parameter_group();  // table rows and rules, in table order

}  // namespace tunnelmap
