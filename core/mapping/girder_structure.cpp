#include "core/mapping/girder_structure.h"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <map>
#include <set>

#include "core/solvers/outline_fit.h"
#include "core/mapping/station_map.h"
#include "core/util/median.h"

namespace tunnelmap {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// The 5 cm cell (lateral, vertical) a plate's sample falls in: areas are counted in cells.
using Cell = std::pair<long, long>;
long cell_index(double v, double cell) { return std::lround(std::floor(v / cell)); }
Cell cell_of(const Eigen::Vector3d& p, double cell) { return {cell_index(p.y(), cell), cell_index(p.z(), cell)}; }

double weighted_station(const PlateView& v) {
  double s = 0, w = 0;
  for (std::size_t i = 0; i < v.samples.size(); ++i) s += v.samples[i].x() * v.weights[i], w += v.weights[i];
  return w > 0 ? s / w : kNaN;
}

using StationedViews = std::vector<std::pair<double, const PlateView*>>;  // sorted by station

// Two faces one frame saw this far apart along the axis are two plates: no pose error lies
// between them (a manhole plate a couple of decimetres behind a diaphragm, seen through its
// opening). The pieces of one far plate, split by the depth's steps, lie within 8 cm.
constexpr double kOneFramesTwoPlatesM = 0.1;

// Splits a chain of views where one frame saw two plates: at the widest gap between them.
void split_where_one_frame_saw_two(const StationedViews& chain, std::vector<std::vector<const PlateView*>>& out) {
  for (std::size_t i = 0; i < chain.size(); ++i)
    for (std::size_t j = i + 1; j < chain.size(); ++j) {
      if (chain[j].second->frame != chain[i].second->frame || chain[j].first - chain[i].first <= kOneFramesTwoPlatesM)
        continue;
      std::size_t cut = i;
      for (std::size_t k = i; k < j; ++k)
        if (chain[k + 1].first - chain[k].first > chain[cut + 1].first - chain[cut].first) cut = k;
      split_where_one_frame_saw_two(StationedViews(chain.begin(), chain.begin() + static_cast<long>(cut) + 1), out);
      split_where_one_frame_saw_two(StationedViews(chain.begin() + static_cast<long>(cut) + 1, chain.end()), out);
      return;
    }
  out.emplace_back();
  for (const auto& [station, view] : chain) out.back().push_back(view);
}

// Views grouped into plates: sorted by station, chained while closer than the gap, and split
// where one frame saw two plates.
std::vector<std::vector<const PlateView*>> group_views(const std::vector<PlateView>& views, double gap) {
  StationedViews order;
  for (const PlateView& v : views)
    if (!v.samples.empty()) order.push_back({weighted_station(v), &v});
  std::sort(order.begin(), order.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  std::vector<std::vector<const PlateView*>> groups;
  StationedViews chain;
  for (const auto& entry : order) {
    if (!chain.empty() && entry.first - chain.back().first > gap) {
      split_where_one_frame_saw_two(chain, groups);
      chain.clear();
    }
    chain.push_back(entry);
  }
  if (!chain.empty()) split_where_one_frame_saw_two(chain, groups);
  return groups;
}

// Normal of the plate in map coordinates (smallest principal direction of its samples), with
// a positive station component.
Eigen::Vector3d plate_normal(const std::vector<const PlateView*>& group) {
  Eigen::Vector3d mean = Eigen::Vector3d::Zero();
  double w = 0;
  for (const PlateView* v : group)
    for (std::size_t i = 0; i < v->samples.size(); ++i) mean += v->samples[i] * v->weights[i], w += v->weights[i];
  mean /= w;
  Eigen::Matrix3d cov = Eigen::Matrix3d::Zero();
  for (const PlateView* v : group)
    for (std::size_t i = 0; i < v->samples.size(); ++i) {
      const Eigen::Vector3d d = v->samples[i] - mean;
      cov += v->weights[i] * d * d.transpose();
    }
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(cov);
  Eigen::Vector3d n = eig.eigenvectors().col(0);
  return n.x() < 0 ? -n : n;
}

std::set<Cell> plate_cells(const std::vector<const PlateView*>& group, double cell) {
  std::set<Cell> cells;
  for (const PlateView* v : group)
    for (const Eigen::Vector3d& s : v->samples)
      cells.insert(cell_of(s, cell));
  return cells;
}

// Area of the cells the plate's samples fall in: what the plate tests compare.
double plate_area(const std::vector<const PlateView*>& group, double cell) {
  return static_cast<double>(plate_cells(group, cell).size()) * cell * cell;
}

// The plate's area as measured: a cell its edge (or its manhole's rim) crosses is covered
// half on average, so each cell side with no occupied neighbour gives back half a cell.
// Counted whole, those cells put girder plates 6-12 % over their area on a 5 cm grid. The rule
// takes the samples to be denser than the cells: a plate seen only from far, its samples more
// than a cell apart, leaves empty cells inside and comes out short.
double plate_area_seen(const std::vector<const PlateView*>& group, double cell) {
  const std::set<Cell> cells = plate_cells(group, cell);
  std::size_t open_sides = 0;
  for (const Cell& c : cells)
    for (const Cell& n : {Cell{c.first - 1, c.second}, Cell{c.first + 1, c.second}, Cell{c.first, c.second - 1},
                          Cell{c.first, c.second + 1}})
      open_sides += cells.count(n) == 0;
  const double area = (static_cast<double>(cells.size()) - 0.5 * static_cast<double>(open_sides)) * cell * cell;
  return std::max(area, 0.0);
}

// The stations within `half` of `s` (whole map when none).
std::vector<const Station*> stations_near(const StationMap& map, double s, double half) {
  std::vector<const Station*> out;
  for (const Station& st : map.stations)
    if (std::abs(st.station_m - s) <= half) out.push_back(&st);
  return out;
}

// Median wall positions (left, right, top, bottom) measured within `half` of station `s`.
void walls_near(const StationMap& map, double s, double half, double out[4]) {
  for (int c = 0; c < 4; ++c) {
    std::vector<double> v;
    for (const Station* st : stations_near(map, s, half))
      if (!std::isnan(st->wall_m[c])) v.push_back(st->wall_m[c]);
    out[c] = median_of_measured(v);
  }
}

// The box inside both cross-sections beside station `s`: each wall at the nearer of its
// positions just before and just after it, `cell` in from it. False when a wall was measured on
// neither side.
bool box_inside_both_sections(const StationMap& map, double s, double cell, double inner[4]) {
  const double side = 0.3;  // how far along the girder each side's walls are taken
  double before[4], after[4];
  walls_near(map, s - side, side, before);
  walls_near(map, s + side, side, after);
  for (int c = 0; c < 4; ++c) {
    inner[c] = std::fmin(before[c], after[c]) - cell;
    if (std::isnan(inner[c])) return false;
  }
  return true;
}

// The area of a plate's views that lies inside both cross-sections beside it. A step face
// where the section changes lies between the two sections' walls, outside this box; a plate
// across the girder fills it, however little of the plate the frames saw (one seen only
// through the opening of a plate before it). NaN when a wall was measured on neither side.
double area_inside_both_sections(const StationMap& map, const std::vector<const PlateView*>& group, double s,
                                 double cell) {
  double inner[4];
  if (!box_inside_both_sections(map, s, cell, inner)) return kNaN;
  std::set<Cell> cells;
  for (const PlateView* v : group)
    for (const Eigen::Vector3d& p : v->samples)
      if (p.y() < inner[0] && -p.y() < inner[1] && p.z() < inner[2] && -p.z() < inner[3])
        cells.insert(cell_of(p, cell));
  return static_cast<double>(cells.size()) * cell * cell;
}

// Whether the plate's views cover the box inside the sections beside it but for less than a
// manhole: a plate seen closed across the girder (false when its walls are unknown). Cells count
// by their centres, inside the box or not, so that the cells its edge cuts are not all covered.
bool seen_closed(const StationMap& map, const std::vector<const PlateView*>& group, double s,
                 const GirderStructureOptions& o) {
  double inner[4];
  if (!box_inside_both_sections(map, s, o.cell_m, inner)) return false;
  const double cell = o.cell_m;
  const auto in_box = [&](long i, long j) {
    const double y = (static_cast<double>(i) + 0.5) * cell, z = (static_cast<double>(j) + 0.5) * cell;
    return y < inner[0] && -y < inner[1] && z < inner[2] && -z < inner[3];
  };
  std::set<Cell> covered;
  for (const PlateView* v : group)
    for (const Eigen::Vector3d& p : v->samples) {
      const Cell c = cell_of(p, cell);
      if (in_box(c.first, c.second)) covered.insert(c);
    }
  long open_cells = 0;
  for (long i = cell_index(-inner[1], cell); i * cell < inner[0]; ++i)
    for (long j = cell_index(-inner[3], cell); j * cell < inner[2]; ++j)
      open_cells += in_box(i, j) && !covered.count({i, j}) ? 1 : 0;
  return static_cast<double>(open_cells) * cell * cell < o.max_closed_gap_m2;
}

// The share of the middle of a fitted outline (within 0.7 of its size) that the plate's
// views cover, in cells: near 0 through an opening. Depth spikes behind a plate's surface put
// rim points anywhere on it; the plate seen all around them shows there is no opening there.
double plate_inside_outline(const std::vector<const PlateView*>& group, const OutlineFit& fit, double cell) {
  const double inner = 0.7;
  const double a = inner * fit.half_width_m, b = inner * fit.half_height_m;
  if (a < cell || b < cell) return 0.0;
  const auto inside = [&](double y, double z) {
    const double u = (y - fit.center.x()) / a, v = (z - fit.center.y()) / b;
    return u * u + v * v < 1.0;
  };
  std::set<Cell> covered;
  for (const PlateView* v : group)
    for (const Eigen::Vector3d& p : v->samples)
      if (inside(p.y(), p.z()))
        covered.insert(cell_of(p, cell));
  int cells = 0;
  for (long i = cell_index(fit.center.x() - a, cell); i * cell <= fit.center.x() + a; ++i)
    for (long j = cell_index(fit.center.y() - b, cell); j * cell <= fit.center.y() + b; ++j)
      cells += inside((i + 0.5) * cell, (j + 0.5) * cell) ? 1 : 0;
  return cells > 0 ? std::min(1.0, static_cast<double>(covered.size()) / cells) : 0.0;
}

const Section* section_at(const StationMap& map, double s) {
  for (const Section& sec : map.sections)
    if (s >= sec.from_m && s < sec.to_m) return &sec;
  if (map.sections.empty()) return nullptr;
  return s < map.sections.front().from_m ? &map.sections.front() : &map.sections.back();
}

Eigen::Vector3d to_world(const StationMap& map, double s, double lateral, double vertical) {
  return map.to_world(s, lateral, vertical);
}

// The rim points frame by frame: a pose's error moves the frame's whole view of the plate.
std::vector<std::vector<Eigen::Vector2d>> rims_by_frame(const std::vector<const PlateView*>& group) {
  std::map<int, std::vector<Eigen::Vector2d>> by_frame;
  for (const PlateView* v : group)
    for (const Eigen::Vector3d& p : v->rim) by_frame[v->frame].push_back({p.y(), p.z()});
  std::vector<std::vector<Eigen::Vector2d>> out;
  for (auto& [frame, rim] : by_frame) out.push_back(std::move(rim));
  return out;
}

void measure_manhole(const StationMap& map, const std::vector<const PlateView*>& group,
                     const GirderStructureOptions& o, Diaphragm& d) {
  std::vector<Eigen::Vector2d> rim;
  for (const PlateView* v : group)
    for (const Eigen::Vector3d& p : v->rim) rim.push_back({p.y(), p.z()});
  if (static_cast<int>(rim.size()) < o.min_rim_points) {
    d.manhole_reason = rim.empty() ? "no opening seen in the plate"
                                   : "too few points on the opening's rim (" + std::to_string(rim.size()) + ")";
    return;
  }
  const std::optional<OutlineFit> fit = fit_manhole_outline(rim);
  if (!fit) {
    d.manhole_reason = "the opening's rim could not be fitted";
    return;
  }
  if (plate_inside_outline(group, *fit, o.cell_m) >= 0.5) {
    d.manhole_reason = "no opening seen: the plate was seen where its " + std::to_string(rim.size()) +
                       " rim points lie (depth spikes behind it)";
    return;
  }
  const int directions = rim_directions(rim, fit->center);
  if (directions < o.min_rim_directions) {
    d.manhole_reason = "opening seen only in part (" + std::to_string(directions) + " of 8 directions)";
    return;
  }
  if (fit->median_residual_m * 1000.0 > o.max_fit_mm) {
    d.manhole_reason = "the rim fits neither an ellipse nor a rounded rectangle";
    return;
  }
  // The frames' rims, pooled, decide whether the opening was seen and where it is; its outline is
  // the one they agree on, each moved by its pose's error (a pitch 0.3 degrees off moves a rim
  // seen from 3 m by 16 mm; pooled, frames that disagree so widen the outline, most where the
  // near ones saw only the top of the rim).
  const std::optional<OutlineFit> joint = fit_manhole_outline(rims_by_frame(group), o.view_shift_sigma_m);
  const OutlineFit& outline = joint ? *joint : *fit;
  Manhole m;
  m.shape = outline.shape;
  m.lateral_m = fit->center.x();
  m.vertical_m = fit->center.y();
  m.width_m = 2 * outline.half_width_m;
  m.height_m = 2 * outline.half_height_m;
  m.corner_radius_m = outline.corner_radius_m;
  m.fit_rms_mm = outline.median_residual_m * 1000.0;
  m.rim_points = static_cast<int>(rim.size());
  m.center = to_world(map, d.station_m, m.lateral_m, m.vertical_m);
  double wall[4];
  walls_near(map, d.station_m, 0.6, wall);
  // Lateral runs towards the left wall (+wall[0]) and away from the right (-wall[1]).
  m.clearance_m[0] = wall[0] - (m.lateral_m + m.width_m / 2);
  m.clearance_m[1] = (m.lateral_m - m.width_m / 2) + wall[1];
  m.clearance_m[2] = wall[2] - (m.vertical_m + m.height_m / 2);
  m.clearance_m[3] = (m.vertical_m - m.height_m / 2) + wall[3];
  d.manhole = m;
}

// A plate's station: the median of its views' samples along the axis.
double median_station(const std::vector<const PlateView*>& group) {
  std::vector<double> stations;
  for (const PlateView* v : group)
    for (const Eigen::Vector3d& p : v->samples) stations.push_back(p.x());
  return median_of_measured(stations);
}

std::set<int> frames_of(const std::vector<const PlateView*>& group) {
  std::set<int> frames;
  for (const PlateView* v : group) frames.insert(v->frame);
  return frames;
}

// A ring where the cross-section steps, or a small face across the axis, is no plate; nor is a
// face that closes little of the section, unless it lies inside the section.
bool closes_enough(const StationMap& map, const std::vector<const PlateView*>& group, double station_m,
                   const GirderStructureOptions& o) {
  const Section* sec = section_at(map, station_m);
  const double box = sec && std::isfinite(sec->width_m) && std::isfinite(sec->height_m)
                         ? sec->width_m * sec->height_m
                         : kNaN;
  const double needed = std::isnan(box) ? o.min_plate_area_m2 : o.min_plate_fraction * box;
  return plate_area(group, o.cell_m) >= needed ||
         area_inside_both_sections(map, group, station_m, o.cell_m) >= o.min_plate_area_m2;
}

bool any_checked(const std::vector<const PlateView*>& group) {
  return std::any_of(group.begin(), group.end(), [](const PlateView* v) { return v->checked; });
}

// The plates, in station order; a plate only unchecked views saw goes to `unchecked` instead.
std::vector<Diaphragm> find_diaphragms(const StationMap& map, const std::vector<PlateView>& views,
                                       const GirderStructureOptions& o, std::vector<UncheckedPlate>& unchecked) {
  std::vector<Diaphragm> out;
  for (const auto& group : group_views(views, o.plate_gap_m)) {
    const std::set<int> frames = frames_of(group);
    Diaphragm d;
    d.station_m = median_station(group);
    d.area_m2 = plate_area_seen(group, o.cell_m);
    if (!closes_enough(map, group, d.station_m, o)) continue;
    if (!any_checked(group)) {
      unchecked.push_back({d.station_m, std::vector<int>(frames.begin(), frames.end())});
      continue;
    }
    const Eigen::Vector3d n = plate_normal(group);
    const CentrelineFrame f = map.frame_at(d.station_m);  // the map coordinates' directions there
    d.normal = (n.x() * f.axis + n.y() * f.left() + n.z() * f.up).normalized();
    d.seen_by_frames = static_cast<int>(frames.size());
    d.frames.assign(frames.begin(), frames.end());
    measure_manhole(map, group, o, d);
    // Without an opening measured, a plate seen whole tells there is none (rim points it has are
    // depth spikes); one seen in part keeps its reason.
    d.closed = !d.manhole && seen_closed(map, group, d.station_m, o);
    if (d.closed) d.manhole_reason = "no opening: the plate was seen closed across the section";
    out.push_back(d);
  }
  return out;
}

// Whether a plate lies within `gap` of station `s`: mapped, or only unchecked views saw it.
bool plate_known_near(const GirderStructure& g, double s, double gap) {
  const auto near = [&](double station_m) { return std::abs(station_m - s) <= gap; };
  return std::any_of(g.diaphragms.begin(), g.diaphragms.end(), [&](const Diaphragm& d) { return near(d.station_m); }) ||
         std::any_of(g.unchecked_plates.begin(), g.unchecked_plates.end(),
                     [&](const UncheckedPlate& p) { return near(p.station_m); });
}

// The plates that only views near the end of the depth range saw. Such a view places its plate
// up to a few centimetres too near, within the gap that chains views of one plate.
std::vector<PlateBeyondRange> plates_beyond_range(const StationMap& map, const std::vector<PlateView>& views,
                                                  const GirderStructure& g, const GirderStructureOptions& o) {
  std::vector<PlateBeyondRange> out;
  for (const auto& group : group_views(views, o.plate_gap_m)) {
    const double s = median_station(group);
    if (plate_known_near(g, s, o.plate_gap_m) || !closes_enough(map, group, s, o)) continue;
    const std::set<int> frames = frames_of(group);
    out.push_back({s, std::vector<int>(frames.begin(), frames.end())});
  }
  return out;
}

// Whether a station farther than `margin` beyond station `s` (in direction `dir`, +1 or -1)
// measured the box: a wall's samples at a plate's corner spill a few millimetres past it.
bool measured_beyond(const StationMap& map, double s, int dir, double margin) {
  for (const Station& st : map.stations)
    if (dir * (st.station_m - s) > margin &&
        (st.width_source == DimensionSource::Measured || st.height_source == DimensionSource::Measured))
      return true;
  return false;
}

// Whether the first (or last) plate is closed and nothing was measured before (after) it.
bool ends_girder(const StationMap& map, const std::vector<Diaphragm>& plates, bool first,
                 const GirderStructureOptions& o) {
  if (plates.empty()) return false;
  const Diaphragm& d = first ? plates.front() : plates.back();
  return d.closed && !measured_beyond(map, d.station_m, first ? -1 : +1, o.compartment_margin_m);
}

void mark_end_walls(const StationMap& map, const GirderStructureOptions& o, std::vector<Diaphragm>& plates) {
  if (ends_girder(map, plates, true, o)) plates.front().kind = "end_wall";
  if (ends_girder(map, plates, false, o)) plates.back().kind = "end_wall";
}

std::vector<Compartment> find_compartments(const StationMap& map, const std::vector<Diaphragm>& plates,
                                           const GirderStructureOptions& o) {
  std::vector<Compartment> out;
  if (map.stations.empty()) return out;
  const double step = map.options.station_step_m;
  std::vector<double> bounds{map.stations.front().station_m - 0.5 * step};
  for (const Diaphragm& d : plates) bounds.push_back(d.station_m);
  bounds.push_back(map.stations.back().station_m + 0.5 * step);
  for (std::size_t k = 0; k + 1 < bounds.size(); ++k) {
    Compartment c;
    c.from_m = bounds[k];
    c.to_m = bounds[k + 1];
    c.closed_from = k > 0;
    c.closed_to = k + 1 < bounds.size() - 1;
    if (c.to_m - c.from_m < step) continue;  // a plate at the very end of the observed extent
    // Beyond an end wall is no girder (its corner's samples may make a station there).
    if ((k == 0 && ends_girder(map, plates, true, o)) || (k + 2 == bounds.size() && ends_girder(map, plates, false, o)))
      continue;
    std::vector<double> w, h;
    const double lo = c.from_m + (c.closed_from ? o.compartment_margin_m : 0.0);
    const double hi = c.to_m - (c.closed_to ? o.compartment_margin_m : 0.0);
    int measured = 0;
    for (const Station& st : map.stations) {
      if (st.station_m < lo || st.station_m > hi) continue;
      const bool mw = st.width_source == DimensionSource::Measured;
      const bool mh = st.height_source == DimensionSource::Measured;
      if (mw) w.push_back(st.width_m);
      if (mh) h.push_back(st.height_m);
      measured += (mw || mh) ? 1 : 0;
    }
    c.width_m = median_of_measured(w);
    c.height_m = median_of_measured(h);
    c.stations_measured = measured;
    out.push_back(c);
  }
  return out;
}

// The centre of the measured cross-section at every station: where a wall pair was not
// measured at the station, its centre comes from the nearest station that measured it.
std::vector<CentrelinePoint> find_centreline(const StationMap& map) {
  const std::size_t n = map.stations.size();
  std::vector<double> lat(n, kNaN), ver(n, kNaN);
  for (std::size_t k = 0; k < n; ++k) {
    const double* w = map.stations[k].wall_m;
    if (!std::isnan(w[0]) && !std::isnan(w[1])) lat[k] = 0.5 * (w[0] - w[1]);
    if (!std::isnan(w[2]) && !std::isnan(w[3])) ver[k] = 0.5 * (w[2] - w[3]);
  }
  const auto nearest = [&](const std::vector<double>& v, std::size_t k) {
    for (std::size_t d = 1; d < n; ++d) {
      if (k >= d && !std::isnan(v[k - d])) return v[k - d];
      if (k + d < n && !std::isnan(v[k + d])) return v[k + d];
    }
    return kNaN;
  };
  std::vector<CentrelinePoint> out;
  for (std::size_t k = 0; k < n; ++k) {
    CentrelinePoint c;
    c.station_m = map.stations[k].station_m;
    const bool here = !std::isnan(lat[k]) && !std::isnan(ver[k]);
    const double l = !std::isnan(lat[k]) ? lat[k] : nearest(lat, k);
    const double v = !std::isnan(ver[k]) ? ver[k] : nearest(ver, k);
    c.source = here ? "measured" : (std::isnan(l) || std::isnan(v)) ? "reference" : "context";
    c.point = to_world(map, c.station_m, std::isnan(l) ? 0.0 : l, std::isnan(v) ? 0.0 : v);
    out.push_back(c);
  }
  return out;
}

// The centre line's point at station `s` (linear between its stations; the reference line
// beyond them).
Eigen::Vector3d centreline_at(const StationMap& map, const std::vector<CentrelinePoint>& line, double s) {
  if (line.empty()) return to_world(map, s, 0.0, 0.0);
  if (s <= line.front().station_m) return line.front().point + (s - line.front().station_m) * map.frame_at(s).axis;
  if (s >= line.back().station_m) return line.back().point + (s - line.back().station_m) * map.frame_at(s).axis;
  const auto hi = std::lower_bound(line.begin(), line.end(), s,
                                   [](const CentrelinePoint& c, double v) { return c.station_m < v; });
  const auto lo = hi - 1;
  const double f = (s - lo->station_m) / std::max(1e-9, hi->station_m - lo->station_m);
  return (1 - f) * lo->point + f * hi->point;
}

}  // namespace

std::vector<double> transverse_plate_stations(const std::vector<PlateView>& views,
                                              const GirderStructureOptions& options) {
  std::vector<double> out;
  for (const auto& group : group_views(views, options.plate_gap_m)) {
    if (plate_area(group, options.cell_m) < options.min_plate_area_m2 || !any_checked(group)) continue;
    out.push_back(median_station(group));
  }
  std::sort(out.begin(), out.end());
  return out;
}

GirderStructure build_girder_structure(const StationMap& map, const std::vector<PlateView>& views,
                                       const GirderStructureOptions& options,
                                       const std::vector<PlateView>& range_cut_views) {
  GirderStructure g;
  g.diaphragms = find_diaphragms(map, views, options, g.unchecked_plates);
  g.plates_beyond_range = plates_beyond_range(map, range_cut_views, g, options);
  mark_end_walls(map, options, g.diaphragms);
  g.compartments = find_compartments(map, g.diaphragms, options);
  g.centreline = find_centreline(map);
  for (Diaphragm& d : g.diaphragms) d.point = centreline_at(map, g.centreline, d.station_m);
  return g;
}

bool view_lies_across_axis(const PlateView& view, double max_angle_deg) {
  if (view.samples.size() < 3) return false;
  return plate_normal({&view}).x() > std::cos(max_angle_deg * M_PI / 180.0);
}

}  // namespace tunnelmap
