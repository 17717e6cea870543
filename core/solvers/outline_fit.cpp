#include "core/solvers/outline_fit.h"

#include <ceres/ceres.h>

#include <algorithm>
#include <array>
#include <cmath>

namespace tunnelmap {

namespace {

// Parameters: centre (2), half-width, half-height [, corner radius]; and the shift (2) of the
// view the point belongs to, added to the point.
struct EllipseResidual {
  Eigen::Vector2d p;
  template <typename T>
  bool operator()(const T* const x, const T* const shift, T* residual) const {
    const T du = (T(p.x()) + shift[0] - x[0]) / x[2], dv = (T(p.y()) + shift[1] - x[1]) / x[3];
    // Normalised radius minus one, scaled to metres by the mean semi-axis: close to the
    // distance from the outline for the near-circular shapes of manholes.
    residual[0] = (ceres::sqrt(du * du + dv * dv + T(1e-12)) - T(1.0)) * T(0.5) * (x[2] + x[3]);
    return true;
  }
};

// Signed distance from a rounded rectangle (outside positive).
struct RoundedRectangleResidual {
  Eigen::Vector2d p;
  template <typename T>
  bool operator()(const T* const x, const T* const shift, T* residual) const {
    using ceres::fmax;
    using ceres::fmin;
    const T r = fmin(x[4], fmin(x[2], x[3]));
    const T qx = ceres::abs(T(p.x()) + shift[0] - x[0]) - (x[2] - r);
    const T qy = ceres::abs(T(p.y()) + shift[1] - x[1]) - (x[3] - r);
    const T ox = fmax(qx, T(0.0)), oy = fmax(qy, T(0.0));
    residual[0] = ceres::sqrt(ox * ox + oy * oy + T(1e-12)) + fmin(fmax(qx, qy), T(0.0)) - r;
    return true;
  }
};

// A view's shift costs what `kRimNoiseM` of rim distance costs at `sigma` of shift.
constexpr double kRimNoiseM = 0.003;
constexpr std::size_t kMinShiftedViewPoints = 20;
struct ShiftPrior {
  double weight;
  template <typename T>
  bool operator()(const T* const shift, T* residual) const {
    residual[0] = shift[0] * T(weight);
    residual[1] = shift[1] * T(weight);
    return true;
  }
};

double percentile(std::vector<double> v, double q) {
  std::sort(v.begin(), v.end());
  const std::size_t i = static_cast<std::size_t>(std::clamp(q, 0.0, 1.0) * (v.size() - 1));
  return v[i];
}

// Fits the shape `x` to every view's rim, each view free to shift by about `shift_sigma_m`
// from the view with the most points, which holds still (0: views held where they are). Returns
// the median distance of the shifted points from it.
template <typename Residual, int kParams>
double solve(const std::vector<std::vector<Eigen::Vector2d>>& views, double shift_sigma_m,
             std::array<double, kParams>& x, std::vector<Eigen::Vector2d>& shifts) {
  ceres::Problem problem;
  shifts.assign(views.size(), Eigen::Vector2d::Zero());
  const auto largest = std::max_element(views.begin(), views.end(),
                                        [](const auto& a, const auto& b) { return a.size() < b.size(); });
  for (std::size_t v = 0; v < views.size(); ++v) {
    for (const Eigen::Vector2d& p : views[v])
      problem.AddResidualBlock(new ceres::AutoDiffCostFunction<Residual, 1, kParams, 2>(new Residual{p}),
                               new ceres::HuberLoss(0.005), x.data(), shifts[v].data());
    if (views[v].empty()) continue;
    // A few stray points would move their view anywhere: only a view of some rim may shift.
    if (shift_sigma_m > 0.0 && views[v].size() >= kMinShiftedViewPoints && views.begin() + v != largest)
      problem.AddResidualBlock(new ceres::AutoDiffCostFunction<ShiftPrior, 2, 2>(
                                   new ShiftPrior{kRimNoiseM / shift_sigma_m}),
                               nullptr, shifts[v].data());
    else
      problem.SetParameterBlockConstant(shifts[v].data());
  }
  for (int k = 2; k < kParams; ++k) {
    problem.SetParameterLowerBound(x.data(), k, k == 4 ? 0.0 : 0.02);
    problem.SetParameterUpperBound(x.data(), k, 3.0);
  }
  ceres::Solver::Options options;
  options.max_num_iterations = 50;
  options.num_threads = 1;
  ceres::Solver::Summary summary;
  ceres::Solve(options, &problem, &summary);
  std::vector<double> r;
  for (std::size_t v = 0; v < views.size(); ++v)
    for (const Eigen::Vector2d& p : views[v]) {
      double res = 0;
      Residual{p}(x.data(), shifts[v].data(), &res);
      r.push_back(std::abs(res));
    }
  return percentile(r, 0.5);
}

}  // namespace

int rim_directions(const std::vector<Eigen::Vector2d>& rim, const Eigen::Vector2d& center,
                   int min_points) {
  std::array<int, 8> count{};
  for (const Eigen::Vector2d& p : rim) {
    const double a = std::atan2(p.y() - center.y(), p.x() - center.x());
    const int k = std::clamp(static_cast<int>(std::floor((a + M_PI) / (M_PI / 4))), 0, 7);
    ++count[static_cast<std::size_t>(k)];
  }
  return static_cast<int>(std::count_if(count.begin(), count.end(), [&](int c) { return c >= min_points; }));
}

std::optional<OutlineFit> fit_manhole_outline(const std::vector<Eigen::Vector2d>& rim) {
  return fit_manhole_outline(std::vector<std::vector<Eigen::Vector2d>>{rim}, 0.0);
}

std::optional<OutlineFit> fit_manhole_outline(const std::vector<std::vector<Eigen::Vector2d>>& views,
                                              double shift_sigma_m) {
  std::vector<double> u, v;
  for (const auto& view : views)
    for (const Eigen::Vector2d& p : view) u.push_back(p.x()), v.push_back(p.y());
  if (u.size() < 12) return std::nullopt;
  const double u0 = percentile(u, 0.05), u1 = percentile(u, 0.95);
  const double v0 = percentile(v, 0.05), v1 = percentile(v, 0.95);
  const double a = std::max(0.03, 0.5 * (u1 - u0)), b = std::max(0.03, 0.5 * (v1 - v0));
  std::array<double, 4> ellipse{0.5 * (u0 + u1), 0.5 * (v0 + v1), a, b};
  std::array<double, 5> rect{ellipse[0], ellipse[1], a, b, 0.3 * std::min(a, b)};
  OutlineFit f;
  std::vector<Eigen::Vector2d> ellipse_shifts, rect_shifts;
  f.ellipse_residual_m = solve<EllipseResidual, 4>(views, shift_sigma_m, ellipse, ellipse_shifts);
  f.rectangle_residual_m = solve<RoundedRectangleResidual, 5>(views, shift_sigma_m, rect, rect_shifts);
  // The outline sits where the largest view put it; the views of some rim put it, on average,
  // there less their mean shift.
  const auto mean_shift = [&views](const std::vector<Eigen::Vector2d>& shifts) {
    Eigen::Vector2d sum = Eigen::Vector2d::Zero();
    int counted = 0;
    for (std::size_t v = 0; v < views.size(); ++v)
      if (views[v].size() >= kMinShiftedViewPoints) sum += shifts[v], ++counted;
    return counted > 0 ? Eigen::Vector2d(sum / counted) : Eigen::Vector2d::Zero();
  };
  // The rounded rectangle has one parameter more: it must fit clearly better to be the shape.
  if (f.rectangle_residual_m < 0.7 * f.ellipse_residual_m) {
    f.shape = "rounded_rectangle";
    f.center = Eigen::Vector2d(rect[0], rect[1]) - mean_shift(rect_shifts);
    f.half_width_m = rect[2];
    f.half_height_m = rect[3];
    f.corner_radius_m = std::min(rect[4], std::min(rect[2], rect[3]));
    f.median_residual_m = f.rectangle_residual_m;
    f.view_shifts = rect_shifts;
  } else {
    f.shape = "ellipse";
    f.center = Eigen::Vector2d(ellipse[0], ellipse[1]) - mean_shift(ellipse_shifts);
    f.half_width_m = ellipse[2];
    f.half_height_m = ellipse[3];
    f.median_residual_m = f.ellipse_residual_m;
    f.view_shifts = ellipse_shifts;
  }
  return f;
}

}  // namespace tunnelmap
