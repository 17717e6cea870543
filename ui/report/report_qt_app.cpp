#include "ui/report/report_qt_app.h"

#include <QCoreApplication>
#include <QGuiApplication>
#include <cstdio>
#include <stdexcept>

namespace tunnelmap::report {

namespace {
void critical_only(QtMsgType type, const QMessageLogContext&, const QString& msg) {
  if (type == QtFatalMsg || type == QtCriticalMsg) fprintf(stderr, "%s\n", qPrintable(msg));
}
}  // namespace

QuietQtWarnings::QuietQtWarnings() : previous_(qInstallMessageHandler(critical_only)) {}

QuietQtWarnings::~QuietQtWarnings() { qInstallMessageHandler(previous_); }

void ensure_gui_application() {
  QCoreApplication* existing = QCoreApplication::instance();
  if (qobject_cast<QGuiApplication*>(existing)) return;
  if (existing)
    throw std::runtime_error("cannot write the report: a non-GUI Qt application is running");
  // Forced, not defaulted: an inherited QT_QPA_PLATFORM=xcb without a display would abort.
  qputenv("QT_QPA_PLATFORM", "offscreen");
  // QGuiApplication keeps references to argc/argv for its whole life, hence static storage.
  static int argc = 1;
  static char name[] = "tunnelmap";
  static char* argv[] = {name, nullptr};
  // Qt's start-up warnings (e.g. "XDG_RUNTIME_DIR not set") are noise in a CLI's output: drop
  // them while the application starts, then restore the previous handler.
  const QuietQtWarnings quiet;
  // Never destroyed: it must outlive every font and painter, up to process exit.
  static QGuiApplication* app = new QGuiApplication(argc, argv);
  (void)app;
}

}  // namespace tunnelmap::report
