#pragma once
// Point picking and distance measurement in the 3D scene: a click picks the surface drawn under
// the cursor; two picks give a distance, drawn as a line with its length in millimetres.
#include <Eigen/Core>
#include <optional>
#include <string>
#include <vector>

#include <vtkPolyData.h>
#include <vtkRenderer.h>
#include <vtkSmartPointer.h>

namespace tunnelmap::scene {

// The drawn surface point under display position (x, y) (VTK display coordinates: origin
// bottom-left), or the nearest drawn pixel within 3 px; none over background. Reads the depth
// buffer of the renderer's last render.
std::optional<Eigen::Vector3d> pick_point(vtkRenderer* renderer, double x, double y);

struct Measurement {
  std::vector<Eigen::Vector3d> picks;  // 0, 1 or 2
  // A third pick starts the measurement again.
  void add(const Eigen::Vector3d& p);
  std::optional<double> distance_m() const;
  std::string label() const;  // "1234.5 mm", empty before two picks
};

// The 3D view's measurements, oldest first: a pick goes to the last one, or starts a new one
// when the last has its two points, so earlier distances stay on screen until cleared.
void add_pick(std::vector<Measurement>& measurements, const Eigen::Vector3d& p);

// Every measurement's picks as vertices and, with two, the segment between them.
vtkSmartPointer<vtkPolyData> measurement_polydata(const std::vector<Measurement>& measurements);
// One vertex at each segment's middle labelled with its distance (string array "label").
vtkSmartPointer<vtkPolyData> measurement_label(const std::vector<Measurement>& measurements);

}  // namespace tunnelmap::scene
