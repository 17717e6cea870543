#pragma once
// Stage 4's parameters (tunnel.*, zones.*), declared once, and the options detect_tunnel takes.
#include "core/params/parameter_key.h"

namespace tunnelmap {

class Parameters;

namespace tunnel_keys {
inline constexpr ParameterKey<double> class_angle_deg{
    "tunnel.class_angle_deg", "deg", 35.0, 5.0, 45.0, 1.0, Stage::Tunnel, "Class cone",
    "A plane joins a wall class when its normal is within this angle of that class's direction"};
inline constexpr ParameterKey<double> outlier_bin_deg{
    "tunnel.outlier_bin_deg", "deg", 1.0, 0.1, 10.0, 0.1, Stage::Tunnel, "Histogram bin",
    "Bin width of the normal-deviation histogram used to reject outlier planes per class"};
inline constexpr ParameterKey<double> outlier_max_deg{
    "tunnel.outlier_max_deg", "deg", 8.0, 1.0, 45.0, 0.5, Stage::Tunnel, "Outlier limit",
    "Planes whose normal deviates more than this from the class mean are always outliers"};
inline constexpr ParameterKey<double> zone_cluster_mm{
    "tunnel.zone_cluster_mm", "mm", 10.0, 1.0, 100.0, 0.5, Stage::Tunnel, "Zone cluster gap",
    "Zone planes whose positions differ by less than this are one zone (paper: 10 mm)"};
inline constexpr ParameterKey<int> min_cluster_points{
    "tunnel.min_cluster_points", "points", 300, 10, 100000, 10, Stage::Tunnel, "Min zone support",
    "Fewest points a zone cluster needs to bound the tunnel, and a plane needs to link two zone positions"};
inline constexpr ParameterKey<double> zone_support_ref_m{
    "tunnel.zone_support_ref_m", "m", 0.0, 0.0, 10.0, 0.05, Stage::Tunnel, "Zone support distance",
    "Beyond this distance a zone's support is Min zone support * (ref/d)^2, at least 40 points (a patch "
    "covers ~1/d^2 pixels); 0 = the same support at every distance"};
inline constexpr ParameterKey<double> zone_gap_ref_m{
    "tunnel.zone_gap_ref_m", "m", 0.0, 0.0, 10.0, 0.05, Stage::Tunnel, "Zone gap distance",
    "Beyond this distance the zone cluster gap is Zone cluster gap * (d/ref)^2 (depth noise grows "
    "~d^2); 0 = the same gap at every distance"};
inline constexpr ParameterKey<double> context_tolerance_mm{
    "tunnel.context_tolerance_mm", "mm", 40.0, 1.0, 500.0, 1.0, Stage::Tunnel, "Context tolerance",
    "Max width/height change from the previous scans' context in a sequence (paper: 40 mm)"};
inline constexpr ParameterKey<double> max_pair_angle_deg{
    "tunnel.max_pair_angle_deg", "deg", 10.0, 1.0, 45.0, 0.5, Stage::Tunnel, "Parallel-pair angle",
    "Max angle between opposite walls (left/right, top/bottom) to be a pair"};
inline constexpr ParameterKey<double> symmetric_step_max_mm{
    "tunnel.symmetric_step_max_mm", "mm", 30.0, 0.0, 100.0, 1.0, Stage::Tunnel, "Symmetric zone prior",
    "A wall with one zone cluster borrows the opposite wall's edge-to-middle step up to this size; 0 = off"};
inline constexpr ParameterKey<double> width_min_m{
    "tunnel.width_min_m", "m", 0.3, 0.05, 10.0, 0.01, Stage::Tunnel, "Width min",
    "Template prior: smallest plausible tunnel width"};
inline constexpr ParameterKey<double> width_max_m{
    "tunnel.width_max_m", "m", 3.0, 0.1, 20.0, 0.01, Stage::Tunnel, "Width max",
    "Template prior: largest plausible tunnel width"};
inline constexpr ParameterKey<double> height_min_m{
    "tunnel.height_min_m", "m", 0.3, 0.05, 10.0, 0.01, Stage::Tunnel, "Height min",
    "Template prior: smallest plausible tunnel height"};
inline constexpr ParameterKey<double> height_max_m{
    "tunnel.height_max_m", "m", 3.0, 0.1, 20.0, 0.01, Stage::Tunnel, "Height max",
    "Template prior: largest plausible tunnel height"};
inline constexpr ParameterKey<double> forbidden_band_m{
    "zones.forbidden_band_m", "m", 0.15, 0.0, 1.0, 0.005, Stage::Tunnel, "Forbidden band",
    "Width of the riveted edge band along each tunnel corner (prior knowledge)"};
inline constexpr ParameterKey<double> design_width_m{
    "tunnel.design_width_m", "m", 0.0, 0.0, 20.0, 0.001, Stage::Tunnel, "Design width",
    "The tunnel's design width; infers a wall out of view when the sequence gives no context, and "
    "is the reference of `map` deviations; 0 = no design"};
inline constexpr ParameterKey<double> design_height_m{
    "tunnel.design_height_m", "m", 0.0, 0.0, 20.0, 0.001, Stage::Tunnel, "Design height",
    "The tunnel's design height (see Design width); 0 = no design"};
}  // namespace tunnel_keys

struct TunnelOptions {
  double class_angle_deg = tunnel_keys::class_angle_deg.default_value;
  double outlier_bin_deg = tunnel_keys::outlier_bin_deg.default_value;
  double outlier_max_deg = tunnel_keys::outlier_max_deg.default_value;
  double zone_cluster_m = mm_to_m(tunnel_keys::zone_cluster_mm.default_value);
  int min_cluster_points = tunnel_keys::min_cluster_points.default_value;
  // Zone support / gap scaling with the wall's distance (zone_support.h); 0 = off.
  double zone_support_ref_m = tunnel_keys::zone_support_ref_m.default_value;
  double zone_gap_ref_m = tunnel_keys::zone_gap_ref_m.default_value;
  double context_tolerance_m = mm_to_m(tunnel_keys::context_tolerance_mm.default_value);
  double max_pair_angle_deg = tunnel_keys::max_pair_angle_deg.default_value;
  double width_min_m = tunnel_keys::width_min_m.default_value;
  double width_max_m = tunnel_keys::width_max_m.default_value;
  double height_min_m = tunnel_keys::height_min_m.default_value;
  double height_max_m = tunnel_keys::height_max_m.default_value;
  double forbidden_band_m = tunnel_keys::forbidden_band_m.default_value;
  // Symmetric zone prior (zone_clustering.h): a wall seen only by its middle plate borrows the
  // opposite wall's edge-to-middle step, up to this size (0 = off).
  double max_symmetric_step_m = mm_to_m(tunnel_keys::symmetric_step_max_mm.default_value);
  // Design prior (0 = none): infers a wall out of view from the opposite wall, or gives the
  // dimension itself when neither wall of the pair was measured.
  double design_width_m = tunnel_keys::design_width_m.default_value;
  double design_height_m = tunnel_keys::design_height_m.default_value;
};
bool operator==(const TunnelOptions& a, const TunnelOptions& b);
inline bool operator!=(const TunnelOptions& a, const TunnelOptions& b) { return !(a == b); }

TunnelOptions tunnel_options(const Parameters& p);
ParameterGroup tunnel_parameter_group();  // table rows and rules, in table order

}  // namespace tunnelmap
