#include "ui/view3d_export.h"

#include <QImage>
#include <cstring>

#include <vtkImageData.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkSmartPointer.h>
#include <vtkWindowToImageFilter.h>

#include "core/util/atomic_file.h"
#include "core/util/error.h"
#include "ui/view3d_widget.h"

namespace tunnelmap::ui {

namespace {

constexpr int kMaxSide = 8192;

// One render of `renderer` in an off-screen window of the given size; null when the window
// did not give that size.
QImage render_off_screen(vtkRenderer* renderer, int width, int height) {
  QImage image;
  auto off = vtkSmartPointer<vtkRenderWindow>::New();
  off->SetOffScreenRendering(1);
  off->SetMultiSamples(0);
  off->SetSize(width, height);
  off->AddRenderer(renderer);
  off->Render();
  auto grab = vtkSmartPointer<vtkWindowToImageFilter>::New();
  grab->SetInput(off);
  grab->SetInputBufferTypeToRGB();
  grab->ReadFrontBufferOff();
  grab->Update();
  vtkImageData* img = grab->GetOutput();
  int dims[3];
  img->GetDimensions(dims);
  if (dims[0] == width && dims[1] == height) {
    image = QImage(width, height, QImage::Format_RGB888);
    const auto* px = static_cast<const unsigned char*>(img->GetScalarPointer());
    for (int y = 0; y < height; ++y)  // VTK rows run bottom-up
      std::memcpy(image.scanLine(height - 1 - y), px + std::size_t(y) * width * 3, std::size_t(width) * 3);
  }
  off->RemoveRenderer(renderer);
  off->Finalize();
  return image;
}

}  // namespace

void export_view3d_png(View3DWidget* view, const QString& path, int width, int height) {
  const std::string file = path.toStdString();
  if (width < 16 || height < 16 || width > kMaxSide || height > kMaxSide)
    throw InputError(file, QString("size %1x%2 out of range (16..%3 per side)").arg(width).arg(height).arg(kMaxSide).toStdString());
  // The scene's renderer moves into an off-screen window of the requested size for one
  // render, then back: same actors, camera and layers, no copy of the scene.
  vtkRenderer* renderer = view->scene().renderer();
  vtkRenderWindow* shown = view->renderWindow();
  view->makeCurrent();
  shown->RemoveRenderer(renderer);
  const QImage image = render_off_screen(renderer, width, height);
  view->makeCurrent();
  shown->AddRenderer(renderer);
  shown->Render();
  view->update();
  if (image.isNull()) throw InputError(file, "the off-screen render did not give the requested size");
  write_path_atomically(file, [&](const std::string& tmp) {
    if (!image.save(QString::fromStdString(tmp), "PNG")) throw InputError(file, "cannot write PNG");
  });
}

}  // namespace tunnelmap::ui
