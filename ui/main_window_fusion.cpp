// MainWindow, Processing > Fuse sequence: the TSDF mesh, merged map and one frustum per arm
// pose on a worker thread, and the fused view at the refined or forward-kinematics poses.
#include <QAction>
#include <QLabel>
#include <QProgressBar>
#include <QPushButton>
#include <QSignalBlocker>
#include <QtConcurrent/QtConcurrentRun>
#include <algorithm>

#include "ui/fused_scene.h"
#include "ui/live_view.h"
#include "ui/main_window.h"
#include "ui/map_summary.h"
#include "ui/parameter_panel.h"
#include "ui/results_panel.h"
#include "ui/view3d_widget.h"

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

void MainWindow::fuse_sequence() { start_fusion(true); }

void MainWindow::start_fusion(bool refine_poses) {
  if (sequence_running_) return;
  const Dataset* ds = source_ ? source_->dataset() : nullptr;
  if (!ds) {
    show_error(tr("%1: Fuse sequence needs a posed dataset (dataset.json with poses or joints)")
                   .arg(input_path_.isEmpty() ? tr("no input") : input_path_));
    emit fusionFinished(false);
    return;
  }
  if (live_->running()) stop_live_view();
  sequence_running_ = true;
  cancel_.store(false);
  progress_->setRange(0, 2 * static_cast<int>(ds->frames.size()));
  progress_->setValue(0);
  progress_->show();
  cancel_button_->show();
  status_label_->setText(refine_poses ? tr("Fusing %1 frame(s)…").arg(ds->frames.size())
                                      : tr("Fusing %1 frame(s) at the forward-kinematics poses…").arg(ds->frames.size()));
  auto source = source_;  // keeps the dataset alive
  const Parameters params = params_->parameters();
  // A fusion at the given poses completes the shown fusion `target` (its mesh for comparison).
  auto target = refine_poses ? nullptr : fused_;
  sequence_future_ = QtConcurrent::run([this, source, params, refine_poses, target] {
    auto fused = std::make_shared<FusedScene>();
    QString error;
    bool cancelled = false;
    try {
      *fused = build_fused_scene(*source->dataset(), params, [this](int done, int) {
        QMetaObject::invokeMethod(this, [this, done] { progress_->setValue(done); });
      }, cancel_, refine_poses);
    } catch (const FusionCancelled&) {
      cancelled = true;
    } catch (const std::exception& e) {
      error = QString::fromStdString(e.what());
    }
    QMetaObject::invokeMethod(this, [this, fused, error, cancelled, refine_poses, target] {
      progress_->hide();
      cancel_button_->hide();
      sequence_running_ = false;
      if (cancelled) {
        status_label_->setText(tr("Fusion cancelled"));
        return emit fusionFinished(false);
      }
      if (!error.isEmpty()) {
        show_error(error);
        return emit fusionFinished(false);
      }
      if (!refine_poses) {
        if (!target || target != fused_) return emit fusionFinished(false);  // another input or fusion since
        fused_->given_geometry = fused->geometry;
        given_mesh_ = true;
        if (fused_shown_ && !refined_action_->isChecked()) show_fused(false);
        status_label_->setText(tr("Forward-kinematics poses: mesh %1 triangles (refined poses: %2) — fusion %3 ms, mesh %4 ms")
                                   .arg(fused->triangles)
                                   .arg(fused_->triangles)
                                   .arg(fused->fuse_ms, 0, 'f', 0)
                                   .arg(fused->mesh_ms, 0, 'f', 0));
        return emit fusionFinished(true);
      }
      fused_ = fused;
      given_mesh_ = !fused->refined;  // not refined: both geometries are the given poses'
      fused_shown_ = true;
      {
        const QSignalBlocker block(refined_action_);  // a new fusion starts at the refined poses
        refined_action_->setChecked(true);
      }
      refined_action_->setEnabled(fused->refined);
      show_fused(true);
      fused_frusta_ = fused->frusta;
      fused_triangles_ = fused->triangles;
      QStringList lines;
      int rescan = 0;
      for (const auto& p : fused->groups) {
        rescan += p.rescan ? 1 : 0;
        lines << pose_line(p, fused->refined);
      }
      results_->set_pose_status(lines);
      const auto& m = fused->merged.map;
      status_label_->setText(
          tr("Fused %1 frame(s), %2 pose(s) (%3 to rescan): mesh %4 triangles; merged map %5; %8 — fusion %6 ms, mesh %7 ms")
              .arg(fused->frames)
              .arg(fused->frusta)
              .arg(rescan)
              .arg(fused->triangles)
              .arg(map_summary(m))
              .arg(fused->fuse_ms, 0, 'f', 0)
              .arg(fused->mesh_ms, 0, 'f', 0)
              .arg(refinement_summary(*fused)));
      emit fusionFinished(true);
    });
  });
}

void MainWindow::show_fused(bool reset_camera) {
  const bool refined = refined_action_->isChecked();
  const scene::SceneGeometry& g = refined ? fused_->geometry : fused_->given_geometry;
  view3d_->show_geometry(g, reset_camera);
  // The mesh then follows the shown frame's pose like a loaded mesh PLY (world frame).
  mesh_world_ = g.mesh;
  mesh_frame_ = last_.frame_index;
  std::vector<View3DWidget::Label> labels;
  // At the middle of each frustum's far end: the apices of nearby poses crowd together.
  const Eigen::Vector3d tip(0.0, 0.0, kFusedFrustumDepthM);
  for (const auto& p : fused_->groups) labels.push_back({(refined ? p.fused_pose : p.given_pose) * tip, pose_label(p)});
  view3d_->set_labels(labels);
}

void MainWindow::show_refined_poses(bool refined) {
  if (refined_action_->isChecked() != refined) return refined_action_->setChecked(refined);  // re-enters
  if (!fused_ || !fused_shown_) return;
  show_fused(false);
  if (refined) return status_label_->setText(tr("Refined poses: %1").arg(refinement_summary(*fused_)));
  if (given_mesh_) return status_label_->setText(tr("Forward-kinematics poses (mesh fused with them)"));
  if (sequence_running_)
    return status_label_->setText(tr("Forward-kinematics poses: frusta and map; the mesh is still the refined one"));
  start_fusion(false);  // the mesh at these poses, once, on the worker
}

bool MainWindow::refined_poses_shown() const { return refined_action_->isChecked(); }

std::vector<Eigen::Vector3d> MainWindow::fused_frustum_centres() const {
  std::vector<Eigen::Vector3d> out;
  if (!fused_ || !fused_shown_) return out;
  for (const auto& p : fused_->groups)
    out.push_back((refined_action_->isChecked() ? p.fused_pose : p.given_pose).translation());
  return out;
}

void MainWindow::leave_fused_view() {
  if (!fused_shown_) return;
  fused_shown_ = false;
  refined_action_->setEnabled(false);
  view3d_->set_labels({});
}

}  // namespace tunnelmap::ui
