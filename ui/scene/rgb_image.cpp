#include "ui/scene/rgb_image.h"

#include <vtkImageData.h>
#include <vtkSmartPointer.h>
#include <vtkUnsignedCharArray.h>
#include <vtkWindowToImageFilter.h>
#include <vtkPointData.h>

#include <cstring>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "core/util/atomic_file.h"
#include "core/util/error.h"
#include "core/util/image_file.h"

namespace tunnelmap::scene {

RgbImage grab_window(vtkRenderWindow* window) {
  auto grab = vtkSmartPointer<vtkWindowToImageFilter>::New();
  grab->SetInput(window);
  grab->SetInputBufferTypeToRGB();
  grab->ReadFrontBufferOff();
  grab->ShouldRerenderOff();
  grab->Update();
  vtkImageData* img = grab->GetOutput();
  int dims[3];
  img->GetDimensions(dims);
  RgbImage out;
  out.width = dims[0];
  out.height = dims[1];
  out.rgb.resize(static_cast<std::size_t>(out.width) * out.height * 3);
  auto* data = static_cast<const std::uint8_t*>(img->GetScalarPointer());
  if (!data || out.empty()) return RgbImage();
  // VTK's rows start at the bottom.
  const std::size_t row = static_cast<std::size_t>(out.width) * 3;
  for (int y = 0; y < out.height; ++y)
    std::memcpy(&out.rgb[y * row], data + (out.height - 1 - y) * row, row);
  return out;
}

void save_png(const RgbImage& image, const std::string& path) {
  if (image.empty()) throw InputError(path, "cannot write an empty image");
  cv::Mat rgb(image.height, image.width, CV_8UC3, const_cast<std::uint8_t*>(image.rgb.data()));
  cv::Mat bgr;
  cv::cvtColor(rgb, bgr, cv::COLOR_RGB2BGR);
  write_image_file(path, bgr);
}

RgbImage load_png(const std::string& path) {
  cv::Mat bgr = cv::imread(path, cv::IMREAD_COLOR);
  if (bgr.empty()) throw InputError(path, "cannot read image (missing or not an image)");
  cv::Mat rgb;
  cv::cvtColor(bgr, rgb, cv::COLOR_BGR2RGB);
  RgbImage out;
  out.width = rgb.cols;
  out.height = rgb.rows;
  out.rgb.assign(rgb.data, rgb.data + rgb.total() * 3);
  return out;
}

}  // namespace tunnelmap::scene
