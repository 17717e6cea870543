#pragma once
// OsMesaWindow: a VTK render window that draws into an OSMesa (software, off-screen) OpenGL
// core-profile context. No X server and no DISPLAY needed. Only for executables linked with
// libOSMesa first and gl_shims.cpp exported (see app/render/CMakeLists.txt).
#include <memory>

#include <vtkGenericOpenGLRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkSmartPointer.h>

#include "ui/scene/rgb_image.h"

namespace tunnelmap::render {

class OsMesaWindow {
 public:
  // Throws std::runtime_error when no OSMesa 3.2+ core context can be created.
  OsMesaWindow(int width, int height);
  ~OsMesaWindow();
  OsMesaWindow(const OsMesaWindow&) = delete;
  OsMesaWindow& operator=(const OsMesaWindow&) = delete;

  void add_renderer(vtkRenderer* renderer) { window_->AddRenderer(renderer); }
  vtkRenderWindow* window() const { return window_; }
  // Renders and returns the frame (top row first).
  scene::RgbImage render();

 public:
  struct Context;  // the OSMesa context and its colour buffer (defined in the .cpp)

 private:
  std::unique_ptr<Context> context_;
  vtkSmartPointer<vtkGenericOpenGLRenderWindow> window_;
};

}  // namespace tunnelmap::render
