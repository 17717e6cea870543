#pragma once
// Processing > Fuse sequence: the TSDF mesh, merged map and one frustum per arm pose, fused on
// the background job (the mesh growing in the view meanwhile), shown in the world frame; View > Refined poses switches the frusta, map
// and mesh between the refined and the forward-kinematics poses (the latter fused once, on
// demand). Showing a frame leaves the fused view.
#include <Eigen/Core>
#include <QObject>
#include <functional>
#include <memory>
#include <vector>

class QAction;
class QMenu;

namespace tunnelmap::ui {

class FrameController;
class FusionPreview;
class ResultsPanel;
struct FusedScene;
struct WindowContext;

class FusionController : public QObject {
  Q_OBJECT
 public:
  FusionController(WindowContext& ctx, FrameController* frames);

  QAction* add_fuse_action(QMenu* processing);
  void add_view_actions(QMenu* view);  // View > Refined poses

  // Posed datasets, with progress and cancel; nothing while another job runs.
  void fuse_sequence();
  // On: the frusta and merged map at the refined poses the mesh was fused with; off: at the
  // forward-kinematics poses, and the mesh re-fused with them (once, on the worker).
  void show_refined_poses(bool refined);
  bool refined_poses_shown() const;
  // Camera centres of the frusta shown in the fused view (world frame), one per pose group.
  std::vector<Eigen::Vector3d> fused_frustum_centres() const;
  int fused_frusta() const { return frusta_; }
  long long fused_triangles() const { return triangles_; }
  FusionPreview* preview() const { return preview_; }  // the growing mesh while fusing
  void forget();  // a new input: the fusion belongs to the previous one
  std::function<void()> stop_live = [] {};

 signals:
  void fusionFinished(bool ok);

 private:
  void start_fusion(bool refine_poses);
  void finish_fusion(const std::shared_ptr<FusedScene>& fused, const QString& error, bool cancelled,
                     bool refine_poses, const std::shared_ptr<FusedScene>& target);
  void adopt_given_poses_mesh(const FusedScene& given);
  void adopt_fusion(const std::shared_ptr<FusedScene>& fused);
  void show_fused(bool reset_camera);  // at the poses View > Refined poses chooses
  void leave_fused_view();
  void drop_preview();  // after a cancelled or failed fusion

  WindowContext& ctx_;
  FrameController* frames_;
  ResultsPanel* results_;
  FusionPreview* preview_;
  QAction* refined_action_ = nullptr;
  std::shared_ptr<FusedScene> fused_;  // the last fusion (refined poses when refinement ran)
  bool shown_ = false;                 // the 3D view shows it (not a single frame)
  bool given_mesh_ = false;            // fused_->given_geometry holds a mesh fused at given poses
  int frusta_ = 0;
  long long triangles_ = 0;
};

}  // namespace tunnelmap::ui
