// Makes Debian's X-only VTK 9.1 render through OSMesa (see docs/gui.md, "Headless rendering"):
// - GLEW loads every GL entry point through glXGetProcAddress(ARB); this executable defines and
//   exports (-rdynamic) both, answering with OSMesa's own entry points.
// - glewInit() then fails with GLEW_ERROR_NO_GLX_DISPLAY (4) only because there is no X display,
//   after all function pointers loaded. VTK treats any error as fatal, so map 4 to GLEW_OK.
// This file must never be linked into a process that renders through X (the Qt GUI).
#include <GL/osmesa.h>
#include <dlfcn.h>

extern "C" {

using TunnelmapGlProc = void (*)();

__attribute__((visibility("default"))) TunnelmapGlProc glXGetProcAddress(const unsigned char* name) {
  return reinterpret_cast<TunnelmapGlProc>(OSMesaGetProcAddress(reinterpret_cast<const char*>(name)));
}

__attribute__((visibility("default"))) TunnelmapGlProc glXGetProcAddressARB(const unsigned char* name) {
  return glXGetProcAddress(name);
}

__attribute__((visibility("default"))) unsigned int glewInit() {
  using GlewInitFn = unsigned int (*)();
  static GlewInitFn real = reinterpret_cast<GlewInitFn>(dlsym(RTLD_NEXT, "glewInit"));
  if (!real) return 1;  // GLEW_ERROR_NO_GL_VERSION: VTK reports it
  constexpr unsigned int kGlewOk = 0, kGlewErrorNoGlxDisplay = 4;
  const unsigned int result = real();
  return result == kGlewErrorNoGlxDisplay ? kGlewOk : result;
}

}  // extern "C"
