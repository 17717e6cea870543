#include "ui/fusion_controller.h"

#include <QAction>
#include <QMainWindow>
#include <QMenu>
#include <QSignalBlocker>
#include <algorithm>

#include "ui/background_job.h"
#include "ui/frame_controller.h"
#include "ui/fused_scene.h"
#include "ui/fusion_preview.h"
#include "ui/map_summary.h"
#include "ui/parameter_panel.h"
#include "ui/results_panel.h"
#include "ui/view3d_widget.h"
#include "ui/window_context.h"
#include "ui/window_status.h"

namespace tunnelmap::ui {

namespace {

// "Pose 1: 0.64°, 6.3 mm" next to the pose's frustum; "Pose 1" when it has no correction.
QString pose_label(const FusedPoseGroup& p) {
  if (!p.corrected) return QObject::tr("Pose %1").arg(p.group);
  return QObject::tr("Pose %1: %2°, %3 mm")
      .arg(p.group)
      .arg(p.correction.rotation_deg, 0, 'f', 2)
      .arg(p.correction.translation_mm, 0, 'f', 1);
}

// The results panel's line for a pose: verdict, then its correction and the directions
// nothing constrained (kept at their forward-kinematics value).
QString pose_line(const FusedPoseGroup& p, bool refined) {
  QString line = QObject::tr("Pose %1 (frames %2–%3): %4")
                     .arg(p.group)
                     .arg(p.frames.empty() ? -1 : p.frames.front())
                     .arg(p.frames.empty() ? -1 : p.frames.back())
                     .arg(QString::fromStdString(p.message));
  if (!refined) return line;
  if (!p.corrected) return line + QObject::tr(" — not refined");
  line += QObject::tr(" — refined by %1°, %2 mm").arg(p.correction.rotation_deg, 0, 'f', 2).arg(p.correction.translation_mm, 0, 'f', 1);
  QStringList free;
  for (const auto& d : p.correction.degenerate) free << QString::fromStdString(d);
  line += free.isEmpty() ? QObject::tr("; all directions constrained")
                         : QObject::tr("; not constrained: %1").arg(free.join(", "));
  return line;
}

// "poses refined: largest 0.64°, 7.3 mm" (largest rotation and largest translation).
QString refinement_summary(const FusedScene& f) {
  if (!f.refined) return QObject::tr("poses not refined (no detection to align with)");
  double deg = 0.0, mm = 0.0;
  for (const auto& p : f.groups)
    if (p.corrected) {
      deg = std::max(deg, p.correction.rotation_deg);
      mm = std::max(mm, p.correction.translation_mm);
    }
  return QObject::tr("poses refined: largest %1°, %2 mm").arg(deg, 0, 'f', 2).arg(mm, 0, 'f', 1);
}

}  // namespace

FusionController::FusionController(WindowContext& ctx, FrameController* frames)
    : QObject(ctx.window), ctx_(ctx), frames_(frames), results_(frames->results()),
      preview_(new FusionPreview(ctx, this)) {
  connect(frames_, &FrameController::frameShown, this, &FusionController::leave_fused_view);
  connect(frames_, &FrameController::frameShown, preview_, &FusionPreview::stop_showing);
  // The view shows the growing mesh now, not the last fusion (Refined poses would redraw it),
  // and the next frame shown puts its own mesh (or none) back in the mesh layer.
  connect(preview_, &FusionPreview::previewShown, this, &FusionController::leave_fused_view);
  connect(preview_, &FusionPreview::previewShown, this, [this] { frames_->mesh().forget_placement(); });
}

QAction* FusionController::add_fuse_action(QMenu* processing) {
  QAction* a = processing->addAction(tr("&Fuse sequence"), this, &FusionController::fuse_sequence);
  a->setObjectName("fuseSequence");
  return a;
}

void FusionController::add_view_actions(QMenu* view) {
  refined_action_ = view->addAction(tr("Refined &poses"));
  refined_action_->setObjectName("refinedPoses");
  refined_action_->setCheckable(true);
  refined_action_->setChecked(true);
  refined_action_->setEnabled(false);  // until a fusion with refined poses is shown
  refined_action_->setStatusTip(tr("Fused view: camera frusta, merged map and mesh at the refined poses (on) "
                                   "or at the forward-kinematics poses (off)"));
  connect(refined_action_, &QAction::toggled, this, &FusionController::show_refined_poses);
}

void FusionController::fuse_sequence() { start_fusion(true); }

void FusionController::start_fusion(bool refine_poses) {
  if (ctx_.job->running()) return;
  const Dataset* ds = ctx_.dataset();
  if (!ds) {
    ctx_.status->show_error(tr("%1: Fuse sequence needs a posed dataset (dataset.json with poses or joints)")
                                .arg(ctx_.input_path.isEmpty() ? tr("no input") : ctx_.input_path));
    return emit fusionFinished(false);
  }
  if (frames_->live_running()) stop_live();  // the views show the fusion now
  ctx_.status->show_progress(2 * static_cast<int>(ds->frames.size()));
  ctx_.status->set_text(refine_poses
                            ? tr("Fusing %1 frame(s)…").arg(ds->frames.size())
                            : tr("Fusing %1 frame(s) at the forward-kinematics poses…").arg(ds->frames.size()));
  auto source = ctx_.source;  // keeps the dataset alive
  const Parameters params = ctx_.params->parameters();
  // A fusion at the given poses completes the shown fusion `target` (its mesh for comparison).
  auto target = refine_poses ? nullptr : fused_;
  const std::atomic<bool>& cancel = ctx_.job->cancel_flag();
  // Only the shown fusion grows in the view; a fusion at the given poses is a comparison.
  const VolumeWatcher watch = refine_poses ? preview_->start(params, *ds) : VolumeWatcher{};
  ctx_.job->start([this, source, params, refine_poses, target, watch, &cancel] {
    auto fused = std::make_shared<FusedScene>();
    QString error;
    bool cancelled = false;
    try {
      *fused = build_fused_scene(*source->dataset(), params, [this](int done, int) {
        QMetaObject::invokeMethod(this, [this, done] { ctx_.status->set_progress(done); });
      }, cancel, refine_poses, watch);
    } catch (const FusionCancelled&) {
      cancelled = true;
    } catch (const std::exception& e) {
      error = QString::fromStdString(e.what());
    }
    QMetaObject::invokeMethod(this, [=] { finish_fusion(fused, error, cancelled, refine_poses, target); });
  });
}

void FusionController::finish_fusion(const std::shared_ptr<FusedScene>& fused, const QString& error, bool cancelled,
                                     bool refine_poses, const std::shared_ptr<FusedScene>& target) {
  ctx_.status->hide_progress();
  ctx_.job->finished();
  if (cancelled || !error.isEmpty()) drop_preview();
  if (cancelled) {
    ctx_.status->set_text(tr("Fusion cancelled"));
    return emit fusionFinished(false);
  }
  if (!error.isEmpty()) {
    ctx_.status->show_error(error);
    return emit fusionFinished(false);
  }
  if (refine_poses) return adopt_fusion(fused);
  if (!target || target != fused_) return emit fusionFinished(false);  // another input or fusion since
  adopt_given_poses_mesh(*fused);
}

// The mesh fused at the given poses, beside the refined fusion it completes.
void FusionController::adopt_given_poses_mesh(const FusedScene& given) {
  fused_->given_geometry = given.geometry;
  given_mesh_ = true;
  if (shown_ && !refined_action_->isChecked()) show_fused(false);
  ctx_.status->set_text(tr("Forward-kinematics poses: mesh %1 triangles (refined poses: %2) — fusion %3 ms, mesh %4 ms")
                            .arg(given.triangles)
                            .arg(fused_->triangles)
                            .arg(given.fuse_ms, 0, 'f', 0)
                            .arg(given.mesh_ms, 0, 'f', 0));
  emit fusionFinished(true);
}

void FusionController::adopt_fusion(const std::shared_ptr<FusedScene>& fused) {
  fused_ = fused;
  given_mesh_ = !fused->refined;  // not refined: both geometries are the given poses'
  shown_ = true;
  {
    const QSignalBlocker block(refined_action_);  // a new fusion starts at the refined poses
    refined_action_->setChecked(true);
  }
  refined_action_->setEnabled(fused->refined);
  show_fused(true);
  frusta_ = fused->frusta;
  triangles_ = fused->triangles;
  QStringList lines;
  int rescan = 0;
  for (const auto& p : fused->groups) {
    rescan += p.rescan ? 1 : 0;
    lines << pose_line(p, fused->refined);
  }
  results_->set_pose_status(lines);
  ctx_.status->set_text(
      tr("Fused %1 frame(s), %2 pose(s) (%3 to rescan): mesh %4 triangles; merged map %5; %8 — fusion %6 ms, mesh %7 ms")
          .arg(fused->frames)
          .arg(fused->frusta)
          .arg(rescan)
          .arg(fused->triangles)
          .arg(map_summary(fused->merged.map))
          .arg(fused->fuse_ms, 0, 'f', 0)
          .arg(fused->mesh_ms, 0, 'f', 0)
          .arg(refinement_summary(*fused)));
  emit fusionFinished(true);
}

void FusionController::show_fused(bool reset_camera) {
  const bool refined = refined_action_->isChecked();
  const scene::SceneGeometry& g = refined ? fused_->geometry : fused_->given_geometry;
  ctx_.view3d->show_geometry(g, reset_camera);
  // The mesh then follows the shown frame's pose like a loaded mesh PLY (world frame).
  frames_->mesh().adopt(g.mesh, frames_->last_outcome().frame_index);
  std::vector<View3DWidget::Label> labels;
  // At the middle of each frustum's far end: the apices of nearby poses crowd together.
  const Eigen::Vector3d tip(0.0, 0.0, kFusedFrustumDepthM);
  for (const auto& p : fused_->groups) labels.push_back({(refined ? p.fused_pose : p.given_pose) * tip, pose_label(p)});
  ctx_.view3d->set_labels(labels);
}

void FusionController::show_refined_poses(bool refined) {
  if (refined_action_->isChecked() != refined) return refined_action_->setChecked(refined);  // re-enters
  if (!fused_ || !shown_) return;
  show_fused(false);
  if (refined) return ctx_.status->set_text(tr("Refined poses: %1").arg(refinement_summary(*fused_)));
  if (given_mesh_) return ctx_.status->set_text(tr("Forward-kinematics poses (mesh fused with them)"));
  if (ctx_.job->running())
    return ctx_.status->set_text(tr("Forward-kinematics poses: frusta and map; the mesh is still the refined one"));
  start_fusion(false);  // the mesh at these poses, once, on the worker
}

bool FusionController::refined_poses_shown() const { return refined_action_->isChecked(); }

std::vector<Eigen::Vector3d> FusionController::fused_frustum_centres() const {
  std::vector<Eigen::Vector3d> out;
  if (!fused_ || !shown_) return out;
  for (const auto& p : fused_->groups)
    out.push_back((refined_action_->isChecked() ? p.fused_pose : p.given_pose).translation());
  return out;
}

// A fusion that stops early leaves no partial mesh behind: the view returns to the last
// fusion, else to the current frame.
void FusionController::drop_preview() {
  if (!preview_->on_view()) return;
  preview_->stop_showing();
  if (!fused_) return frames_->request_run(true);
  shown_ = true;
  refined_action_->setEnabled(fused_->refined);
  show_fused(false);
}

void FusionController::leave_fused_view() {
  if (!shown_) return;
  shown_ = false;
  refined_action_->setEnabled(false);
  ctx_.view3d->set_labels({});
}

void FusionController::forget() {
  leave_fused_view();
  fused_.reset();  // a running compare fusion then finds nothing to attach to
}

}  // namespace tunnelmap::ui
