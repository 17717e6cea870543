// libqhull_r (reentrant C API) is called directly: one small translation unit, no PCL surface
// templates to compile.
#include "core/baselines/qhull_tunnel.h"

#include <Eigen/Geometry>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>
#include <vector>

extern "C" {
#include <libqhull_r/qhull_ra.h>
}

#include "core/tunnel/template_fit.h"
#include "core/tunnel/wall_classification.h"
#include "core/tunnel/wall_geometry.h"
#include "core/util/error.h"

namespace tunnelmap {

namespace {

constexpr double kDeg = 3.14159265358979323846 / 180.0;

// Hull vertices of `pts` (x,y,z interleaved). Empty when qhull fails (degenerate input).
std::vector<Eigen::Vector3d> convex_hull_vertices(std::vector<coordT>& pts) {
  std::vector<Eigen::Vector3d> out;
  const int n = static_cast<int>(pts.size() / 3);
  qhT qh_qh;
  qhT* qh = &qh_qh;
  QHULL_LIB_CHECK
  FILE* devnull = std::fopen("/dev/null", "w");
  qh_zero(qh, devnull);
  char flags[] = "qhull Qt";
  const int code = qh_new_qhull(qh, 3, n, pts.data(), False, flags, nullptr, devnull);
  if (code == 0) {
    vertexT* vertex;
    FORALLvertices {
      const coordT* p = vertex->point;
      out.emplace_back(p[0], p[1], p[2]);
    }
  }
  qh_freeqhull(qh, !qh_ALL);
  int curlong = 0, totlong = 0;
  qh_memfreeshort(qh, &curlong, &totlong);
  if (devnull) std::fclose(devnull);
  return out;
}

struct Alignment {
  Eigen::Vector3d axis, up, right;
  double lo_r = 0, hi_r = 0, lo_u = 0, hi_u = 0, lo_a = 0, hi_a = 0;
  double area() const { return (hi_r - lo_r) * (hi_u - lo_u); }
};

Alignment align(const std::vector<Eigen::Vector3d>& hull, const RoughTunnelFrame& f, double yaw,
                double tilt) {
  Alignment a;
  a.axis = (std::cos(tilt) * (std::cos(yaw) * f.forward + std::sin(yaw) * f.right) +
            std::sin(tilt) * f.up).normalized();
  a.up = (f.up - f.up.dot(a.axis) * a.axis).normalized();
  a.right = a.axis.cross(a.up);
  a.lo_r = a.lo_u = a.lo_a = std::numeric_limits<double>::infinity();
  a.hi_r = a.hi_u = a.hi_a = -a.lo_r;
  for (const auto& v : hull) {
    const double r = a.right.dot(v), u = a.up.dot(v), x = a.axis.dot(v);
    a.lo_r = std::min(a.lo_r, r);
    a.hi_r = std::max(a.hi_r, r);
    a.lo_u = std::min(a.lo_u, u);
    a.hi_u = std::max(a.hi_u, u);
    a.lo_a = std::min(a.lo_a, x);
    a.hi_a = std::max(a.hi_a, x);
  }
  return a;
}

// Coarse-to-fine search for the axis with the smallest cross-section bounding rectangle.
Alignment best_alignment(const std::vector<Eigen::Vector3d>& hull, const RoughTunnelFrame& f,
                         const QhullOptions& o) {
  Alignment best = align(hull, f, 0, 0);
  double by = 0, bt = 0;
  for (double step : {1.0, 0.1}) {
    const double yr = step == 1.0 ? o.yaw_range_deg : 1.0;
    const double tr = step == 1.0 ? o.tilt_range_deg : 1.0;
    const double cy = by, ct = bt;
    for (double dy = -yr; dy <= yr + 1e-9; dy += step)
      for (double dt = -tr; dt <= tr + 1e-9; dt += step) {
        const Alignment a = align(hull, f, (cy + dy) * kDeg, (ct + dt) * kDeg);
        if (a.area() < best.area()) {
          best = a;
          by = cy + dy;
          bt = ct + dt;
        }
      }
  }
  return best;
}

void fail(TunnelMap& m, TunnelStatus status, const std::string& reason) {
  m.detected = false;
  m.status = status;
  m.reason = reason;
}

std::string fmt(const char* f, double a, double b = 0, double c = 0) {
  char buf[200];
  std::snprintf(buf, sizeof buf, f, a, b, c);
  return buf;
}

void run(const OrganizedCloud& cloud, const Eigen::Vector3d& up_camera, const TunnelOptions& opt,
         const TunnelContext* context, const QhullOptions& o, QhullTunnelResult& out) {
  TunnelMap& map = out.map;
  const RoughTunnelFrame rough = make_rough_frame(up_camera);
  map.up = rough.up;
  map.axis_dir = rough.forward;
  std::vector<coordT> pts;
  for (int v = 0; v < cloud.height; v += o.sample_step)
    for (int u = 0; u < cloud.width; u += o.sample_step) {
      const Eigen::Vector3f& p = cloud.points[cloud.index(u, v)];
      if (!OrganizedCloud::valid(p)) continue;
      pts.insert(pts.end(), {p.x(), p.y(), p.z()});
    }
  out.input_points = static_cast<int>(pts.size() / 3);
  if (out.input_points < o.min_points) {
    fail(map, TunnelStatus::TooFewPoints, fmt("%.0f valid points, at least %.0f needed", out.input_points, o.min_points));
    return;
  }
  const std::vector<Eigen::Vector3d> hull = convex_hull_vertices(pts);
  out.hull_vertices = static_cast<int>(hull.size());
  if (hull.size() < 4) {
    fail(map, TunnelStatus::DegenerateHull, "qhull found no 3D hull (points coplanar or too few)");
    return;
  }
  const Alignment a = best_alignment(hull, rough, o);
  TemplateFrame tf;
  tf.ok = true;
  tf.right = a.right;
  tf.up = a.up;
  tf.axis = a.axis;
  // Left wall at the lowest right-coordinate, roof at the highest up-coordinate.
  const WallOffsets off{-a.lo_r, a.hi_r, a.hi_u, -a.lo_u};
  map.width_m = a.hi_r - a.lo_r;
  map.height_m = a.hi_u - a.lo_u;
  for (int c = 0; c < 4; ++c) {
    map.walls[c].cls = static_cast<WallClass>(c);
    map.walls[c].found = true;
  }
  build_wall_geometry(tf, off, a.lo_a, a.hi_a, opt.forbidden_band_m, map);
  if (map.width_m < opt.width_min_m || map.width_m > opt.width_max_m ||
      map.height_m < opt.height_min_m || map.height_m > opt.height_max_m) {
    fail(map, TunnelStatus::OutOfTemplate, fmt("hull %.3f x %.3f m outside the template window", map.width_m, map.height_m));
    return;
  }
  if (context && ((context->has_width() &&
                   std::abs(map.width_m - context->width_m()) > opt.context_tolerance_m) ||
                  (context->has_height() &&
                   std::abs(map.height_m - context->height_m()) > opt.context_tolerance_m))) {
    fail(map, TunnelStatus::InconsistentWithContext,
         fmt("hull %.3f x %.3f m differs from the context by more than %.0f mm", map.width_m,
             map.height_m, opt.context_tolerance_m * 1000.0));
    return;
  }
  map.detected = true;
  map.status = TunnelStatus::Ok;
  map.width_source = map.height_source = DimensionSource::Measured;
  for (Wall& w : map.walls)
    if (w.found) w.source = DimensionSource::Measured;
  map.reason = fmt("width %.3f m, height %.3f m (convex hull)", map.width_m, map.height_m);
}

}  // namespace

QhullTunnelResult qhull_tunnel(const OrganizedCloud& cloud, const Eigen::Vector3d& up_camera,
                               const TunnelOptions& tunnel, const TunnelContext* context,
                               const QhullOptions& options) {
  if (options.sample_step < 1 || options.min_points < 4 || !(options.yaw_range_deg >= 0) ||
      !(options.tilt_range_deg >= 0))
    throw ParameterError("Qhull options out of range (step >= 1, min points >= 4, ranges >= 0)");
  const double up_norm = up_camera.norm();
  if (!std::isfinite(up_norm) || up_norm < 1e-9)
    throw ParameterError("Qhull: the up vector must be finite and non-zero");
  QhullTunnelResult out;
  const auto start = std::chrono::steady_clock::now();
  run(cloud, up_camera, tunnel, context, options, out);
  out.map.timings_ms["tunnel"] =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  return out;
}

}  // namespace tunnelmap
