#include "app/render/osmesa_window.h"

#include <GL/osmesa.h>
#include <vtkCallbackCommand.h>
#include <vtkCommand.h>

#include <stdexcept>
#include <string>
#include <vector>

namespace tunnelmap::render {

struct OsMesaWindow::Context {
  OSMesaContext ctx = nullptr;
  std::vector<unsigned char> buffer;
  int width = 0, height = 0;

  void make_current() const {
    if (!OSMesaMakeCurrent(ctx, const_cast<unsigned char*>(buffer.data()), GL_UNSIGNED_BYTE, width,
                           height))
      throw std::runtime_error("OSMesaMakeCurrent failed");
  }
};

namespace {
// The generic window asks its observers whether the context is current (bool*) and whether it
// supports OpenGL / is direct (int*): the answer is written through the call data pointer.
void answer_true_bool(vtkObject*, unsigned long, void*, void* call_data) {
  if (call_data) *static_cast<bool*>(call_data) = true;
}
void answer_true_int(vtkObject*, unsigned long, void*, void* call_data) {
  if (call_data) *static_cast<int*>(call_data) = 1;
}
void make_current(vtkObject*, unsigned long, void* client, void*) {
  static_cast<const OsMesaWindow::Context*>(client)->make_current();
}
}  // namespace

OsMesaWindow::OsMesaWindow(int width, int height) : context_(std::make_unique<Context>()) {
  if (width < 16 || height < 16 || width > 8192 || height > 8192)
    throw std::runtime_error("image size " + std::to_string(width) + "x" + std::to_string(height) +
                             " is out of range (16..8192)");
  const int attribs[] = {OSMESA_FORMAT, OSMESA_RGBA, OSMESA_DEPTH_BITS, 24, OSMESA_STENCIL_BITS, 8,
                         OSMESA_PROFILE, OSMESA_CORE_PROFILE, OSMESA_CONTEXT_MAJOR_VERSION, 3,
                         OSMESA_CONTEXT_MINOR_VERSION, 2, 0};
  context_->ctx = OSMesaCreateContextAttribs(attribs, nullptr);
  if (!context_->ctx) throw std::runtime_error("cannot create an OSMesa OpenGL 3.2 core context");
  context_->width = width;
  context_->height = height;
  context_->buffer.assign(static_cast<std::size_t>(width) * height * 4, 0);
  context_->make_current();

  window_ = vtkSmartPointer<vtkGenericOpenGLRenderWindow>::New();
  window_->SetSize(width, height);
  window_->SetMultiSamples(0);
  auto is_current = vtkSmartPointer<vtkCallbackCommand>::New();
  is_current->SetCallback(answer_true_bool);
  window_->AddObserver(vtkCommand::WindowIsCurrentEvent, is_current);
  for (unsigned long event : {vtkCommand::WindowSupportsOpenGLEvent, vtkCommand::WindowIsDirectEvent}) {
    auto cb = vtkSmartPointer<vtkCallbackCommand>::New();
    cb->SetCallback(answer_true_int);
    window_->AddObserver(event, cb);
  }
  auto current = vtkSmartPointer<vtkCallbackCommand>::New();
  current->SetCallback(make_current);
  current->SetClientData(context_.get());
  window_->AddObserver(vtkCommand::WindowMakeCurrentEvent, current);
  if (!window_->InitializeFromCurrentContext())
    throw std::runtime_error("VTK cannot use the OSMesa context (OpenGL 3.2 required)");
}

OsMesaWindow::~OsMesaWindow() {
  if (window_) {
    window_->Finalize();
    window_ = nullptr;
  }
  if (context_ && context_->ctx) OSMesaDestroyContext(context_->ctx);
}

scene::RgbImage OsMesaWindow::render() {
  context_->make_current();
  window_->Render();
  return scene::grab_window(window_);
}

}  // namespace tunnelmap::render
