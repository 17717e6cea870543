#include "ui/file_dialogs.h"

#include <QFileDialog>
#include <QFileInfo>
#include <QMessageBox>
#include <QSettings>

#include "ui/window_status.h"

namespace tunnelmap::ui {

FileDialogs::FileDialogs(QWidget* parent, WindowStatus* status) : status_(status) {
  choose_open_path = [parent](const QString& title, const QString& folder, const QString& filter) {
    return QFileDialog::getOpenFileName(parent, title, folder, filter);
  };
  choose_save_path = [parent](const QString& title, const QString& folder, const QString& filter) {
    // Overwriting is asked by confirm_overwrite (after the suffix is added), not twice.
    return QFileDialog::getSaveFileName(parent, title, folder, filter, nullptr, QFileDialog::DontConfirmOverwrite);
  };
  confirm_overwrite = [parent](const QString& path) {
    return QMessageBox::question(parent, QObject::tr("Replace file?"),
                                 QObject::tr("%1 already exists. Replace it?").arg(path),
                                 QMessageBox::Yes | QMessageBox::No, QMessageBox::No) == QMessageBox::Yes;
  };
}

QString FileDialogs::last_folder() { return QSettings().value("files/lastFolder").toString(); }

QString FileDialogs::ask_open_path(const QString& title, const QString& filter) const {
  return choose_open_path(title, last_folder(), filter);
}

QString FileDialogs::ask_save_path(const QString& title, const QString& filter, const QString& suffix) const {
  QString path = choose_save_path(title, last_folder(), filter);
  if (path.isEmpty()) return path;
  if (QFileInfo(path).suffix().isEmpty()) path += "." + suffix;
  if (QFileInfo::exists(path) && !confirm_overwrite(path)) {
    status_->set_text(QObject::tr("Not written: %1 exists").arg(path));
    return {};
  }
  return path;
}

}  // namespace tunnelmap::ui
