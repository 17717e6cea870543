#pragma once
// The Device menu: the OpenNI2 device list, the live view (each camera frame through the
// pipeline, newest first, into the views), and recording the live stream to .oni.
#include <QObject>
#include <QStringList>

class QActionGroup;
class QMenu;

namespace tunnelmap::ui {

class FrameController;
class LiveView;
struct RunOutcome;
struct WindowContext;

class DeviceController : public QObject {
  Q_OBJECT
 public:
  DeviceController(WindowContext& ctx, FrameController* frames);
  ~DeviceController() override;

  void add_menu(QMenu* device);
  // All return false and show the error on failure.
  QStringList refresh_devices();              // URIs of the connected devices
  bool start_live_view(const QString& uri);   // "" = the device chosen in Device > Devices
  void stop_live_view();
  bool start_recording(const QString& path);  // .oni, while the live view runs
  bool stop_recording();
  LiveView* live_view() const { return live_; }
  bool live() const;

 signals:
  void liveStarted();  // the views show the camera: the open input's review state goes

 private:
  void on_live_frame(const RunOutcome& outcome);
  void update_actions();

  WindowContext& ctx_;
  FrameController* frames_;
  LiveView* live_;
  QMenu* devices_menu_ = nullptr;
  QActionGroup* device_actions_ = nullptr;
};

}  // namespace tunnelmap::ui
