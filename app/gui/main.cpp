// tunnelmap: the inspection GUI.
//   tunnelmap [INPUT] [--params FILE] [--method pgc|ransac|qhull] [--frame N] [--view V] [--size WxH]
//             [--screenshot FILE --exit] [--list-devices] [--intrinsics FX,FY,CX,CY] [--session FILE]
//             [--device URI]
// With --screenshot the window is grabbed once the first frame is processed; with --exit the
// program then quits (exit 0, or 3 when the input or the screenshot failed). --list-devices
// prints the URIs Device > Refresh finds, one per line, and quits (as in the menu, no device is
// not an error). --session opens a review session (docs/gui.md) instead of INPUT; --device starts
// the live view; --intrinsics applies to INPUT as the CLI's --intrinsics does.
#include <QApplication>
#include <QCommandLineParser>
#include <QSurfaceFormat>
#include <QTimer>
#include <QVTKOpenGLNativeWidget.h>
#include <iostream>

#include "core/baselines/method.h"
#include "sensors/openni/register_openni.h"
#include "ui/main_window.h"
#include "ui/review_session.h"
#include "ui/view3d_widget.h"

namespace {
// QApplication takes "-session"/"--session" for X11 session management and drops it: ours is
// taken out of argv first. Returns the FILE of "--session FILE" or "--session=FILE", or "".
QString take_session_option(int& argc, char** argv, bool& given) {
  QString file;
  int out = 1;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if ((a == "--session" || a == "-session") && i + 1 < argc) {
      file = QString::fromLocal8Bit(argv[++i]);
      given = true;
    } else if (a.rfind("--session=", 0) == 0) {
      file = QString::fromLocal8Bit(argv[i] + 10);
      given = true;
    } else {
      argv[out++] = argv[i];
    }
  }
  argc = out;
  argv[argc] = nullptr;
  return file;
}
}  // namespace

int main(int argc, char** argv) {
  QSurfaceFormat::setDefaultFormat(QVTKOpenGLNativeWidget::defaultFormat());
  bool session_given = false;
  const QString session_file = take_session_option(argc, argv, session_given);
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
  QCommandLineOption devices_opt("list-devices", "Print the OpenNI2 device URIs (Device > Refresh) and quit");
  QCommandLineOption intrinsics_opt("intrinsics", "Camera intrinsics of INPUT: FX,FY,CX,CY in pixels", "K");
  QCommandLineOption session_opt("session", "Open a review session JSON (File > Open review session)", "FILE");
  QCommandLineOption device_opt("device", "Start the live view on an OpenNI2 device URI", "URI");
  QCommandLineOption map_opt("map", "Posed datasets: map the tunnel (Processing > Map tunnel) once the first frame is shown");
  QCommandLineOption station_opt("station", "With --map: show station S (metres along the map), as a click on the profile does",
                                 "S");
  cli.addOptions({params_opt, shot_opt, exit_opt, size_opt, view_opt, frame_opt, method_opt, devices_opt,
                  intrinsics_opt, session_opt, device_opt, map_opt, station_opt});
  cli.process(app);
  tunnelmap::openni2::register_openni_inputs();  // INPUT / File > Open may be an .oni recording

  tunnelmap::ui::MainWindow window;
  if (cli.isSet(devices_opt)) {
    for (const QString& uri : window.refresh_devices()) std::cout << uri.toStdString() << "\n";
    return 0;
  }
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
  if (cli.isSet(method_opt) || !session_given) {  // a session has its own method
    try {
      window.set_method(tunnelmap::parse_method(cli.value(method_opt).toStdString()));
    } catch (const std::exception& e) {
      fail(QString("--method: %1").arg(e.what()));
    }
  }
  const QStringList inputs = cli.positionalArguments();
  if (cli.isSet(intrinsics_opt)) {
    try {
      const tunnelmap::Intrinsics K = tunnelmap::ui::parse_intrinsics(cli.value(intrinsics_opt).toStdString());
      if (!inputs.isEmpty()) window.use_intrinsics(inputs.first(), K);
    } catch (const std::exception& e) {
      fail(e.what());
    }
  }
  // The frame a --screenshot waits for: --frame, else the session's, else the first (live: any).
  const bool live = cli.isSet(device_opt);
  const bool from_session = session_given && !cli.isSet(frame_opt);

  // --map: the map is built after the first frame, then --station picks the frame to show; a
  // screenshot waits for both.
  const bool map_requested = cli.isSet(map_opt);
  bool map_done = !map_requested;
  double station = 0.0;
  if (cli.isSet(station_opt)) {
    bool ok = false;
    station = cli.value(station_opt).toDouble(&ok);
    if (!ok || !map_requested) fail(QString("--station %1: expects metres, with --map").arg(cli.value(station_opt)));
  }

  const QString shot = cli.value(shot_opt);
  static bool grabbed = false;  // only once
  auto grab = [&] {
    if (grabbed || shot.isEmpty()) return;
    grabbed = true;
    try {  // a session's own camera stays unless --view is given
      if (cli.isSet(view_opt) || !session_given)
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
  };
  if (!shot.isEmpty()) {
    QObject::connect(&window, &tunnelmap::ui::MainWindow::frameShown, &window, [&] {
      if (!map_done) return;
      const int want = from_session || cli.isSet(station_opt) ? window.frame_index() : cli.value(frame_opt).toInt();
      if (!live && window.last_outcome().frame_index != want) return;
      grab();
    });
  }
  if (map_requested) {
    static bool started = false;
    QObject::connect(&window, &tunnelmap::ui::MainWindow::frameShown, &window, [&] {
      if (started) return;
      started = true;
      window.map_tunnel();
    });
    QObject::connect(&window, &tunnelmap::ui::MainWindow::tunnelMapped, &window, [&](bool ok) {
      if (!ok) return fail(window.last_error());
      QString why_not;
      if (cli.isSet(station_opt) && !window.show_station(station, &why_not))
        return fail(QString("--station %1: %2").arg(station).arg(why_not));
      map_done = true;
      // The station's frame is already shown (or no station asked): nothing else will come.
      if (window.last_outcome().frame_index == window.frame_index()) {
        if (!shot.isEmpty()) grab();
        else if (batch) app.exit(exit_code);
      }
    });
  }
  if (session_given) {
    if (exit_code == 0 && !window.open_session(session_file)) fail(window.last_error());
  } else if (live) {
    if (exit_code == 0 && !window.start_live_view(cli.value(device_opt))) fail(window.last_error());
  } else if (!inputs.isEmpty() && exit_code == 0 && !window.open_input(inputs.first())) {
    fail(window.last_error());
  }
  if (cli.isSet(frame_opt) && !live && exit_code == 0 && !window.select_frame(cli.value(frame_opt).toInt()))
    fail(QString("--frame %1: the input has no such frame").arg(cli.value(frame_opt)));
  if (batch && inputs.isEmpty() && !session_given && !live)
    fail("--exit needs an INPUT, --session or --device to process");
  if (batch && shot.isEmpty() && exit_code == 0 && !map_requested)
    QObject::connect(&window, &tunnelmap::ui::MainWindow::frameShown, &app, [&] { app.exit(0); });
  const int rc = app.exec();
  return exit_code ? exit_code : rc;
}
