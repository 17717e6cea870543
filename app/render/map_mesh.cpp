#include "app/render/map_mesh.h"

#include "ui/scene/mesh_polydata.h"

#include <Eigen/Eigenvalues>
#include <vtkCellArray.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkUnsignedCharArray.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <limits>

#include "core/export/map_ply.h"
#include "core/io/ply_mesh_reader.h"
#include "core/util/error.h"

namespace tunnelmap::render {

namespace {

// Centre of the triangles of each wall class (Left..Bottom); `count` 0 where a wall is absent.
struct WallCentres {
  std::array<Eigen::Vector3d, 4> centre;
  std::array<int, 4> count{};
  bool has(WallClass c) const { return count[static_cast<int>(c)] > 0; }
  Eigen::Vector3d at(WallClass c) const { return centre[static_cast<int>(c)]; }
};

WallCentres wall_centres(const PlyMesh& mesh) {
  WallCentres w;
  for (auto& c : w.centre) c.setZero();
  if (mesh.face_walls.size() != mesh.triangles.size()) return w;
  for (std::size_t f = 0; f < mesh.triangles.size(); ++f) {
    const int wall = mesh.face_walls[f];
    if (wall < 0 || wall > 3) continue;
    Eigen::Vector3d c = Eigen::Vector3d::Zero();
    for (int k = 0; k < 3; ++k) c += mesh.vertices[mesh.triangles[f][k]].cast<double>();
    w.centre[wall] += c / 3.0;
    ++w.count[wall];
  }
  for (int k = 0; k < 4; ++k)
    if (w.count[k] > 0) w.centre[k] /= w.count[k];
  return w;
}

Eigen::Vector3d orthogonal_unit(const Eigen::Vector3d& v, const Eigen::Vector3d& axis) {
  const Eigen::Vector3d o = v - v.dot(axis) * axis;
  return o.norm() > 1e-9 ? Eigen::Vector3d(o.normalized()) : Eigen::Vector3d::Zero();
}

// The tunnel frame: up from the floor to the roof and left from the right wall to the left one
// when the mesh has those walls; otherwise the longest direction of the points as the axis and
// world +z as up.
TunnelMap frame_of(const PlyMesh& mesh) {
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();
  for (const auto& v : mesh.vertices) centre += v.cast<double>();
  centre /= static_cast<double>(mesh.vertices.size());
  Eigen::Matrix3d cov = Eigen::Matrix3d::Zero();
  for (const auto& v : mesh.vertices) {
    const Eigen::Vector3d d = v.cast<double>() - centre;
    cov += d * d.transpose();
  }
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(cov);
  Eigen::Vector3d axis = eig.eigenvectors().col(2);  // largest spread

  const WallCentres walls = wall_centres(mesh);
  Eigen::Vector3d up = Eigen::Vector3d::Zero(), left = Eigen::Vector3d::Zero();
  if (walls.has(WallClass::Top) && walls.has(WallClass::Bottom))
    up = walls.at(WallClass::Top) - walls.at(WallClass::Bottom);
  if (walls.has(WallClass::Left) && walls.has(WallClass::Right))
    left = walls.at(WallClass::Left) - walls.at(WallClass::Right);
  if (up.norm() > 1e-6 && left.norm() > 1e-6) axis = left.normalized().cross(up.normalized());
  if (axis.norm() < 1e-9) axis = Eigen::Vector3d::UnitX();
  axis.normalize();
  if (up.norm() > 1e-6) up = orthogonal_unit(up, axis);
  if (up.norm() < 0.5 && left.norm() > 1e-6) up = orthogonal_unit(axis.cross(left), axis);
  if (up.norm() < 0.5) up = orthogonal_unit(Eigen::Vector3d::UnitZ(), axis);
  if (up.norm() < 0.5) up = orthogonal_unit(Eigen::Vector3d::UnitY(), axis);
  // With one side wall the axis's sign is the spread's: turn it so that the wall is on its side
  // (the oblique camera stands above the right wall).
  const bool only_left = walls.has(WallClass::Left) && !walls.has(WallClass::Right);
  const bool only_right = walls.has(WallClass::Right) && !walls.has(WallClass::Left);
  if (only_left || only_right) {
    const Eigen::Vector3d towards = walls.at(only_left ? WallClass::Left : WallClass::Right) - centre;
    if ((only_left ? 1.0 : -1.0) * up.cross(axis).dot(towards) < 0) axis = -axis;
  }
  const Eigen::Vector3d side = up.cross(axis);

  TunnelMap frame;
  frame.detected = true;
  frame.status = TunnelStatus::Ok;
  frame.axis_point = centre;
  frame.axis_dir = axis;
  frame.up = up;
  double lo[3], hi[3];
  std::fill(lo, lo + 3, std::numeric_limits<double>::infinity());
  std::fill(hi, hi + 3, -std::numeric_limits<double>::infinity());
  for (const auto& v : mesh.vertices) {
    const Eigen::Vector3d d = v.cast<double>() - centre;
    const double c[3] = {d.dot(axis), d.dot(side), d.dot(up)};
    for (int k = 0; k < 3; ++k) {
      lo[k] = std::min(lo[k], c[k]);
      hi[k] = std::max(hi[k], c[k]);
    }
  }
  frame.extent_min_m = lo[0];
  frame.extent_max_m = hi[0];
  frame.width_m = hi[1] - lo[1];
  frame.height_m = hi[2] - lo[2];
  return frame;
}

}  // namespace

bool is_mesh_input(const std::string& path) {
  if (path.size() < 4) return false;
  std::string ext = path.substr(path.size() - 4);
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
  return ext == ".ply";
}

MapMesh load_map_mesh(const std::string& path, bool cutaway) {
  const PlyMesh mesh = read_ply_mesh(path);
  if (mesh.triangles.empty()) throw InputError(path, "has no triangles to show (not a map or mesh PLY)");
  MapMesh out;
  // The boundary bands lie in the zones' planes; kept apart so they can be drawn on top.
  const bool labelled = mesh.face_labels.size() == mesh.triangles.size();
  auto is_boundary = [&](std::size_t f) {
    return labelled && mesh.face_labels[f] == static_cast<int>(MapFaceLabel::Boundary);
  };
  // The oblique camera stands above the right wall: without the roof and that wall it looks in.
  const bool walled = mesh.face_walls.size() == mesh.triangles.size();
  auto cut = [&](std::size_t f) {
    return cutaway && walled &&
           (mesh.face_walls[f] == static_cast<int>(WallClass::Top) ||
            mesh.face_walls[f] == static_cast<int>(WallClass::Right));
  };
  out.poly = scene::mesh_polydata(mesh, [&](std::size_t f) { return !is_boundary(f) && !cut(f); });
  out.boundary = scene::mesh_polydata(mesh, [&](std::size_t f) { return is_boundary(f) && !cut(f); });
  out.frame = frame_of(mesh);
  out.triangles = mesh.triangles.size();
  return out;
}

}  // namespace tunnelmap::render
