#pragma once
// Qt needs a QGuiApplication before any font or painter is used. The CLI has none, so the report
// creates one on the "offscreen" platform (no display needed) the first time it is called.
namespace tunnelmap::report {

// Returns at once when a QGuiApplication exists; creates an offscreen one when no Qt
// application exists; throws std::runtime_error when a non-GUI QCoreApplication is running
// (a QGuiApplication cannot be added to it).
void ensure_gui_application();

}  // namespace tunnelmap::report
