#include "core/evaluation/report_markdown.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <sstream>

namespace tunnelmap {

namespace {

std::string f(const char* fmt, double a, double b = 0, double c = 0) {
  char buf[128];
  std::snprintf(buf, sizeof buf, fmt, a, b, c);
  return buf;
}

std::vector<Method> methods_of(const std::vector<CellResult>& rs) {
  std::vector<Method> ms;
  for (const CellResult& r : rs)
    if (std::find(ms.begin(), ms.end(), r.method) == ms.end()) ms.push_back(r.method);
  return ms;
}

std::vector<std::string> ordered(const std::vector<CellResult>& rs, bool experiments,
                                 const std::string& experiment = "") {
  std::vector<std::string> out;
  for (const CellResult& r : rs) {
    if (!experiments && r.experiment != experiment) continue;
    const std::string& k = experiments ? r.experiment : r.cell;
    if (std::find(out.begin(), out.end(), k) == out.end()) out.push_back(k);
  }
  return out;
}

const CellResult* find(const std::vector<CellResult>& rs, const std::string& e,
                       const std::string& c, Method m) {
  for (const CellResult& r : rs)
    if (r.experiment == e && r.cell == c && r.method == m) return &r;
  return nullptr;
}

std::string experiment_title(const std::string& e, const CellResult& any) {
  std::string t = e == "lab" ? "Exp. 1: Lab" : e == "field" ? "Exp. 2: Field" : e;
  if (any.gt_width_m && any.gt_height_m)
    t += f(" (true %.0f x %.0f)", *any.gt_width_m * 1000, *any.gt_height_m * 1000);
  return t;
}

}  // namespace

std::string evaluation_markdown(const std::vector<CellResult>& rs,
                                const std::vector<BoundCheck>& bounds, const ReportInfo& info) {
  std::ostringstream md;
  const std::vector<Method> ms = methods_of(rs);
  md << "# " << info.title << "\n\n";
  if (!info.protocol.empty()) md << info.protocol << "\n\n";

  md << "## Mean (sigma) of width and height, mm\n\n| Approach |";
  for (Method m : ms) md << " " << method_display_name(m) << " w (σ) | " << method_display_name(m) << " h (σ) |";
  md << "\n|---|";
  for (size_t i = 0; i < ms.size(); ++i) md << "---:|---:|";
  md << "\n";
  for (const std::string& e : ordered(rs, true)) {
    const std::vector<std::string> cells = ordered(rs, false, e);
    const CellResult* any = nullptr;
    for (const CellResult& r : rs)
      if (!any && r.experiment == e) any = &r;
    md << "| **" << experiment_title(e, *any) << "** |";
    for (size_t i = 0; i < ms.size(); ++i) md << " | |";
    md << "\n";
    for (const std::string& c : cells) {
      md << "| " << c << " |";
      for (Method m : ms) {
        const CellResult* r = find(rs, e, c, m);
        if (!r || r->detected == 0) {
          md << " – | – |";
          continue;
        }
        md << f(" %.0f (%.1f) |", r->width_mean_m * 1000, r->width_std_m * 1000)
           << f(" %.0f (%.1f) |", r->height_mean_m * 1000, r->height_std_m * 1000);
      }
      md << "\n";
    }
  }

  md << "\n## Mean absolute error against ground truth (width / height, mm) and detection rate\n\n| Cell |";
  for (Method m : ms) md << " " << method_display_name(m) << " |w err| / |h err| | " << method_display_name(m) << " detected |";
  md << "\n|---|";
  for (size_t i = 0; i < ms.size(); ++i) md << "---:|---:|";
  md << "\n";
  for (const std::string& e : ordered(rs, true))
    for (const std::string& c : ordered(rs, false, e)) {
      md << "| " << e << " / " << c << " |";
      for (Method m : ms) {
        const CellResult* r = find(rs, e, c, m);
        if (!r) {
          md << " – | – |";
          continue;
        }
        if (r->detected && r->gt_width_m)
          md << f(" %.1f / %.1f |", r->width_abs_error_m * 1000, r->height_abs_error_m * 1000);
        else
          md << " – |";
        md << " " << r->detected << "/" << r->frames << " |";
      }
      md << "\n";
    }

  md << "\n## Speed (all stages, wall clock, this machine)\n\n| Method | frames | ms per frame | frames per second | × slower than PG&C |\n|---|---:|---:|---:|---:|\n";
  std::map<int, std::pair<double, int>> speed;
  for (const CellResult& r : rs) {
    speed[int(r.method)].first += r.ms_mean * r.frames;
    speed[int(r.method)].second += r.frames;
  }
  const double pgc_ms = speed.count(int(Method::Pgc)) && speed[int(Method::Pgc)].second
                            ? speed[int(Method::Pgc)].first / speed[int(Method::Pgc)].second : NAN;
  for (Method m : ms) {
    const auto& s = speed[int(m)];
    if (s.second == 0) continue;
    const double ms_frame = s.first / s.second;
    md << "| " << method_display_name(m) << " | " << s.second << f(" | %.1f | %.2f |", ms_frame, 1000.0 / ms_frame)
       << (std::isfinite(pgc_ms) ? f(" %.1f |", ms_frame / pgc_ms) : std::string(" – |")) << "\n";
  }

  bool any_seg = false;
  for (const CellResult& r : rs) any_seg = any_seg || r.has_segmentation;
  if (any_seg) {
    md << "\n## Plane segmentation against the true surfaces\n\nA plane is correct when ≥ 80 % of its pixels lie on one true surface (precision = correct / planes); a true surface covering ≥ 3000 pixels is found when a correct plane matches it (recall). Qhull produces no planes.\n\n| Experiment | Method | planes | precision | surfaces | recall |\n|---|---|---:|---:|---:|---:|\n";
    for (const std::string& e : ordered(rs, true))
      for (Method m : ms) {
        SegmentationScore s;
        bool has = false;
        for (const CellResult& r : rs)
          if (r.experiment == e && r.method == m && r.has_segmentation) {
            s += r.segmentation;
            has = true;
          }
        if (!has) continue;
        md << "| " << e << " | " << method_display_name(m) << " | " << s.planes
           << f(" | %.1f %% | ", 100 * s.precision()) << s.surfaces << f(" | %.1f %% |", 100 * s.recall()) << "\n";
      }
  }

  if (!bounds.empty()) {
    int passed = 0;
    for (const BoundCheck& b : bounds) passed += b.pass;
    md << "\n## Acceptance bounds (" << passed << " of " << bounds.size() << " pass)\n\n| Check | measured | limit | |\n|---|---:|---:|---|\n";
    for (const BoundCheck& b : bounds)
      md << "| " << b.name << f(" | %.2f | %.2f | ", b.value, b.limit) << (b.pass ? "pass" : "**FAIL**") << " |\n";
  }
  return md.str();
}

}  // namespace tunnelmap
