#include "core/mapping/structure_slam.h"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cassert>
#include <chrono>
#include <cmath>
#include <unordered_map>

#include "core/mapping/compartment_bends.h"
#include "core/mapping/slam_patches.h"
#include "core/solvers/correction_evidence.h"

namespace tunnelmap {

namespace {

constexpr double kDeg = M_PI / 180.0;
constexpr double kMinPlateReachM = 0.05;  // plates nearer than this along the girder are one

// A kind of wall surface: the wall, and its middle plate or its outer surface.
int surface_kind(const FramePatch& patch) { return patch.wall * 2 + (patch.zone == FramePatch::Zone::Inner ? 1 : 0); }

// The graph solved under the evidence test. The measurements alone (odometry, plates and
// walls, without the walls' continuity ties) must demand a correction of the given poses
// (`at_given` solves a graph with them held); the ties then shape the correction, starting
// from the measurements' optimum, but never demand one: a tie holds two stretches of wall to
// a couple of millimetres, finer than a wall beyond a plate is always known, and exact poses
// must stay exact.
template <typename AtGiven>
PoseGraphSolution solve_under_evidence(PoseGraph graph, const PoseGraphOptions& options, int free_poses,
                                       double sigmas, AtGiven at_given, CorrectionEvidence& evidence,
                                       bool& kept) {
  std::vector<PlaneContinuity> ties;
  std::vector<PlaneBend> bends;
  ties.swap(graph.continuities);
  bends.swap(graph.bends);
  PoseGraphSolution s = solve_pose_graph(graph, options);
  kept = false;
  evidence = correction_evidence(0.0, 0.0, free_poses, 0.0);
  if (sigmas > 0.0) {
    PoseGraphSolution given = at_given(graph);
    evidence = correction_evidence(given.final_cost, s.final_cost, free_poses, sigmas);
    kept = !evidence.significant;
    if (kept) return given;
  }
  if (ties.empty() && bends.empty()) return s;
  graph.continuities = std::move(ties);
  graph.bends = std::move(bends);
  graph.poses = s.poses;
  graph.planes = s.planes;
  return solve_pose_graph(graph, options);
}

// The tunnel's axis in the world, pointing the way `forward` does.
Eigen::Vector3d oriented(const Eigen::Vector3d& axis, const Eigen::Vector3d& forward) {
  return axis.dot(forward) < 0 ? -axis : axis;
}

}  // namespace

StructureSlam::StructureSlam(SlamOptions options)
    : options_(options), plates_({options.odometry_m_per_sqrt_m, kMinPlateReachM, options.plate_gate_m}),
      bands_(options.band_m, {}) {}

void StructureSlam::start_group(const Eigen::Isometry3d& pose, int id) {
  Group g;
  g.id = id;
  g.odometry = pose;
  if (groups_.empty()) {
    g.axis = pose.linear().col(2);
    g.up = -pose.linear().col(1);
    graph_.poses.push_back(pose);
    graph_.fixed.push_back(true);  // the map's frame is the first pose's
  } else {
    // The previous group's axis until this group's first detection gives its own: stations
    // then follow a curving girder as arc length along the walk.
    const Group& prev = groups_.back();
    g.axis = prev.axis;
    g.up = prev.up;
    const Eigen::Isometry3d relative = prev.odometry.inverse() * pose;
    g.station_m = prev.station_m + prev.axis.dot(pose.translation() - prev.odometry.translation());
    // Where the odometry factor expects it: with world-frame drift the step is the world's,
    // whatever the heading's correction (composed in the camera's frame, a heading 5 degrees
    // off would start each group 5 cm sideways, past where its walls land on the map's).
    Eigen::Isometry3d start = graph_.poses.back() * relative;
    if (options_.odometry_in_world) start.translation() = graph_.poses.back().translation() + (pose.translation() - prev.odometry.translation());
    graph_.poses.push_back(start);
    graph_.fixed.push_back(false);
    const double d = relative.translation().norm();
    GraphOdometry o;
    o.from = static_cast<int>(groups_.size()) - 1;
    o.to = static_cast<int>(groups_.size());
    o.relative = relative;
    o.world_translation = options_.odometry_in_world;
    o.world_step = pose.translation() - prev.odometry.translation();
    o.sigma_m = std::max(options_.odometry_m_per_sqrt_m * std::sqrt(d), options_.min_odometry_m);
    o.sigma_rad = std::max(options_.odometry_deg_per_sqrt_m * std::sqrt(d), options_.min_odometry_deg) * kDeg;
    graph_.odometry.push_back(o);
  }
  groups_.push_back(g);
}

std::vector<double> StructureSlam::group_stations_m() const {
  std::vector<double> stations;
  for (const Group& g : groups_) stations.push_back(g.station_m);
  return stations;
}

int StructureSlam::add_plane(const Eigen::Vector3d& normal, double offset) {
  graph_.planes.push_back({normal, offset});
  layer_zone_.push_back(FramePatch::Zone::Unknown);
  return static_cast<int>(graph_.planes.size()) - 1;
}

int StructureSlam::plate_landmark(const FramePatch& patch, const Eigen::Isometry3d& camera_to_world,
                                  double camera_station_m) {
  // A view of a known plate (core/mapping/plate_tracks.h), or a new plate's landmark.
  return plates_.view(patch.station_m, patch.sigma_m, camera_station_m, [&] {
    const Eigen::Vector3d normal = camera_to_world.linear() * patch.normal;
    return add_plane(normal, normal.dot(camera_to_world * patch.centroid));
  });
}

std::vector<int> StructureSlam::wall_layers(const std::vector<const FramePatch*>& patches,
                                            const Eigen::Isometry3d& camera_to_world) {
  // The frame's pose error moves its view of a wall along the wall's normal by a shift that
  // changes linearly along the girder (an offset and a heading error): shift(s) = a + b (s - s0).
  // Opposite walls (left and right, top and bottom) face opposite ways, so one pose error
  // shifts them by opposite amounts: the line is the first wall's shift, the second's negated.
  // A wall's layers lie a plate's thickness apart, about as far as a frame's odometry may be
  // off, so one wall alone cannot tell which layer it sees; the wall opposite can.
  struct Line {
    double a = 0.0, b = 0.0;
  };
  auto sign = [](const FramePatch* p) { return p->wall % 2 == 0 ? 1.0 : -1.0; };
  double s0 = 0.0;
  for (const FramePatch* p : patches) s0 += p->station_m;
  if (!patches.empty()) s0 /= static_cast<double>(patches.size());
  auto layers_of = [&](const FramePatch* p) -> const std::vector<int>* {
    const auto it = wall_landmarks_.find({p->wall, p->band});
    return it == wall_landmarks_.end() ? nullptr : &it->second;
  };
  auto offset_of = [&](const FramePatch* p, int plane) {
    const GraphPlane& L = graph_.planes[static_cast<std::size_t>(plane)];
    return L.offset - L.normal.dot(camera_to_world * p->centroid);  // the shift that lands p on it
  };
  auto shift_at = [&](const FramePatch* p, const Line& line) {
    return sign(p) * (line.a + line.b * (p->station_m - s0));
  };
  // The nearest layer within reach: two layers a plate's thickness apart may both be.
  auto layer_near = [&](const FramePatch* p, const Line& line) {
    const std::vector<int>* layers = layers_of(p);
    if (!layers) return -1;
    const double shift = shift_at(p, line);
    int nearest = -1;
    double nearest_gap = options_.layer_tolerance_m;
    for (int plane : *layers) {
      const double gap = std::abs(offset_of(p, plane) - shift);
      if (gap <= nearest_gap) nearest_gap = gap, nearest = plane;
    }
    return nearest;
  };
  // Candidate lines: no shift, each patch-on-layer shift, and each pair of them far enough
  // apart along the girder to give a heading.
  struct Landing {
    double station, shift;
  };
  std::vector<Landing> landings;
  for (const FramePatch* p : patches)
    if (const std::vector<int>* layers = layers_of(p))
      for (int plane : *layers) {
        const double shift = sign(p) * offset_of(p, plane);
        if (std::abs(shift) <= options_.max_layer_shift_m) landings.push_back({p->station_m, shift});
      }
  std::vector<Line> lines = {Line{}};
  for (std::size_t i = 0; i < landings.size(); ++i) {
    lines.push_back({landings[i].shift, 0.0});
    for (std::size_t j = i + 1; j < landings.size(); ++j) {
      const double ds = landings[j].station - landings[i].station;
      if (std::abs(ds) < 0.5) continue;
      const double b = (landings[j].shift - landings[i].shift) / ds;
      if (std::abs(b) <= options_.max_layer_slope) lines.push_back({landings[i].shift + b * (s0 - landings[i].station), b});
    }
  }
  // The line that lands the most points on known layers; the smaller one on a tie.
  Line best;
  long best_points = -1;
  for (const Line& line : lines) {
    long points = 0;
    for (const FramePatch* p : patches)
      if (layer_near(p, line) >= 0) points += p->points;
    const double size = std::abs(line.a) + std::abs(line.b);
    if (points > best_points || (points == best_points && size < std::abs(best.a) + std::abs(best.b)))
      best_points = points, best = line;
  }
  std::vector<int> planes;
  for (const FramePatch* p : patches) {
    int plane = layer_near(p, best);
    if (plane < 0) {
      const Eigen::Vector3d normal = camera_to_world.linear() * p->normal;
      plane = add_plane(normal, normal.dot(camera_to_world * p->centroid) + shift_at(p, best));
      wall_landmarks_[{p->wall, p->band}].push_back(plane);
    }
    FramePatch::Zone& zone = layer_zone_[static_cast<std::size_t>(plane)];
    if (zone == FramePatch::Zone::Unknown) zone = p->zone;
    if (zone != FramePatch::Zone::Unknown && zone == p->zone) continue_wall(*p, plane, camera_to_world * p->centroid);
    planes.push_back(plane);
  }
  return planes;
}

// A girder's walls run on through its diaphragms: the floor beyond a plate continues the floor
// before it. The frames near a plate see little of the floor and roof, and none sees both
// sides, so without this the map's height (and its sideways position) starts afresh in each
// compartment from where the odometry put it. Each band's outer surface, and its middle
// plate, is tied to the nearest one of its kind along the same wall across a plate the walk
// has seen (within a compartment the frames that see both bands already tie them). The zone
// is what the frame took the patch for; it only chooses the kind and never where a patch
// lands (a landing held to it misplaced whole walls where frames misjudged their zones).
void StructureSlam::continue_wall(const FramePatch& patch, int plane, const Eigen::Vector3d& point) {
  if (!(options_.wall_continuity_m > 0.0)) return;
  const int kind = surface_kind(patch);
  const auto [it, added] = zone_layers_.try_emplace({kind, patch.band}, ZoneLayer{plane, point, patch.station_m});
  if (!added) return;
  // The point between the two, held by the current pose so that it moves with the map.
  auto tie = [&](const ZoneLayer& other, long other_band) {
    if (other.plane == plane || !bands_.plate_between(other_band, patch.band)) return;
    const Eigen::Isometry3d& pose = graph_.poses.back();
    const ZoneLayer here{plane, point, patch.station_m};
    const double plate_m = plate_between(other, here);
    const Eigen::Vector3d between = pose.inverse() * wall_at_plate(other, here, plate_m);
    // A side wall's normal along the world's up is the sine of the girder's cross-fall: the
    // same either side of the plate unless the girder rolls there, however it turns or climbs
    // (a turn about the up leaves it, a climb turns about the normal itself). Against the
    // girder's own up instead, a curve that climbs would read as a roll at every plate, all
    // one way. A floor's or roof's normal says nothing of a roll along the up.
    const bool side_wall = patch.wall / 2 == 0;
    const Eigen::Vector3d up = pose.linear().transpose() * options_.world_up;
    graph_.continuities.push_back({other.plane, plane, static_cast<int>(groups_.size()) - 1, between,
                                   options_.wall_continuity_m, up, side_wall ? options_.wall_turn_rad : 0.0});
    tie_crossings_.push_back({patch.wall / 2, plate_m, std::min(other_band, patch.band), std::max(other_band, patch.band)});
  };
  auto near = [&](long other_band) {  // the unseen stretch between the two bands
    const long first = std::min(other_band, patch.band), last = std::max(other_band, patch.band);
    return bands_.from_m(last) - bands_.to_m(first) <= options_.max_continuity_gap_m;
  };
  if (it != zone_layers_.begin()) {
    const auto below = std::prev(it);
    if (below->first.first == kind && near(below->first.second)) tie(below->second, below->first.second);
  }
  const auto above = std::next(it);
  if (above != zone_layers_.end() && above->first.first == kind && near(above->first.second))
    tie(above->second, above->first.second);
}

// The girder's turn tied from one compartment to the next, once the walk has seen its plates.
std::vector<PlaneBend> StructureSlam::turn_ties() const {
  if (!(options_.compartment_turn_rad > 0.0)) return {};
  return compartment_bends(wall_bands(), cuts_m_, options_.compartment_turn_rad);
}

std::vector<std::vector<EvenTurn>> StructureSlam::even_turns() const {
  return compartment_even_turns(wall_bands(), cuts_m_, options_.compartment_turn_rad);
}

std::vector<WallBand> StructureSlam::wall_bands() const {
  std::vector<WallBand> bands;
  for (const auto& [key, layer] : zone_layers_)
    bands.push_back({key.first, bands_.from_m(key.second), bands_.to_m(key.second), layer.plane});
  return bands;
}

// Where the map, its turn tied to a quadratic, turns evenly (a straight or an arc), the even
// turn is tied as well and the graph solved again from there (core/mapping/compartment_bends.h).
PoseGraphSolution StructureSlam::with_even_turns(const PoseGraphSolution& tied) const {
  if (!(options_.compartment_turn_rad > 0.0)) return tied;
  const std::vector<PlaneBend> even = even_turns_where_the_map_turns_evenly(even_turns(), tied.planes);
  if (even.empty()) return tied;
  PoseGraph graph = graph_;
  graph.poses = tied.poses;
  graph.planes = tied.planes;
  graph.bends.insert(graph.bends.end(), even.begin(), even.end());
  PoseGraphSolution out = solve_pose_graph(graph);
  out.iterations += tied.iterations;
  out.converged = out.converged && tied.converged;
  return out;
}

// Each plate cuts the cell it was first seen in, where the plate is now estimated to lie (kept
// within that cell): the bands' keys keep their meaning while the estimate moves by
// centimetres, and the cut follows the estimate, which the nearer views make better.
void StructureSlam::cut_bands_at_plates() {
  for (int i = static_cast<int>(cut_cells_.size()); i < plates_.size(); ++i)
    cut_cells_.push_back(static_cast<long>(std::floor(plates_.station_m(i) / options_.band_m)));
  cuts_m_.clear();
  for (int i = 0; i < plates_.size(); ++i) {
    const double lo = static_cast<double>(cut_cells_[static_cast<std::size_t>(i)]) * options_.band_m;
    const double hi = std::nextafter(lo + options_.band_m, lo);
    cuts_m_.push_back(std::clamp(plates_.station_m(i), lo, hi));
  }
  bands_ = WallBandGrid(options_.band_m, cuts_m_);
}

// Where two stretches of a wall either side of a plate meet: on the line between their points,
// at the plate. A girder that curves turns there (a chorded girder kinks at its plates), and
// two planes that meet at an angle agree on their distance from a point only where they meet;
// the midpoint of two points seen at different distances from the plate would see the turn
// as a step (a 1.5 degree kink and points 1 m and 3 m from the plate: 26 mm).
Eigen::Vector3d StructureSlam::wall_at_plate(const ZoneLayer& a, const ZoneLayer& b, double plate_m) const {
  if (std::isnan(plate_m) || !(std::abs(b.station_m - a.station_m) > 0.0)) return 0.5 * (a.point + b.point);
  const double t = (plate_m - a.station_m) / (b.station_m - a.station_m);
  return a.point + t * (b.point - a.point);
}

// The tracked plate between two stretches of wall nearest their middle; NaN if none.
double StructureSlam::plate_between(const ZoneLayer& a, const ZoneLayer& b) const {
  const double lo = std::min(a.station_m, b.station_m), hi = std::max(a.station_m, b.station_m);
  return plates_.nearest_within(lo, hi, 0.5 * (lo + hi));
}

// A girder's section may change at a diaphragm: past the plate the roof rises, or the floor
// drops. Its walls then do not run on through the plate, and the ties of two opposite walls
// disagree by the change. Where the section the frames measured on either side (each frame
// its own: core/mapping/section_sizes.h) changes by more than the two ties' tolerance allows,
// neither wall of the pair, at either zone, is held at its distance across that plate: which
// one stepped only frames that see across the plate can tell, and they need no tie. Held
// together, the two ties split the change between the walls and pull the map beyond the
// plate with it (`PoseRefinement.ARoofThatRisesPastAPlateIsNotTiedToTheRoofBeforeIt`). A side
// wall keeps its roll tie: a wider section does not roll.
void StructureSlam::free_ties_across_section_changes() {
  constexpr double kChangeSigmas = 3.0;
  constexpr double kSamePlateM = 0.5;  // plates lie metres apart; one plate's estimate moves by centimetres
  assert(tie_crossings_.size() == graph_.continuities.size());
  const double limit = kChangeSigmas * std::sqrt(2.0) * options_.wall_continuity_m;
  const auto same_crossing = [&](const TieCrossing& a, const TieCrossing& b) {
    return a.dimension == b.dimension && std::abs(a.plate_m - b.plate_m) < kSamePlateM;
  };
  // Per tie: whether the section changes where it crosses, judged once per crossing (by its
  // first tie) over the bands either side that all the crossing's ties name.
  std::vector<bool> changes(tie_crossings_.size(), false);
  for (std::size_t i = 0; i < tie_crossings_.size(); ++i) {
    const auto first = std::find_if(tie_crossings_.begin(), tie_crossings_.end(),
                                    [&](const TieCrossing& t) { return same_crossing(tie_crossings_[i], t); });
    if (const auto j = static_cast<std::size_t>(first - tie_crossings_.begin()); j < i) {
      changes[i] = changes[j];
      continue;
    }
    std::vector<long> before, after;
    for (const TieCrossing& other : tie_crossings_)
      if (same_crossing(tie_crossings_[i], other)) before.push_back(other.before), after.push_back(other.after);
    changes[i] = std::abs(section_sizes_.change(tie_crossings_[i].dimension, before, after, limit)) > limit;
  }
  std::vector<PlaneContinuity> kept;
  std::vector<TieCrossing> kept_crossings;
  for (std::size_t i = 0; i < tie_crossings_.size(); ++i) {
    PlaneContinuity c = graph_.continuities[i];
    if (changes[i]) c.sigma_m = 0.0;
    if (!(c.sigma_m > 0.0) && !(c.sigma_rad > 0.0)) continue;
    kept.push_back(c);
    kept_crossings.push_back(tie_crossings_[i]);
  }
  graph_.continuities.swap(kept);
  tie_crossings_.swap(kept_crossings);
}

void StructureSlam::add_patches(const TunnelMap& map, const FrameWalls& walls, const Eigen::Isometry3d& offset) {
  Group& g = groups_.back();
  const int pose = static_cast<int>(groups_.size()) - 1;
  const Eigen::Isometry3d frame_to_world = graph_.poses.back() * offset;
  const Eigen::Isometry3d frame_odometry = g.odometry * offset;
  // The frame's view of the axis: its own detection, oriented as the walk goes; a frame that
  // found no cross-section takes its group's (the walk's so far).
  const bool own_axis = map.detected;
  const Eigen::Vector3d axis_world = own_axis ? oriented(frame_odometry.linear() * map.axis_dir, g.axis) : g.axis;
  walk_has_axis_ = walk_has_axis_ || own_axis;
  if (own_axis && !g.has_axis) {
    g.axis = axis_world;
    g.up = frame_odometry.linear() * map.up;
    g.has_axis = true;
  }
  const Eigen::Vector3d axis_cam = frame_odometry.linear().transpose() * axis_world;
  const double camera_station = g.station_m + g.axis.dot(frame_odometry.translation() - g.odometry.translation());
  // Plates first: a wall band is cut at a plate inside it, this frame's own new plates too.
  std::vector<FramePatch> patches = frame_plate_patches(map, walls, camera_station, axis_cam, options_);
  std::vector<int> planes;
  for (const FramePatch& plate : patches) planes.push_back(plate_landmark(plate, frame_to_world, camera_station));
  cut_bands_at_plates();
  for (const FramePatch& wall : frame_wall_patches(map, walls, camera_station, axis_cam, options_, bands_)) {
    patches.push_back(wall);
    planes.push_back(-1);
  }
  section_sizes_.record(patches);
  for (int pair = 0; pair < 4; pair += 2) {  // left and right, top and bottom
    std::vector<const FramePatch*> on_wall;
    std::vector<std::size_t> index;
    for (std::size_t k = 0; k < patches.size(); ++k)
      if (!patches[k].plate && patches[k].wall / 2 == pair / 2) on_wall.push_back(&patches[k]), index.push_back(k);
    const std::vector<int> layers = wall_layers(on_wall, frame_to_world);
    for (std::size_t k = 0; k < index.size(); ++k) planes[index[k]] = layers[k];
  }
  for (std::size_t k = 0; k < patches.size(); ++k) {
    const FramePatch& patch = patches[k];
    const int plane = planes[k];
    PlanePatch p;
    p.pose = pose;
    p.plane = plane;
    p.centroid = offset * patch.centroid;
    p.spread = offset.linear() * patch.spread;
    p.sigma_m = patch.sigma_m;
    graph_.patches.push_back(p);
    share_systematic_error(pose, plane, patch.sigma_m);
    g.samples += patch.points;
  }
}

// Frames of one pose group see a plane from (nearly) one place, so its depth's systematic error
// (the quantisation's steps, the floor) is theirs in common and does not average over them: k
// frames' patches of one plane together weigh as much as one frame's (each sigma times sqrt(k)).
// Counted as independent, the ten frames of one arm pose made the evidence test take that
// common error for a pose error.
void StructureSlam::share_systematic_error(int pose, int plane, double sigma_m) {
  SharedView& view = shared_views_[{pose, plane}];
  if (view.last_frame != frames_) ++view.frames, view.last_frame = frames_;
  view.patches.push_back(graph_.patches.size() - 1);
  base_sigma_m_.push_back(sigma_m);
  const double scale = std::sqrt(static_cast<double>(view.frames));
  for (std::size_t i : view.patches) graph_.patches[i].sigma_m = base_sigma_m_[i] * scale;
}

Eigen::Isometry3d StructureSlam::add_frame(const TunnelMap& map, const FrameWalls& walls,
                                           const Eigen::Isometry3d& pose, int group,
                                           const std::optional<Eigen::Vector3d>& gravity) {
  const auto t0 = std::chrono::steady_clock::now();
  if (groups_.empty() || groups_.back().id != group) start_group(pose, group);
  Group& g = groups_.back();
  const Eigen::Isometry3d offset = g.odometry.inverse() * pose;
  // The group's pose is its first frame's camera: the frame's gravity turned into it.
  if (gravity && options_.gravity_rad > 0.0)
    graph_.gravities.push_back({static_cast<int>(groups_.size()) - 1, offset.linear() * gravity->normalized(),
                                -options_.world_up.normalized(), options_.gravity_rad});
  g.frames.push_back(frames_++);
  g.offsets.push_back(offset);
  // A frame with no cross-section of its own may still see a plate (core/mapping/frame_walls.h),
  // told from a wall by the girder's axis once a detected frame has given it.
  if (map.detected || (walk_has_axis_ && !walls.samples.empty())) {
    add_patches(map, walls, offset);
    solve_window();
  }
  last_frame_ms_ = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
  frames_ms_ += last_frame_ms_;
  return graph_.poses.back() * offset;
}

// The latest `window_groups` groups move; the same number before them hold still and tie the
// window's landmarks to the map already built.
void StructureSlam::solve_window() {
  const int n = static_cast<int>(groups_.size());
  const int free_from = std::max(1, n - options_.window_groups);
  const int from = std::max(0, free_from - options_.window_groups);
  if (free_from >= n) return;
  PoseGraph window;
  std::unordered_map<int, int> plane_index;  // graph plane -> window plane
  std::vector<int> planes_used;
  for (int g = from; g < n; ++g) {
    window.poses.push_back(graph_.poses[static_cast<std::size_t>(g)]);
    window.fixed.push_back(g < free_from);
  }
  // Odometry and patches are stored in pose order: the window's are the tail of each, so the
  // time per frame does not grow with the sequence.
  const auto first_odometry = std::lower_bound(graph_.odometry.begin(), graph_.odometry.end(), from,
                                               [](const GraphOdometry& o, int pose) { return o.from < pose; });
  for (auto it = first_odometry; it != graph_.odometry.end(); ++it) {
    GraphOdometry o = *it;
    o.from -= from;
    o.to -= from;
    window.odometry.push_back(o);
  }
  const auto first_patch = std::lower_bound(graph_.patches.begin(), graph_.patches.end(), from,
                                            [](const PlanePatch& p, int pose) { return p.pose < pose; });
  for (auto it = first_patch; it != graph_.patches.end(); ++it) {
    const auto [entry, added] = plane_index.try_emplace(it->plane, static_cast<int>(window.planes.size()));
    if (added) {
      window.planes.push_back(graph_.planes[static_cast<std::size_t>(it->plane)]);
      planes_used.push_back(it->plane);
    }
    PlanePatch q = *it;
    q.pose -= from;
    q.plane = entry->second;
    window.patches.push_back(q);
  }
  const auto first_gravity = std::lower_bound(graph_.gravities.begin(), graph_.gravities.end(), from,
                                              [](const PoseGravity& g, int pose) { return g.pose < pose; });
  for (auto it = first_gravity; it != graph_.gravities.end(); ++it) {
    PoseGravity g = *it;
    g.pose -= from;
    window.gravities.push_back(g);
  }
  // The walls' continuity ties stay out of the windows: a window's correction is the
  // measurements' alone. Tie-shaped window states would start the batch's evidence solve
  // (finish()) away from the measurements' own optimum, and a girder walked with exact poses
  // was corrected by 7 mm that way; the batch applies the ties to the whole walk.
  PoseGraphOptions po;
  po.max_iterations = options_.window_iterations;
  CorrectionEvidence evidence;
  bool kept = false;
  const PoseGraphSolution s = solve_under_evidence(
      std::move(window), po, n - free_from, options_.correction_sigmas,
      [&](const PoseGraph& g) { return solve_window_at_given_poses(g, from, free_from, po); }, evidence, kept);
  for (int g = free_from; g < n; ++g) graph_.poses[static_cast<std::size_t>(g)] = s.poses[static_cast<std::size_t>(g - from)];
  for (std::size_t k = 0; k < planes_used.size(); ++k) graph_.planes[static_cast<std::size_t>(planes_used[k])] = s.planes[k];
}

// The window's null hypothesis: its free groups where the odometry puts them from the last
// group held still (every pose held, the landmarks refitted). Exact odometry then stays exact
// while the walk runs, as it does in the batch (finish()).
PoseGraphSolution StructureSlam::solve_window_at_given_poses(PoseGraph window, int from, int free_from,
                                                            const PoseGraphOptions& options) const {
  for (int g = free_from; g < static_cast<int>(groups_.size()); ++g) {
    const auto k = static_cast<std::size_t>(g - from);
    const Eigen::Isometry3d step = groups_[static_cast<std::size_t>(g) - 1].odometry.inverse() * groups_[static_cast<std::size_t>(g)].odometry;
    window.poses[k] = window.poses[k - 1] * step;
    window.fixed[k] = true;
  }
  return solve_pose_graph(window, options);
}

PoseCorrection StructureSlam::correction(std::size_t g) const {
  const Group& group = groups_[g];
  PoseCorrection c;
  c.group = group.id;
  c.frames = group.frames;
  c.delta = graph_.poses[g] * group.odometry.inverse();
  c.rotation_deg = Eigen::AngleAxisd(c.delta.linear()).angle() / kDeg;
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();
  for (const Eigen::Isometry3d& o : group.offsets) centre += (group.odometry * o).translation();
  centre /= static_cast<double>(group.offsets.size());
  c.translation_mm = (c.delta * centre - centre).norm() * 1000.0;
  c.samples = group.samples;
  return c;
}

// The landmarks fitted to the poses as given (poses held): the null hypothesis the optimum is
// tested against.
PoseGraphSolution StructureSlam::solve_at_given_poses(PoseGraph given) const {
  for (std::size_t g = 0; g < groups_.size(); ++g) {
    given.poses[g] = groups_[g].odometry;
    given.fixed[g] = true;
  }
  return solve_pose_graph(given);
}

PoseRefinement StructureSlam::finish() {
  const auto t0 = std::chrono::steady_clock::now();
  PoseRefinement out;
  if (groups_.empty()) return out;
  free_ties_across_section_changes();
  graph_.bends = turn_ties();
  PoseGraphSolution s = solve_under_evidence(
      graph_, {}, static_cast<int>(groups_.size()) - 1, options_.correction_sigmas,
      [&](const PoseGraph& g) { return solve_at_given_poses(g); }, out.evidence, out.given_poses_kept);
  if (!out.given_poses_kept) s = with_even_turns(s);
  graph_.poses = s.poses;
  graph_.planes = s.planes;
  out.ran = !graph_.patches.empty();
  out.iterations = s.iterations;
  out.poses.resize(static_cast<std::size_t>(frames_));
  std::vector<Eigen::Vector3d> centres;
  for (const Eigen::Isometry3d& T : graph_.poses) centres.push_back(T.translation());
  const std::vector<PoseInformation> information = patch_information(graph_, s, centres);
  for (std::size_t g = 0; g < groups_.size(); ++g) {
    const Group& group = groups_[g];
    for (std::size_t k = 0; k < group.frames.size(); ++k)
      out.poses[static_cast<std::size_t>(group.frames[k])] = graph_.poses[g] * group.offsets[k];
    PoseCorrection c = correction(g);
    split_by_information(information[g], group, c);
    out.groups.push_back(c);
  }
  // The whole estimate's time: every frame's window and the final optimisation.
  out.ms = frames_ms_ + std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
  return out;
}

// Which of the group's directions the landmarks fix, in the girder's frame there: those with
// information above `degenerate_ratio` of the strongest.
void StructureSlam::split_by_information(const PoseInformation& H, const Group& group, PoseCorrection& c) const {
  const Eigen::SelfAdjointEigenSolver<PoseInformation> eig(H);
  const double top = eig.eigenvalues().maxCoeff();
  PoseInformation null_space = PoseInformation::Zero();
  for (int i = 0; i < 6; ++i)
    if (!(eig.eigenvalues()[i] > options_.degenerate_ratio * top))
      null_space += eig.eigenvectors().col(i) * eig.eigenvectors().col(i).transpose();
  const Eigen::Vector3d axis = group.axis, up = (group.up - axis * axis.dot(group.up)).normalized();
  const Eigen::Vector3d left = up.cross(axis);
  const Eigen::Vector3d basis[6] = {axis, left, up, left, up, axis};
  for (int a = 0; a < 6; ++a) {
    Eigen::Matrix<double, 6, 1> e = Eigen::Matrix<double, 6, 1>::Zero();
    if (a < 3) e.head<3>() = basis[a];
    else e.tail<3>() = basis[a];
    const bool degenerate = !(top > 0) || e.dot(null_space * e) > 0.5;
    (degenerate ? c.degenerate : c.constrained).push_back(pose_axis_name(a));
  }
}

}  // namespace tunnelmap
