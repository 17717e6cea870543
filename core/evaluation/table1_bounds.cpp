#include "core/evaluation/table1_bounds.h"

#include <cmath>
#include <cstdio>

namespace tunnelmap {

namespace {

std::string label(const CellResult& r, const char* what) {
  char buf[256];
  std::snprintf(buf, sizeof buf, "%s / %s: %s", r.experiment.c_str(), r.cell.c_str(), what);
  return buf;
}

void le(std::vector<BoundCheck>& out, const std::string& name, double v, double limit) {
  out.push_back({name, v, limit, std::isfinite(v) && v <= limit});
}

const CellResult* find(const std::vector<CellResult>& rs, const CellResult& like, Method m) {
  for (const CellResult& r : rs)
    if (r.method == m && r.experiment == like.experiment && r.cell == like.cell) return &r;
  return nullptr;
}

}  // namespace

std::vector<BoundCheck> check_table1_bounds(const std::vector<CellResult>& results, bool speed) {
  std::vector<BoundCheck> out;
  double pgc_ms = 0, ransac_ms = 0;
  int pgc_n = 0, ransac_n = 0;
  for (const CellResult& r : results) {
    if (r.method == Method::Ransac) {
      ransac_ms += r.ms_mean * r.frames;
      ransac_n += r.frames;
    }
    if (r.method != Method::Pgc) continue;
    pgc_ms += r.ms_mean * r.frames;
    pgc_n += r.frames;
    const bool lab = r.experiment == "lab";
    const double err = lab ? 5.0 : 12.0, sd = lab ? 3.0 : 6.0;
    char what[128];
    std::snprintf(what, sizeof what, "PG&C width |error| <= %.0f mm", err);
    le(out, label(r, what), r.detected ? r.width_abs_error_m * 1000 : NAN, err);
    std::snprintf(what, sizeof what, "PG&C height |error| <= %.0f mm", err);
    le(out, label(r, what), r.detected ? r.height_abs_error_m * 1000 : NAN, err);
    std::snprintf(what, sizeof what, "PG&C width sigma <= %.0f mm", sd);
    le(out, label(r, what), r.detected ? r.width_std_m * 1000 : NAN, sd);
    std::snprintf(what, sizeof what, "PG&C height sigma <= %.0f mm", sd);
    le(out, label(r, what), r.detected ? r.height_std_m * 1000 : NAN, sd);
    out.push_back({label(r, "PG&C detection rate = 100 %"), 100.0 * r.detection_rate(), 100.0,
                   r.detected == r.frames});
    for (Method m : {Method::Qhull, Method::Ransac}) {
      const CellResult* b = find(results, r, m);
      if (!b) continue;
      // A baseline that detects nothing has no error to beat: PG&C wins if it detected.
      const double mine = r.mean_abs_error_mm(), theirs = b->mean_abs_error_mm();
      const bool pass = std::isfinite(mine) && (!std::isfinite(theirs) || mine < theirs);
      std::snprintf(what, sizeof what, "PG&C mean |error| < %s's (%.1f mm)", method_display_name(m),
                    theirs);
      out.push_back({label(r, what), mine, theirs, pass});
    }
  }
  if (speed && pgc_n > 0 && ransac_n > 0) {
    const double ratio = (ransac_ms / ransac_n) / (pgc_ms / pgc_n);
    out.push_back({"speed: R&L ms per frame / PG&C ms per frame >= 30", ratio, 30.0, ratio >= 30.0});
  }
  return out;
}

}  // namespace tunnelmap
