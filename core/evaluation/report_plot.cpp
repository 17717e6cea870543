#include "core/evaluation/report_plot.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "core/util/atomic_file.h"
#include "core/util/error.h"

namespace tunnelmap {

namespace {

const cv::Scalar kBlack(0, 0, 0), kGrey(200, 200, 200), kWhite(255, 255, 255);

cv::Scalar method_colour(Method m) {  // BGR
  switch (m) {
    case Method::Pgc: return {180, 100, 30};    // blue
    case Method::Qhull: return {40, 150, 40};   // green
    case Method::Ransac: return {40, 60, 210};  // red
  }
  return kBlack;
}

void text(cv::Mat& img, const std::string& s, cv::Point p, double scale = 0.45, int thick = 1,
          cv::Scalar c = kBlack) {
  cv::putText(img, s, p, cv::FONT_HERSHEY_SIMPLEX, scale, c, thick, cv::LINE_AA);
}

std::string fmt(const char* f, double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, f, v);
  return buf;
}

template <class T>
std::vector<T> unique_in_order(const std::vector<CellResult>& rs, T (*key)(const CellResult&)) {
  std::vector<T> out;
  for (const CellResult& r : rs)
    if (std::find(out.begin(), out.end(), key(r)) == out.end()) out.push_back(key(r));
  return out;
}
std::string exp_of(const CellResult& r) { return r.experiment; }
Method method_of(const CellResult& r) { return r.method; }

void legend(cv::Mat& img, const std::vector<Method>& ms, cv::Point at) {
  for (Method m : ms) {
    cv::rectangle(img, {at.x, at.y - 10, 14, 12}, method_colour(m), cv::FILLED);
    text(img, method_display_name(m), {at.x + 20, at.y});
    at.x += 40 + 9 * static_cast<int>(std::string(method_display_name(m)).size());
  }
}

// Horizontal grid lines with labels; returns the y pixel of a value.
struct Axis {
  cv::Rect area;
  double lo, hi;
  int y(double v) const {
    const double t = (std::clamp(v, lo, hi) - lo) / (hi - lo);
    return area.y + area.height - static_cast<int>(std::lround(t * area.height));
  }
  void draw(cv::Mat& img, double step, const char* unit) const {
    for (double v = std::ceil(lo / step) * step; v <= hi + 1e-9; v += step) {
      cv::line(img, {area.x, y(v)}, {area.x + area.width, y(v)}, std::abs(v) < 1e-9 ? kBlack : kGrey, 1);
      text(img, fmt("%g", std::abs(v) < 1e-9 ? 0.0 : v), {area.x - 42, y(v) + 4}, 0.4);
    }
    text(img, unit, {area.x - 42, area.y + area.height + 18}, 0.4);
  }
};

double nice_step(double range) {
  const double raw = range / 6;
  const double p = std::pow(10.0, std::floor(std::log10(raw)));
  for (double m : {1.0, 2.0, 5.0, 10.0})
    if (m * p >= raw) return m * p;
  return 10 * p;
}

void save_png(const std::string& path, const cv::Mat& img) {
  std::vector<uchar> buf;
  if (!cv::imencode(".png", img, buf)) throw InputError(path, "PNG encoding failed");
  write_file_atomically(path, [&](std::ostream& out) {
    out.write(reinterpret_cast<const char*>(buf.data()), static_cast<std::streamsize>(buf.size()));
  });
}

}  // namespace

