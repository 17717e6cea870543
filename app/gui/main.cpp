// tunnelmap: the inspection GUI.
//   tunnelmap [INPUT] [--params FILE] [--method pgc|ransac|qhull] [--frame N] [--view V] [--size WxH]
//             [--screenshot FILE --exit]
// With --screenshot the window is grabbed once the first frame is processed; with --exit the
// program then quits (exit 0, or 3 when the input or the screenshot failed).
#include <QApplication>
#include <QCommandLineParser>
#include <QSurfaceFormat>
#include <QTimer>
#include <QVTKOpenGLNativeWidget.h>
#include <iostream>

#include "core/baselines/method.h"
#include "sensors/openni/register_openni.h"
#include "ui/main_window.h"
#include "ui/view3d_widget.h"

int main(int argc, char** argv) {
  QSurfaceFormat::setDefaultFormat(QVTKOpenGLNativeWidget::defaultFormat());
  QApplication app(argc, argv);
  QApplication::setOrganizationName("TunnelMap");
  QApplication::setApplicationName("tunnelmap");
  QApplication::setApplicationVersion(TUNNELMAP_VERSION);

  QCommandLineParser cli;
  cli.setApplicationDescription("TunnelMap inspection GUI");
  cli.addHelpOption();
  cli.addVersionOption();
  cli.addPositionalArgument("input", "Depth PNG, organised PCD or dataset folder");
  QCommandLineOption params_opt("params", "Parameter preset JSON", "FILE");
  QCommandLineOption shot_opt("screenshot", "Save a PNG grab of the window once processed", "FILE");
  QCommandLineOption exit_opt("exit", "Quit after --screenshot");
  QCommandLineOption size_opt("size", "Window size WIDTHxHEIGHT", "SIZE", "1400x860");
  QCommandLineOption view_opt("view", "Camera: along, side, top", "VIEW", "along");
  QCommandLineOption frame_opt("frame", "Show frame N of a sequence (0 = first)", "N", "0");
  QCommandLineOption method_opt("method", "Detection method: pgc (PG&C), ransac (R&L) or qhull", "METHOD", "pgc");
  cli.addOptions({params_opt, shot_opt, exit_opt, size_opt, view_opt, frame_opt, method_opt});
  cli.process(app);
  tunnelmap::openni2::register_openni_inputs();  // INPUT / File > Open may be an .oni recording

  tunnelmap::ui::MainWindow window;
  const bool batch = cli.isSet(exit_opt);
  window.suppress_dialogs = batch;
  const QStringList size = cli.value(size_opt).split('x');
  if (cli.isSet(size_opt) || batch) {
    if (size.size() == 2) window.resize(size[0].toInt(), size[1].toInt());
  }
  window.show();
  int exit_code = 0;
  auto fail = [&](const QString& message) {
    std::cerr << "tunnelmap: " << message.toStdString() << "\n";
    exit_code = 3;
    if (batch) QTimer::singleShot(0, &app, [&] { app.exit(exit_code); });
  };
  if (cli.isSet(params_opt) && !window.load_preset(cli.value(params_opt))) fail(window.last_error());
  try {
    window.set_method(tunnelmap::parse_method(cli.value(method_opt).toStdString()));
  } catch (const std::exception& e) {
    fail(QString("--method: %1").arg(e.what()));
  }

  const QString shot = cli.value(shot_opt);
  if (!shot.isEmpty()) {
    static bool grabbed = false;  // only the first processed frame
    QObject::connect(&window, &tunnelmap::ui::MainWindow::frameShown, &window, [&] {
      if (grabbed || window.last_outcome().frame_index != cli.value(frame_opt).toInt()) return;
      grabbed = true;
      try {
        window.view3d()->apply_view(tunnelmap::scene::parse_view(cli.value(view_opt).toStdString()));
      } catch (const std::exception& e) {
        return fail(e.what());
      }
      // Let the views repaint before grabbing.
      QTimer::singleShot(300, &window, [&] {
        if (!window.save_screenshot(shot)) return fail(window.last_error());
        std::cout << shot.toStdString() << "\n";
        if (batch) app.exit(exit_code);
      });
    });
  }
  const QStringList inputs = cli.positionalArguments();
  if (!inputs.isEmpty() && exit_code == 0 && !window.open_input(inputs.first())) fail(window.last_error());
  if (cli.isSet(frame_opt) && exit_code == 0 && !window.select_frame(cli.value(frame_opt).toInt()))
    fail(QString("--frame %1: the input has no such frame").arg(cli.value(frame_opt)));
  if (batch && inputs.isEmpty()) fail("--exit needs an INPUT to process");
  if (batch && shot.isEmpty() && exit_code == 0)
    QObject::connect(&window, &tunnelmap::ui::MainWindow::frameShown, &app, [&] { app.exit(0); });
  const int rc = app.exec();
  return exit_code ? exit_code : rc;
}
