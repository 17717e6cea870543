#pragma once
// The fused view while Processing > Fuse sequence integrates: the mesh of the frames fused so
// far, growing. A PreviewMesher (ui/preview_mesher.h) meshes the volume between frames on the
// worker, where the volume is not being written (no lock), at most every kPreviewIntervalMs;
// the GUI thread swaps each snapshot into the 3D view (the first seen as the first frame's
// camera sees it, then the camera is left to the user) and says how far the fusion is.
#include <QObject>
#include <QVector>
#include <memory>

#include "ui/fused_scene.h"

namespace tunnelmap::ui {

struct PreviewChannel;
struct PreviewMesh;
struct WindowContext;

// At most this often (PreviewMesher also waits a multiple of what the last preview cost): a
// mesh that visibly grows without slowing the integration much.
constexpr int kPreviewIntervalMs = 1000;

class FusionPreview : public QObject {
  Q_OBJECT
 public:
  FusionPreview(WindowContext& ctx, QObject* parent);

  // The watcher for the worker of a fusion with `params` starting now (empty when previews are
  // off).
  VolumeWatcher start(const Parameters& params, const Dataset& dataset);
  void stop_showing() { showing_ = false; }  // a frame is shown: the view is not the fusion's
  // The 3D view shows a preview of the fusion still (none was replaced by a frame since).
  bool on_view() const { return showing_ && !shown_.isEmpty(); }
  void set_interval_ms(int ms) { interval_ms_ = ms; }  // 0: after every frame; < 0: off
  // The triangle counts of the previews the last fusion showed, in order.
  const QVector<long long>& shown_triangles() const { return shown_; }
  double worker_ms() const { return worker_ms_; }  // making them on the worker, all together
  double show_ms() const { return show_ms_; }      // showing them on the GUI thread, all together

 signals:
  void previewShown(long long triangles);

 private:
  void show(const PreviewMesh& preview);

  WindowContext& ctx_;
  int interval_ms_;
  bool showing_ = false;
  std::shared_ptr<PreviewChannel> channel_;
  Eigen::Isometry3d first_camera_ = Eigen::Isometry3d::Identity();  // the first preview looks like it
  QVector<long long> shown_;
  double worker_ms_ = 0.0, show_ms_ = 0.0;
};

}  // namespace tunnelmap::ui
