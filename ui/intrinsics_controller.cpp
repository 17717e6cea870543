#include "ui/intrinsics_controller.h"

#include <QAction>
#include <QDockWidget>
#include <QDoubleSpinBox>
#include <QFileInfo>
#include <QFormLayout>
#include <QLabel>
#include <QMainWindow>
#include <QMenu>
#include <QPushButton>
#include <QSettings>
#include <QUrl>

#include "core/io/input_options.h"
#include "core/io/png_folder.h"
#include "ui/frame_controller.h"
#include "ui/parameter_panel.h"
#include "ui/review_session.h"
#include "ui/window_context.h"
#include "ui/window_status.h"

namespace tunnelmap::ui {

namespace {

QString absolute(const QString& path) { return QFileInfo(path).absoluteFilePath(); }

QString settings_key(const QString& input) {
  // QSettings keys must not contain '/': the absolute path, percent-encoded.
  return "intrinsics/" + QString::fromLatin1(QUrl::toPercentEncoding(absolute(input)));
}

}  // namespace

bool takes_user_intrinsics(const QString& input) {
  const QFileInfo info(input);
  if (info.isFile()) return info.suffix().compare("png", Qt::CaseInsensitive) == 0;
  if (!info.isDir() || QFileInfo::exists(info.filePath() + "/dataset.json")) return false;
  return !list_depth_pngs(info.absoluteFilePath().toStdString()).empty();
}

IntrinsicsController::IntrinsicsController(WindowContext& ctx, FrameController* frames)
    : QObject(ctx.window), ctx_(ctx), frames_(frames) {
  build_dock();
  connect(frames_, &FrameController::frameShown, this, &IntrinsicsController::fill_dock);
}

void IntrinsicsController::build_dock() {
  dock_ = new QDockWidget(tr("Camera intrinsics"), ctx_.window);
  dock_->setObjectName("intrinsicsDock");
  auto* box = new QWidget(dock_);
  auto* form = new QFormLayout(box);
  const char* names[] = {"fx", "fy", "cx", "cy"};
  for (int i = 0; i < 4; ++i) {
    auto* spin = new QDoubleSpinBox(box);
    spin->setObjectName(QString("intrinsics_") + names[i]);
    spin->setRange(i < 2 ? 1.0 : -1e5, 1e5);
    spin->setDecimals(2);
    spin->setSuffix(" px");
    form->addRow(QString(names[i]) + ":", spin);
    k_[i] = spin;
  }
  auto* apply = new QPushButton(tr("Apply"), box);
  apply->setObjectName("applyIntrinsics");
  form->addRow(apply);
  note_ = new QLabel(box);
  note_->setWordWrap(true);
  form->addRow(note_);
  dock_->setWidget(box);
  ctx_.window->addDockWidget(Qt::LeftDockWidgetArea, dock_);
  dock_->hide();
  connect(apply, &QPushButton::clicked, this, [this] {
    Intrinsics K;
    K.fx = k_[0]->value(), K.fy = k_[1]->value();
    K.cx = k_[2]->value(), K.cy = k_[3]->value();
    set_intrinsics(K);
  });
}

void IntrinsicsController::add_actions(QMenu* file) {
  QAction* toggle = dock_->toggleViewAction();
  toggle->setObjectName("showIntrinsics");
  file->addAction(toggle);
}

ReadOptions IntrinsicsController::read_options_for(const QString& input) const {
  ReadOptions opt;
  if (ctx_.params) opt.max_image_pixels = input_limit_options(ctx_.params->parameters()).max_image_pixels;
  if (input.isEmpty()) return opt;
  const auto it = given_.find(absolute(input));
  if (it != given_.end()) {
    opt.intrinsics = it->second;
  } else if (takes_user_intrinsics(input)) {
    // A list: QSettings' INI format reads "a,b" back as a list.
    const QString saved = QSettings().value(settings_key(input)).toStringList().join(",");
    try {
      if (!saved.isEmpty()) opt.intrinsics = parse_intrinsics(saved.toStdString());
    } catch (const std::exception&) {
      // A stale or hand-edited entry: the default intrinsics.
    }
  }
  return opt;
}

std::optional<Intrinsics> IntrinsicsController::user_intrinsics(const QString& input) const {
  if (!takes_user_intrinsics(input)) return std::nullopt;
  return read_options_for(input).intrinsics;
}

void IntrinsicsController::use_intrinsics(const QString& input, const Intrinsics& K) { given_[absolute(input)] = K; }

bool IntrinsicsController::set_intrinsics(const Intrinsics& K) {
  const QString input = ctx_.input_path;
  if (!ctx_.source || !takes_user_intrinsics(input)) {
    ctx_.status->show_error(tr("%1: intrinsics are set only for a depth PNG or a folder of depth PNGs").arg(input));
    return false;
  }
  ReadOptions opt = read_options_for(input);
  opt.intrinsics = K;
  std::shared_ptr<const FrameSource> source;
  try {
    source = tunnelmap::open_input(input.toStdString(), opt);
    source->load(frames_->frame_index());
  } catch (const std::exception& e) {
    ctx_.status->show_error(QString::fromStdString(e.what()));
    return false;
  }
  use_intrinsics(input, K);
  QStringList saved;
  for (double v : {K.fx, K.fy, K.cx, K.cy}) saved << QString::number(v, 'g', 12);
  QSettings().setValue(settings_key(input), saved);
  ctx_.source = source;
  frames_->reload_input();
  return true;
}

void IntrinsicsController::fill_dock() {
  const scene::ProcessedFrame* shown = frames_->current();
  if (!shown) return;
  const Intrinsics& K = shown->frame.intrinsics;
  const double values[] = {K.fx, K.fy, K.cx, K.cy};
  for (int i = 0; i < 4; ++i) k_[i]->setValue(values[i]);
  const QString input = ctx_.input_path;
  const bool editable = takes_user_intrinsics(input);
  dock_->widget()->setEnabled(editable);
  note_->setText(editable ? tr("%1x%2 depth image; Apply re-runs and remembers them for this input").arg(K.width).arg(K.height)
                          : tr("Given by the input (dataset or recording)"));
  // A folder of PNGs opened: shown (a single PNG: File > Camera intrinsics).
  if (editable && QFileInfo(input).isDir() && panel_input_ != input) dock_->show();
  panel_input_ = input;
}

}  // namespace tunnelmap::ui
