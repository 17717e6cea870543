#pragma once
#include <QtGlobal>

// Qt needs a QGuiApplication before any font or painter is used. The CLI has none, so the report
// creates one on the "offscreen" platform (no display needed) the first time it is called.
namespace tunnelmap::report {

// Returns at once when a QGuiApplication exists; creates an offscreen one when no Qt
// application exists; throws std::runtime_error when a non-GUI QCoreApplication is running
// (a QGuiApplication cannot be added to it).
void ensure_gui_application();

// While one lives, Qt's warnings and debug output (e.g. "QPainter::begin(): Returned false"
// when the PDF cannot be written) are dropped: the report's own checks name the file and the
// problem in the one line the tool prints. Critical and fatal messages still reach stderr.
class QuietQtWarnings {
 public:
  QuietQtWarnings();
  ~QuietQtWarnings();
  QuietQtWarnings(const QuietQtWarnings&) = delete;
  QuietQtWarnings& operator=(const QuietQtWarnings&) = delete;

 private:
  QtMessageHandler previous_;
};

}  // namespace tunnelmap::report
