#include "ui/scene/cloud_polydata.h"

#include <vtkCellArray.h>
#include <vtkIdTypeArray.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkUnsignedCharArray.h>

#include <algorithm>
#include <limits>
#include <unordered_map>

#include "ui/scene/scene_colors.h"

namespace tunnelmap::scene {

namespace {

// Accumulates points with colours, then packs them into one vertex cell (fast for ~300k points).
class PointsBuilder {
 public:
  explicit PointsBuilder(vtkIdType capacity = 0) {
    points_->SetDataTypeToFloat();
    if (capacity > 0) {
      points_->Allocate(capacity);
      colors_->Allocate(capacity * 3);
    }
    colors_->SetNumberOfComponents(3);
    colors_->SetName("colors");
  }
  void add(const Eigen::Vector3f& p, const Rgb& c) {
    points_->InsertNextPoint(p.x(), p.y(), p.z());
    colors_->InsertNextTypedTuple(std::array<unsigned char, 3>{
        static_cast<unsigned char>(c[0] * 255.0 + 0.5), static_cast<unsigned char>(c[1] * 255.0 + 0.5),
        static_cast<unsigned char>(c[2] * 255.0 + 0.5)}
                                      .data());
  }
  void add(const Eigen::Vector3f& p, const std::uint8_t* rgb) {
    points_->InsertNextPoint(p.x(), p.y(), p.z());
    colors_->InsertNextTypedTuple(rgb);
  }
  vtkSmartPointer<vtkPolyData> finish() {
    auto poly = vtkSmartPointer<vtkPolyData>::New();
    const vtkIdType n = points_->GetNumberOfPoints();
    auto verts = vtkSmartPointer<vtkCellArray>::New();
    if (n > 0) {
      // One poly-vertex cell over all points: offsets {0, n}, connectivity 0..n-1.
      auto offsets = vtkSmartPointer<vtkIdTypeArray>::New();
      offsets->SetNumberOfValues(2);
      offsets->SetValue(0, 0);
      offsets->SetValue(1, n);
      auto conn = vtkSmartPointer<vtkIdTypeArray>::New();
      conn->SetNumberOfValues(n);
      for (vtkIdType i = 0; i < n; ++i) conn->SetValue(i, i);
      verts->SetData(offsets, conn);
    }
    poly->SetPoints(points_);
    poly->SetVerts(verts);
    poly->GetPointData()->SetScalars(colors_);
    return poly;
  }

 private:
  vtkSmartPointer<vtkPoints> points_ = vtkSmartPointer<vtkPoints>::New();
  vtkSmartPointer<vtkUnsignedCharArray> colors_ = vtkSmartPointer<vtkUnsignedCharArray>::New();
};

}  // namespace

vtkSmartPointer<vtkPolyData> make_cloud_polydata(const SceneData& data) {
  PointsBuilder out(data.cloud ? static_cast<vtkIdType>(data.cloud->points.size()) : 0);
  if (!data.cloud) return out.finish();
  const OrganizedCloud& cloud = *data.cloud;
  const bool rgb = data.frame && data.frame->has_rgb() && data.frame->width == cloud.width &&
                   data.frame->height == cloud.height;
  float zmin = std::numeric_limits<float>::max(), zmax = -zmin;
  for (const auto& p : cloud.points)
    if (OrganizedCloud::valid(p)) {
      zmin = std::min(zmin, p.z());
      zmax = std::max(zmax, p.z());
    }
  const double span = zmax > zmin ? zmax - zmin : 1.0;
  for (std::size_t i = 0; i < cloud.points.size(); ++i) {
    const auto& p = cloud.points[i];
    if (!OrganizedCloud::valid(p)) continue;
    if (rgb)
      out.add(p, &data.frame->rgb[i * 3]);
    else
      out.add(p, depth_color((p.z() - zmin) / span));
  }
  return out.finish();
}

vtkSmartPointer<vtkPolyData> make_planes_polydata(const SceneData& data) {
  PointsBuilder out;
  if (!data.cloud || !data.planes) return out.finish();
  const OrganizedCloud& cloud = *data.cloud;
  const PlaneSegments& planes = *data.planes;
  if (planes.labels.size() != cloud.points.size()) return out.finish();
  // Label value (plane id) -> colour of its wall class.
  std::unordered_map<std::int32_t, Rgb> color_of;
  for (std::size_t k = 0; k < planes.planes.size(); ++k) {
    WallClass cls = WallClass::Unassigned;
    if (data.map && k < data.map->plane_classes.size()) cls = data.map->plane_classes[k];
    if (data.map && k < data.map->plane_outlier.size() && data.map->plane_outlier[k])
      cls = WallClass::Unassigned;
    color_of[planes.planes[k].id] = wall_class_color(cls);
  }
  const Rgb unassigned = wall_class_color(WallClass::Unassigned);
  for (std::size_t i = 0; i < cloud.points.size(); ++i) {
    const std::int32_t id = planes.labels[i];
    if (id <= 0 || !OrganizedCloud::valid(cloud.points[i])) continue;
    auto it = color_of.find(id);
    out.add(cloud.points[i], it == color_of.end() ? unassigned : it->second);
  }
  return out.finish();
}

}  // namespace tunnelmap::scene
