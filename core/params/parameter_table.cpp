#include "core/params/parameter_table.h"

namespace tunnelmap {

const char* stage_name(Stage s) {
  switch (s) {
    case Stage::Cloud: return "cloud";
    case Stage::Normals: return "normals";
    case Stage::Planes: return "planes";
    case Stage::Tunnel: return "tunnel";
    case Stage::Fusion: return "fusion";
    case Stage::Map: return "map";
  }
  return "?";
}

const std::vector<ParameterSpec>& parameter_table() {
  // clang-format off
  static const std::vector<ParameterSpec> table = {
    // key, unit, default, min, max, step, integer, stage, label, description
    {"cloud.max_range_m", "m", 5.0, 0.5, 12.0, 0.1, false, Stage::Cloud, "Max range",
     "Max usable range from the sensing plane; farther pixels are ignored (paper: 5 m)"},
    {"cloud.min_range_m", "m", 0.3, 0.0, 2.0, 0.05, false, Stage::Cloud, "Min range",
     "Pixels nearer than this are ignored (below the sensor's working range)"},
    {"normals.smoothing_px", "px", 10, 3, 41, 1, true, Stage::Normals, "Normal window",
     "Side of the integral-image smoothing window used for per-pixel normals (Holzer et al.)"},
    {"normals.max_depth_change", "", 0.15, 0.005, 1.0, 0.005, false, Stage::Normals,
     "Discontinuity limit",
     "Relative second difference of inverse depth that marks a depth edge (no normal near it); planes give 0"},
    {"grow.angle_deg", "deg", 4.0, 0.5, 30.0, 0.1, false, Stage::Planes, "Normal angle (lambda)",
     "Max angle between a point's normal and the plane's mean normal (eq. 2, paper: 4 deg)"},
    {"grow.distance_mm", "mm", 15.0, 1.0, 100.0, 0.5, false, Stage::Planes,
     "Point-to-plane (epsilon)", "Max point-to-plane distance to join a plane (eq. 2, paper: 15 mm)"},
    {"grow.candidate_distance_mm", "mm", 40.0, 5.0, 300.0, 1.0, false, Stage::Planes,
     "Candidate distance", "Max 3D distance from a region point to a candidate neighbour (paper: 40 mm)"},
    {"grow.neighbourhood_n", "px", 5, 3, 9, 2, true, Stage::Planes, "Neighbourhood n",
     "Candidates are the n*n-1 pixels around a region point; odd (paper: n = 5)"},
    {"grow.min_points", "points", 40, 3, 100000, 1, true, Stage::Planes, "Min points",
     "Fewest points that constitute a plane (paper: 40)"},
    {"grow.min_area_m2", "m2", 0.004, 0.0, 1.0, 0.001, false, Stage::Planes, "Min area",
     "Smallest allowable plane area (paper: 0.004 m2)"},
    {"grow.refit_normal", "", 1, 0, 1, 1, true, Stage::Planes, "Refit normal (PCA)",
     "1: report each plane's least-squares normal from its points; 0: the grown mean normal (eq. 3)"},
    {"grow.grid_step", "px", 2, 1, 4, 1, true, Stage::Planes, "Growing grid step",
     "1: grow over every pixel exactly as the paper; k > 1 (default 2, 2-3x faster, same accuracy): grow "
     "on every k-th pixel and row, then assign each remaining pixel to a neighbouring sample's plane by "
     "the same distance and angle tests"},
    {"grow.edge_on_pass", "", 1, 0, 1, 1, true, Stage::Planes, "Edge-on pass",
     "With grid step > 1: 1 grows every pixel from the unlabelled pixels where grid neighbours lie beyond "
     "the candidate distance (surfaces seen nearly edge-on, e.g. wall edge bands down the tunnel); 0: off"},
    {"tunnel.class_angle_deg", "deg", 35.0, 5.0, 45.0, 1.0, false, Stage::Tunnel, "Class cone",
     "A plane joins a wall class when its normal is within this angle of that class's direction"},
    {"tunnel.outlier_bin_deg", "deg", 1.0, 0.1, 10.0, 0.1, false, Stage::Tunnel, "Histogram bin",
     "Bin width of the normal-deviation histogram used to reject outlier planes per class"},
    {"tunnel.outlier_max_deg", "deg", 8.0, 1.0, 45.0, 0.5, false, Stage::Tunnel, "Outlier limit",
     "Planes whose normal deviates more than this from the class mean are always outliers"},
    {"tunnel.zone_cluster_mm", "mm", 10.0, 1.0, 100.0, 0.5, false, Stage::Tunnel, "Zone cluster gap",
     "Zone planes whose positions differ by less than this are one zone (paper: 10 mm)"},
    {"tunnel.min_cluster_points", "points", 300, 10, 100000, 10, true, Stage::Tunnel,
     "Min zone support",
     "Fewest points a zone cluster needs to bound the tunnel, and a plane needs to link two zone positions"},
    {"tunnel.zone_support_ref_m", "m", 0.0, 0.0, 10.0, 0.05, false, Stage::Tunnel,
     "Zone support distance",
     "Beyond this distance a zone's support is Min zone support * (ref/d)^2, at least 40 points (a patch "
     "covers ~1/d^2 pixels); 0 = the same support at every distance"},
    {"tunnel.zone_gap_ref_m", "m", 0.0, 0.0, 10.0, 0.05, false, Stage::Tunnel, "Zone gap distance",
     "Beyond this distance the zone cluster gap is Zone cluster gap * (d/ref)^2 (depth noise grows "
     "~d^2); 0 = the same gap at every distance"},
    {"tunnel.context_tolerance_mm", "mm", 40.0, 1.0, 500.0, 1.0, false, Stage::Tunnel,
     "Context tolerance",
     "Max width/height change from the previous scans' context in a sequence (paper: 40 mm)"},
    {"tunnel.max_pair_angle_deg", "deg", 10.0, 1.0, 45.0, 0.5, false, Stage::Tunnel,
     "Parallel-pair angle", "Max angle between opposite walls (left/right, top/bottom) to be a pair"},
    {"tunnel.symmetric_step_max_mm", "mm", 30.0, 0.0, 100.0, 1.0, false, Stage::Tunnel,
     "Symmetric zone prior",
     "A wall with one zone cluster borrows the opposite wall's edge-to-middle step up to this size; 0 = off"},
    {"tunnel.width_min_m", "m", 0.3, 0.05, 10.0, 0.01, false, Stage::Tunnel, "Width min",
     "Template prior: smallest plausible tunnel width"},
    {"tunnel.width_max_m", "m", 3.0, 0.1, 20.0, 0.01, false, Stage::Tunnel, "Width max",
     "Template prior: largest plausible tunnel width"},
    {"tunnel.height_min_m", "m", 0.3, 0.05, 10.0, 0.01, false, Stage::Tunnel, "Height min",
     "Template prior: smallest plausible tunnel height"},
    {"tunnel.height_max_m", "m", 3.0, 0.1, 20.0, 0.01, false, Stage::Tunnel, "Height max",
     "Template prior: largest plausible tunnel height"},
    {"zones.forbidden_band_m", "m", 0.15, 0.0, 1.0, 0.005, false, Stage::Tunnel, "Forbidden band",
     "Width of the riveted edge band along each tunnel corner (prior knowledge)"},
    {"tunnel.design_width_m", "m", 0.0, 0.0, 20.0, 0.001, false, Stage::Tunnel, "Design width",
     "The tunnel's design width; infers a wall out of view when the sequence gives no context, and "
     "is the reference of `map` deviations; 0 = no design"},
    {"tunnel.design_height_m", "m", 0.0, 0.0, 20.0, 0.001, false, Stage::Tunnel, "Design height",
     "The tunnel's design height (see Design width); 0 = no design"},
    // The station map of the whole tunnel (docs/tunnel-map.md).
    {"map.station_step_m", "m", 0.10, 0.02, 2.0, 0.01, false, Stage::Map, "Station step",
     "Distance between map stations along the tunnel axis"},
    {"map.tolerance_mm", "mm", 10.0, 0.5, 500.0, 0.5, false, Stage::Map, "Design tolerance",
     "A station whose width or height deviates from the design by more than this is out of tolerance"},
    {"map.section_change_mm", "mm", 12.0, 2.0, 500.0, 0.5, false, Stage::Map, "Section change",
     "Stations whose width or height differs from the current section's by more than this, over at "
     "least Section length stations, start a new section; shorter runs are outliers"},
    {"map.min_section_m", "m", 0.3, 0.05, 10.0, 0.05, false, Stage::Map, "Section length",
     "Shortest stretch of agreeing stations that makes a new section"},
    {"map.min_station_points", "points", 60, 5, 100000, 5, true, Stage::Map, "Station support",
     "Fewest wall points (over all frames) that measure a wall at one station"},
    // Multi-frame fusion (docs/fusion.md). Not from the paper: sensible values for a VGA
    // structured-light camera in a ~1 m tunnel.
    {"fusion.voxel_mm", "mm", 8.0, 2.0, 50.0, 0.5, false, Stage::Fusion, "Voxel size",
     "Edge of one TSDF voxel; memory grows with its inverse cube"},
    {"fusion.truncation_mm", "mm", 30.0, 5.0, 200.0, 1.0, false, Stage::Fusion, "Truncation",
     "TSDF truncation distance; at least ~3 voxels and above the depth noise"},
    {"fusion.max_depth_m", "m", 2.5, 0.5, 10.0, 0.1, false, Stage::Fusion, "Fusion max depth",
     "Depth beyond this is not fused (structured-light noise grows with depth squared)"},
    {"fusion.max_weight", "", 64, 1, 10000, 1, true, Stage::Fusion, "Max weight",
     "Cap of a voxel's running-average weight (frames); lower adapts faster to pose changes"},
    {"fusion.min_weight", "", 2, 1, 1000, 1, true, Stage::Fusion, "Min weight",
     "Mesh only cells whose 8 voxels were seen at least this many times"},
    {"fusion.bounds_margin_m", "m", 0.05, 0.0, 2.0, 0.01, false, Stage::Fusion, "Bounds margin",
     "The volume is the box of all fused points (world frame) grown by this margin"},
    {"fusion.max_extent_m", "m", 12.0, 0.5, 100.0, 0.5, false, Stage::Fusion, "Max extent",
     "Largest volume side; a bigger point box is refused (asks for a coarser voxel or less depth)"},
    {"fusion.pose_group_mm", "mm", 50.0, 1.0, 1000.0, 1.0, false, Stage::Fusion, "Pose grouping",
     "Consecutive frames whose camera moved less than this (and 5 deg) are one arm pose"},
  };
  // clang-format on
  return table;
}

const ParameterSpec* find_parameter(const std::string& key) {
  for (const auto& spec : parameter_table())
    if (spec.key == key) return &spec;
  return nullptr;
}

}  // namespace tunnelmap
