#pragma once
// The outline of a manhole from the points of its rim in the plate's plane: an axis-aligned
// ellipse and a rounded rectangle are both fitted by robust least squares (Ceres), and the one
// the rim lies closer to is the opening's shape.
#include <Eigen/Core>
#include <optional>
#include <string>
#include <vector>

namespace tunnelmap {

struct OutlineFit {
  std::string shape;                 // "ellipse" or "rounded_rectangle"
  Eigen::Vector2d center = Eigen::Vector2d::Zero();
  double half_width_m = 0.0, half_height_m = 0.0;
  double corner_radius_m = 0.0;      // rounded rectangle only
  double median_residual_m = 0.0;    // median distance of the rim points from the outline
  double ellipse_residual_m = 0.0, rectangle_residual_m = 0.0;  // both fits, for the record
  std::vector<Eigen::Vector2d> view_shifts;  // per view: added to its points to meet the outline
};

// `rim`: (lateral, vertical) points on the opening's edge. nullopt when too few to fit.
std::optional<OutlineFit> fit_manhole_outline(const std::vector<Eigen::Vector2d>& rim);

// The rims of several views of one opening, each view of 20 points or more free to shift by
// about `shift_sigma_m` in the plate's plane from the view with the most points (a pose's error
// moves the whole view): the outline they agree on. Its centre is where those views put it on
// average, each view alike. `shift_sigma_m` 0 pools them as they are.
std::optional<OutlineFit> fit_manhole_outline(const std::vector<std::vector<Eigen::Vector2d>>& views,
                                              double shift_sigma_m);

// Of 8 directions around `center`, how many hold at least `min_points` rim points: an opening
// seen only in part cannot be measured.
int rim_directions(const std::vector<Eigen::Vector2d>& rim, const Eigen::Vector2d& center,
                   int min_points = 3);

}  // namespace tunnelmap
