#pragma once
// The file dialogs every controller asks through. Hooks, so tests and batch runs drive the real
// menu actions: the defaults show QFileDialog / QMessageBox. A chooser returns the chosen path,
// or an empty string on cancel.
#include <QString>
#include <functional>

class QWidget;

namespace tunnelmap::ui {

class WindowStatus;

struct FileDialogs {
  using PathChooser = std::function<QString(const QString& title, const QString& folder, const QString& filter)>;

  FileDialogs(QWidget* parent, WindowStatus* status);

  PathChooser choose_open_path;  // File > Open…, Open mesh…, Load preset…
  PathChooser choose_save_path;  // exports, screenshot, Save preset…
  std::function<bool(const QString& path)> confirm_overwrite;  // true: replace the existing file
  bool suppress = false;  // --exit runs and tests: never ask (confirmations take "no")

  // In the last folder used; "" on cancel.
  QString ask_open_path(const QString& title, const QString& filter) const;
  // `suffix` added when the name has none; an existing file only when confirmed (else "" and
  // the status line says it was not written).
  QString ask_save_path(const QString& title, const QString& filter, const QString& suffix) const;
  static QString last_folder();

 private:
  WindowStatus* status_;
};

}  // namespace tunnelmap::ui
