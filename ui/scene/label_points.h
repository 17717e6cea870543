#pragma once
// Polydata of labelled points, as the scene's text actors read it (vtkLabeledDataMapper over the
// string array "label"): the distance grid, the width and height, a measurement's length.
#include <Eigen/Core>
#include <string>

#include <vtkCellArray.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>
#include <vtkStringArray.h>

namespace tunnelmap::scene {

class LabelPoints {
 public:
  LabelPoints() {
    labels_->SetName("label");
    poly_->SetPoints(points_);
    poly_->SetVerts(verts_);
    poly_->GetPointData()->AddArray(labels_);
  }
  void add(const Eigen::Vector3d& at, const std::string& text) {
    const vtkIdType id = points_->InsertNextPoint(at.x(), at.y(), at.z());
    verts_->InsertNextCell(1, &id);
    labels_->InsertNextValue(text);
  }
  vtkSmartPointer<vtkPolyData> polydata() const { return poly_; }

 private:
  vtkSmartPointer<vtkPolyData> poly_ = vtkSmartPointer<vtkPolyData>::New();
  vtkSmartPointer<vtkPoints> points_ = vtkSmartPointer<vtkPoints>::New();
  vtkSmartPointer<vtkCellArray> verts_ = vtkSmartPointer<vtkCellArray>::New();
  vtkSmartPointer<vtkStringArray> labels_ = vtkSmartPointer<vtkStringArray>::New();
};

}  // namespace tunnelmap::scene
