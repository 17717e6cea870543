#include "ui/preset_controller.h"

#include <QCoreApplication>
#include <QDir>
#include <QFileInfo>
#include <QLabel>
#include <QMainWindow>
#include <QPushButton>
#include <QStatusBar>
#include <QVariant>
#include <nlohmann/json.hpp>

#include "core/tunnel/tunnel_options.h"
#include "core/util/build_paths.h"
#include "ui/file_dialogs.h"
#include "ui/parameter_panel.h"
#include "ui/window_context.h"
#include "ui/window_status.h"

namespace tunnelmap::ui {

namespace {

// Installed presets (<prefix>/bin/tunnelmap -> <prefix>/share/tunnelmap/presets), else the
// source tree's (build tree and tests), as tunnelmap-cli evaluate finds them.
QString presets_dir() {
  const QString installed = QCoreApplication::applicationDirPath() + "/../share/tunnelmap/presets";
  if (QFileInfo(installed).isDir()) return QDir(installed).canonicalPath();
  return QString(TUNNELMAP_SOURCE_DIR) + "/resources/presets";
}

// The tunnel kind a dataset names: "tunnel_kind", else the simulator preset it was made with.
QString tunnel_kind(const Dataset& ds) {
  const nlohmann::json& raw = ds.raw;
  if (!raw.is_object()) return {};
  if (raw.contains("tunnel_kind") && raw["tunnel_kind"].is_string())
    return QString::fromStdString(raw["tunnel_kind"].get<std::string>());
  if (raw.contains("simulator") && raw["simulator"].is_object() && raw["simulator"].contains("preset") &&
      raw["simulator"]["preset"].is_string())
    return QString::fromStdString(raw["simulator"]["preset"].get<std::string>());
  return {};
}

}  // namespace

PresetController::PresetController(WindowContext& ctx) : QObject(ctx.window), ctx_(ctx) {
  // The loaded preset ("Preset: field", "(modified)" after an edit) and, when the open dataset
  // names its tunnel kind, a button offering the matching preset (never a dialog).
  offer_ = new QPushButton(ctx.window);
  offer_->setObjectName("offerPreset");
  offer_->hide();
  ctx.window->statusBar()->addPermanentWidget(offer_);
  connect(offer_, &QPushButton::clicked, this, [this] {
    if (load_preset(offer_->property("path").toString())) offer_->hide();
  });
  label_ = new QLabel(ctx.window);
  label_->setObjectName("presetLabel");
  ctx.window->statusBar()->addPermanentWidget(label_);
  ParameterPanel* panel = ctx.params;
  connect(panel, &ParameterPanel::parametersChanged, this, [this] { update_status(); });
  connect(panel, &ParameterPanel::loadPresetRequested, this, [this] {
    const QString path = ctx_.dialogs->ask_open_path(tr("Load parameter preset"), tr("JSON (*.json)"));
    if (!path.isEmpty()) load_preset(path);
  });
  connect(panel, &ParameterPanel::savePresetRequested, this, [this] {
    const QString path = ctx_.dialogs->ask_save_path(tr("Save parameter preset"), tr("JSON (*.json)"), "json");
    if (!path.isEmpty()) save_preset(path);
  });
}

void PresetController::clear_design(const QString& previous_input) {
  Parameters p = ctx_.params->parameters();
  if (p.get(tunnel_keys::design_width_m) == 0.0 && p.get(tunnel_keys::design_height_m) == 0.0) return;
  p.set(tunnel_keys::design_width_m, 0.0);
  p.set(tunnel_keys::design_height_m, 0.0);
  ctx_.params->set_parameters(p, tr("Clear the design of %1").arg(previous_input));
  ctx_.status->note(tr("The design set for %1 was cleared: a design belongs to its input or session")
                        .arg(previous_input.isEmpty() ? tr("the last run") : previous_input));
}

bool PresetController::load_preset(const QString& path) {
  try {
    Parameters p = ctx_.params->parameters();
    p.load_json_file(path.toStdString());
    name_ = QFileInfo(path).completeBaseName();
    params_ = p;
    ctx_.params->set_parameters(p, tr("Load preset %1").arg(QFileInfo(path).fileName()));
  } catch (const std::exception& e) {
    ctx_.status->show_error(QString::fromStdString(e.what()));
    return false;
  }
  offer_->hide();
  update_status();
  return true;
}

bool PresetController::save_preset(const QString& path) {
  try {
    ctx_.params->parameters().save_json_file(path.toStdString(), QFileInfo(path).baseName().toStdString());
  } catch (const std::exception& e) {
    ctx_.status->show_error(QString::fromStdString(e.what()));
    return false;
  }
  set_reference(QFileInfo(path).completeBaseName(), ctx_.params->parameters());
  return true;
}

void PresetController::set_reference(const QString& name, const Parameters& params) {
  name_ = name;
  params_ = params;
  update_status();
}

void PresetController::update_status() {
  const bool modified = !(ctx_.params->parameters() == params_);
  const QString preset = modified ? tr("%1 (modified)").arg(name_) : name_;
  label_->setText(tr("Preset: %1").arg(preset));
  const QString input = ctx_.input_path.isEmpty() ? QString() : QFileInfo(ctx_.input_path).fileName() + " — ";
  ctx_.window->setWindowTitle(tr("TunnelMap — %1preset %2").arg(input, preset));
}

void PresetController::offer_matching_preset() {
  offer_->hide();
  const Dataset* ds = ctx_.dataset();
  const QString kind = ds ? tunnel_kind(*ds) : QString();
  if (kind.isEmpty() || kind == name_) return;
  const QString path = presets_dir() + "/" + kind + ".json";
  if (!QFileInfo::exists(path)) return;
  offer_->setProperty("path", path);
  offer_->setText(tr("Use the %1 preset (dataset: %1 tunnel)").arg(kind));
  offer_->show();
}

}  // namespace tunnelmap::ui
