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

// Calls f(index) for every `stride`-th pixel of every `stride`-th row (a cloud that is not a
// full width x height grid is sampled as one row).
template <class F>
void for_sampled(const OrganizedCloud& cloud, int stride, F&& f) {
  int w = cloud.width, h = cloud.height;
  if (static_cast<std::size_t>(w) * h != cloud.points.size() || w <= 0 || h <= 0) {
    w = static_cast<int>(cloud.points.size());
    h = 1;
  }
  for (int v = 0; v < h; v += stride)
    for (int u = 0; u < w; u += stride) f(static_cast<std::size_t>(v) * w + u);
}

}  // namespace

int display_stride(int width, int height, int max_points) {
  if (max_points <= 0 || width <= 0 || height <= 0) return 1;
  int stride = 1;
  while (static_cast<long long>((width + stride - 1) / stride) * ((height + stride - 1) / stride) > max_points)
    ++stride;
  return stride;
}

vtkSmartPointer<vtkPolyData> make_cloud_polydata(const SceneData& data, int stride) {
  stride = std::max(1, stride);
  PointsBuilder out(data.cloud ? static_cast<vtkIdType>(data.cloud->points.size() / (stride * stride)) : 0);
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
  for_sampled(cloud, stride, [&](std::size_t i) {
    const auto& p = cloud.points[i];
    if (!OrganizedCloud::valid(p)) return;
    if (rgb)
      out.add(p, &data.frame->rgb[i * 3]);
    else
      out.add(p, depth_color((p.z() - zmin) / span));
  });
  return out.finish();
}

vtkSmartPointer<vtkPolyData> make_planes_polydata(const SceneData& data, int stride) {
  stride = std::max(1, stride);
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
  for_sampled(cloud, stride, [&](std::size_t i) {
    const std::int32_t id = planes.labels[i];
    if (id <= 0 || !OrganizedCloud::valid(cloud.points[i])) return;
    auto it = color_of.find(id);
    out.add(cloud.points[i], it == color_of.end() ? unassigned : it->second);
  });
  return out.finish();
}

}  // namespace tunnelmap::scene
