// MainWindow, parameter presets: load/save, the loaded preset's name in the title and status
// bar, and the preset matching the open dataset's tunnel kind offered (a status-bar button).
#include <QCoreApplication>
#include <QDir>
#include <QFileInfo>
#include <QLabel>
#include <QPushButton>
#include <nlohmann/json.hpp>

#include "core/tunnel/tunnel_options.h"
#include "core/util/build_paths.h"
#include "ui/message_log.h"
#include "ui/main_window.h"
#include "ui/parameter_panel.h"

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

// A design typed for one input is not the next input's: it is cleared (one undo step) and the
// status bar says so. A session or a preset brings its own design after this.
void MainWindow::clear_design(const QString& previous_input) {
  Parameters p = params_->parameters();
  if (p.get(tunnel_keys::design_width_m) == 0.0 && p.get(tunnel_keys::design_height_m) == 0.0) return;
  p.set(tunnel_keys::design_width_m, 0.0);
  p.set(tunnel_keys::design_height_m, 0.0);
  params_->set_parameters(p, tr("Clear the design of %1").arg(previous_input));
  messages_->add(tr("The design set for %1 was cleared: a design belongs to its input or session")
                     .arg(previous_input.isEmpty() ? tr("the last run") : previous_input));
}

bool MainWindow::load_preset(const QString& path) {
  try {
    Parameters p = params_->parameters();
    p.load_json_file(path.toStdString());
    preset_name_ = QFileInfo(path).completeBaseName();
    preset_params_ = p;
    params_->set_parameters(p, tr("Load preset %1").arg(QFileInfo(path).fileName()));
  } catch (const std::exception& e) {
    show_error(QString::fromStdString(e.what()));
    return false;
  }
  offer_preset_->hide();
  update_preset_status();
  return true;
}

bool MainWindow::save_preset(const QString& path) {
  try {
    params_->parameters().save_json_file(path.toStdString(), QFileInfo(path).baseName().toStdString());
  } catch (const std::exception& e) {
    show_error(QString::fromStdString(e.what()));
    return false;
  }
  preset_name_ = QFileInfo(path).completeBaseName();
  preset_params_ = params_->parameters();
  update_preset_status();
  return true;
}

void MainWindow::update_preset_status() {
  const bool modified = !(params_->parameters() == preset_params_);
  const QString preset = modified ? tr("%1 (modified)").arg(preset_name_) : preset_name_;
  preset_label_->setText(tr("Preset: %1").arg(preset));
  const QString input = input_path_.isEmpty() ? QString() : QFileInfo(input_path_).fileName() + " — ";
  setWindowTitle(tr("TunnelMap — %1preset %2").arg(input, preset));
}

void MainWindow::offer_matching_preset() {
  offer_preset_->hide();
  const Dataset* ds = source_ ? source_->dataset() : nullptr;
  const QString kind = ds ? tunnel_kind(*ds) : QString();
  if (kind.isEmpty() || kind == preset_name_) return;
  const QString path = presets_dir() + "/" + kind + ".json";
  if (!QFileInfo::exists(path)) return;
  offer_preset_->setProperty("path", path);
  offer_preset_->setText(tr("Use the %1 preset (dataset: %1 tunnel)").arg(kind));
  offer_preset_->show();
}

}  // namespace tunnelmap::ui
