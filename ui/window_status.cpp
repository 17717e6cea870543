#include "ui/window_status.h"

#include <QDockWidget>
#include <QLabel>
#include <QMainWindow>
#include <QProgressBar>
#include <QPushButton>
#include <QStatusBar>
#include <QToolButton>

#include "ui/message_log.h"

namespace tunnelmap::ui {

WindowStatus::WindowStatus(QMainWindow* window) : QObject(window), window_(window) {
  label_ = new QLabel(tr("Ready"), window);
  progress_ = new QProgressBar(window);
  progress_->setMaximumWidth(200);
  progress_->hide();
  cancel_button_ = new QPushButton(tr("Cancel"), window);
  cancel_button_->hide();
  window->statusBar()->addWidget(label_, 1);
  build_messages_dock(window);
}

void WindowStatus::build_messages_dock(QMainWindow* window) {
  messages_ = new MessageLog(window);
  messages_dock_ = new QDockWidget(tr("Messages"), window);
  messages_dock_->setObjectName("messagesDock");
  messages_dock_->setWidget(messages_);
  window->addDockWidget(Qt::BottomDockWidgetArea, messages_dock_);
  messages_dock_->hide();
  messages_button_ = new QToolButton(window);
  messages_button_->setObjectName("messagesButton");
  messages_button_->setAutoRaise(true);
  messages_button_->hide();  // until the first message
  connect(messages_button_, &QToolButton::clicked, this, [this] {
    messages_dock_->setVisible(!messages_dock_->isVisible());
    if (messages_dock_->isVisible()) messages_dock_->raise();
  });
  connect(messages_, &MessageLog::changed, this, [this](int n) {
    messages_button_->setText(tr("⚠ %n message(s)", nullptr, n));
    messages_button_->setVisible(n > 0);
  });
}

void WindowStatus::add_permanent_widgets() {
  window_->statusBar()->addPermanentWidget(progress_);
  window_->statusBar()->addPermanentWidget(cancel_button_);
  window_->statusBar()->addPermanentWidget(messages_button_);
}

void WindowStatus::set_text(const QString& text) { label_->setText(text); }

QString WindowStatus::text() const { return label_->text(); }

void WindowStatus::flash(const QString& text, int ms) { window_->statusBar()->showMessage(text, ms); }

void WindowStatus::show_error(const QString& message) {
  last_error_ = message;
  label_->setText(message);
  messages_->add(message);
  emit errorShown(message);
}

bool WindowStatus::run_or_show_error(const std::function<void()>& work, const QString& done) {
  try {
    work();
  } catch (const std::exception& e) {
    show_error(QString::fromStdString(e.what()));
    return false;
  }
  if (!done.isEmpty()) set_text(done);
  return true;
}

void WindowStatus::note(const QString& message) { messages_->add(message); }

void WindowStatus::show_progress(int maximum) {
  progress_->setRange(0, maximum);
  progress_->setValue(0);
  progress_->show();
  cancel_button_->show();
}

void WindowStatus::set_progress(int value) { progress_->setValue(value); }

void WindowStatus::set_progress(int value, int maximum) {
  progress_->setRange(0, maximum);
  progress_->setValue(value);
  progress_->show();
  cancel_button_->show();
}

void WindowStatus::hide_progress() {
  progress_->hide();
  cancel_button_->hide();
}

}  // namespace tunnelmap::ui
