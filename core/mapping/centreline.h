#pragma once
// Centreline: the station map's reference line in the world frame, parameterised by arc length
// (the station). A point's station is where the plane perpendicular to the line passes through
// it, and its lateral and vertical positions are taken in the line's own frame there (axis,
// left, up), so a cross-section is cut perpendicular to the girder where it curves, rises or
// rolls. A straight line (one frame for every station) is the special case of a tunnel mapped
// without knowing its course in advance. Fitted to the frames' cross-section centres in
// core/mapping/centreline_fit.h.
#include <Eigen/Geometry>  // cross
#include <vector>

namespace tunnelmap {

// The line's frame at one station: `axis` (unit, to larger stations), `up` (unit, perpendicular
// to it) and `left` = up x axis.
struct CentrelineFrame {
  double station_m = 0.0;
  Eigen::Vector3d point = Eigen::Vector3d::Zero();
  Eigen::Vector3d axis = Eigen::Vector3d::UnitX();
  Eigen::Vector3d up = Eigen::Vector3d::UnitZ();
  Eigen::Vector3d left() const { return up.cross(axis); }
};

// A world point in the line's coordinates.
struct LinePosition {
  double station_m = 0.0, lateral_m = 0.0, vertical_m = 0.0;
  int node = 0;  // the node it was found at: a hint for nearby points
};

class Centreline {
 public:
  Centreline() = default;  // a straight line along X through the origin, up Z
  // A straight line: station 0 at `origin`.
  static Centreline straight(const Eigen::Vector3d& origin, const Eigen::Vector3d& axis, const Eigen::Vector3d& up);
  // Nodes in increasing station order, closely spaced (each node's frame holds until halfway
  // to the next); beyond the ends the line runs straight on along the end nodes' axes.
  static Centreline through(std::vector<CentrelineFrame> nodes);

  // `hint`: a node near the point (e.g. the camera's), so a frame's points are found in a few
  // steps; any node is correct, only slower.
  LinePosition locate(const Eigen::Vector3d& world, int hint = -1) const;
  // The frame at station `s` (the nearest node's directions, the point on the line).
  CentrelineFrame frame_at(double s) const;
  Eigen::Vector3d to_world(double s, double lateral, double vertical) const;

  bool is_straight() const { return nodes_.size() == 1; }
  const std::vector<CentrelineFrame>& nodes() const { return nodes_; }

 private:
  int nearest_node(double s) const;

  std::vector<CentrelineFrame> nodes_{CentrelineFrame{}};
};

}  // namespace tunnelmap
