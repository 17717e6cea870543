#pragma once
// The simulator's truth centre line ("ground_truth.girder.centreline": stations and world
// points every few centimetres): the truth station of a world point and the line's direction.
#include <Eigen/Core>
#include <cstddef>
#include <nlohmann/json.hpp>
#include <vector>

namespace tunnelmap {

class TruthLine {
 public:
  explicit TruthLine(const nlohmann::json& line);
  // The nearest point of the line, refined along it.
  double station_of(const Eigen::Vector3d& p) const;
  // The same, searching only the `reach` line points either side of point `near` (a point
  // known to be close: many points seen from one camera).
  double station_near(const Eigen::Vector3d& p, std::size_t near, std::size_t reach) const;
  // The index of the line point nearest `p`.
  std::size_t nearest(const Eigen::Vector3d& p) const;
  // The line's direction at its point nearest `p` (world x when it has one point).
  Eigen::Vector3d direction_at(const Eigen::Vector3d& p) const;

 private:
  std::size_t nearest_within(const Eigen::Vector3d& p, std::size_t from, std::size_t to) const;
  double refined(const Eigen::Vector3d& p, std::size_t i) const;
  Eigen::Vector3d direction_near(std::size_t i) const;

  std::vector<double> s_;
  std::vector<Eigen::Vector3d> x_;
};

}  // namespace tunnelmap