void write_table1_plot(const std::string& path, const std::vector<CellResult>& rs) {
  const auto exps = unique_in_order<std::string>(rs, exp_of);
  const auto ms = unique_in_order<Method>(rs, method_of);
  const int panel_h = 330, width = 1100;
  cv::Mat img(60 + panel_h * std::max<int>(1, exps.size()), width, CV_8UC3, kWhite);
  text(img, "Signed mean error (bar) and sigma (whisker) per cell, mm", {20, 25}, 0.6, 1);
  legend(img, ms, {620, 25});
  const double cap = 120.0;
  for (size_t e = 0; e < exps.size(); ++e) {
    std::vector<std::string> cells;
    for (const CellResult& r : rs)
      if (r.experiment == exps[e] && std::find(cells.begin(), cells.end(), r.cell) == cells.end())
        cells.push_back(r.cell);
    double lo = -10, hi = 10;
    for (const CellResult& r : rs) {
      if (r.experiment != exps[e] || !r.detected || !r.gt_width_m || !r.gt_height_m) continue;
      for (double v : {r.width_mean_m - *r.gt_width_m - r.width_std_m,
                       r.height_mean_m - *r.gt_height_m - r.height_std_m})
        lo = std::min(lo, v * 1000);
      for (double v : {r.width_mean_m - *r.gt_width_m + r.width_std_m,
                       r.height_mean_m - *r.gt_height_m + r.height_std_m})
        hi = std::max(hi, v * 1000);
    }
    lo = std::max(lo * 1.1, -cap);
    hi = std::min(hi * 1.1, cap);
    const int top = 60 + static_cast<int>(e) * panel_h;
    Axis ax{{70, top + 30, width - 100, panel_h - 90}, lo, hi};
    text(img, exps[e], {20, top + 15}, 0.55, 2);
    ax.draw(img, nice_step(hi - lo), "mm");
    const int groups = static_cast<int>(cells.size()) * 2;
    const double gw = static_cast<double>(ax.area.width) / std::max(1, groups);
    const double bw = gw * 0.8 / std::max<size_t>(1, ms.size());
    for (int g = 0; g < groups; ++g) {
      const std::string& cell = cells[g / 2];
      const bool is_w = g % 2 == 0;
      const int gx = ax.area.x + static_cast<int>(g * gw);
      text(img, cell + (is_w ? " w" : " h"), {gx + 4, ax.area.y + ax.area.height + 18}, 0.4);
      for (size_t k = 0; k < ms.size(); ++k) {
        const CellResult* r = nullptr;
        for (const CellResult& c : rs)
          if (c.experiment == exps[e] && c.cell == cell && c.method == ms[k]) r = &c;
        const int x0 = gx + static_cast<int>(gw * 0.1 + k * bw), x1 = static_cast<int>(x0 + bw) - 2;
        if (!r || !r->detected || !r->gt_width_m || !r->gt_height_m) {
          text(img, "n/d", {x0, ax.y(0) - 4}, 0.35, 1, method_colour(ms[k]));
          continue;
        }
        const double err = 1000 * (is_w ? r->width_mean_m - *r->gt_width_m : r->height_mean_m - *r->gt_height_m);
        const double sd = 1000 * (is_w ? r->width_std_m : r->height_std_m);
        cv::rectangle(img, cv::Point(x0, ax.y(0)), cv::Point(x1, ax.y(err)), method_colour(ms[k]), cv::FILLED);
        const int xm = (x0 + x1) / 2;
        cv::line(img, {xm, ax.y(err - sd)}, {xm, ax.y(err + sd)}, kBlack, 1);
        cv::line(img, {xm - 3, ax.y(err - sd)}, {xm + 3, ax.y(err - sd)}, kBlack, 1);
        cv::line(img, {xm - 3, ax.y(err + sd)}, {xm + 3, ax.y(err + sd)}, kBlack, 1);
        if (err < lo || err > hi) text(img, fmt("%.0f", err), {x0, err < lo ? ax.y(lo) + 12 : ax.y(hi) - 4}, 0.35);
      }
    }
  }
  save_png(path, img);
}

void write_sweeps_plot(const std::string& path, const std::vector<CellResult>& rs) {
  const auto exps = unique_in_order<std::string>(rs, exp_of);
  const auto ms = unique_in_order<Method>(rs, method_of);
  const int panel_h = 240, width = 1100, half = width / 2;
  cv::Mat img(50 + panel_h * std::max<int>(1, exps.size()), width, CV_8UC3, kWhite);
  text(img, "Robustness sweeps: mean |error| (left, mm, clipped at 100) and detection rate (right, %)", {20, 25}, 0.55, 1);
  legend(img, ms, {760, 45});
  for (size_t e = 0; e < exps.size(); ++e) {
    std::vector<double> xs;
    for (const CellResult& r : rs)
      if (r.experiment == exps[e] && std::find(xs.begin(), xs.end(), r.cell_value) == xs.end())
        xs.push_back(r.cell_value);
    std::sort(xs.begin(), xs.end());
    const int top = 50 + static_cast<int>(e) * panel_h;
    for (int side = 0; side < 2; ++side) {
      double hi = side == 0 ? 10.0 : 100.0;
      if (side == 0)
        for (const CellResult& r : rs)
          if (r.experiment == exps[e] && std::isfinite(r.mean_abs_error_mm()))
            hi = std::max(hi, std::min(100.0, r.mean_abs_error_mm() * 1.1));
      Axis ax{{side * half + 70, top + 40, half - 100, panel_h - 90}, 0.0, hi};
      text(img, exps[e], {side * half + 70, top + 25}, 0.5, 2);
      ax.draw(img, side == 0 ? nice_step(hi) : 25.0, side == 0 ? "mm" : "%");
      auto xpix = [&](double x) {
        const double lo = xs.front(), span = xs.back() - xs.front();
        return ax.area.x + static_cast<int>(span > 0 ? (x - lo) / span * ax.area.width : ax.area.width / 2);
      };
      for (double x : xs) text(img, fmt("%g", x), {xpix(x) - 8, ax.area.y + ax.area.height + 16}, 0.4);
      for (size_t k = 0; k < ms.size(); ++k) {
        const Method m = ms[k];
        // Later methods are drawn thinner on top, so coinciding lines stay visible.
        const int thick = 2 + 2 * static_cast<int>(ms.size() - 1 - k);
        std::vector<cv::Point> line;
        for (double x : xs)
          for (const CellResult& r : rs) {
            if (r.experiment != exps[e] || r.method != m || r.cell_value != x) continue;
            const double v = side == 0 ? r.mean_abs_error_mm() : 100 * r.detection_rate();
            if (!std::isfinite(v)) continue;
            line.emplace_back(xpix(x), ax.y(v));
          }
        for (size_t i = 0; i < line.size(); ++i) {
          cv::circle(img, line[i], thick / 2 + 2, method_colour(m), cv::FILLED, cv::LINE_AA);
          if (i) cv::line(img, line[i - 1], line[i], method_colour(m), thick, cv::LINE_AA);
        }
      }
    }
  }
  save_png(path, img);
}

}  // namespace tunnelmap
