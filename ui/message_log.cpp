#include "ui/message_log.h"

#include <QListWidget>
#include <QPushButton>
#include <QTime>
#include <QVBoxLayout>

namespace tunnelmap::ui {

MessageLog::MessageLog(QWidget* parent) : QWidget(parent) {
  list_ = new QListWidget(this);
  list_->setObjectName("messageList");
  list_->setWordWrap(true);
  auto* clear_button = new QPushButton(tr("Clear"), this);
  auto* layout = new QVBoxLayout(this);
  layout->setContentsMargins(2, 2, 2, 2);
  layout->addWidget(list_, 1);
  layout->addWidget(clear_button, 0, Qt::AlignRight);
  connect(clear_button, &QPushButton::clicked, this, &MessageLog::clear);
}

void MessageLog::add(const QString& message) {
  auto* item = new QListWidgetItem(QTime::currentTime().toString("hh:mm:ss") + "  " + message, list_);
  item->setData(Qt::UserRole, message);
  item->setToolTip(message);
  list_->scrollToBottom();
  emit changed(count());
}

void MessageLog::clear() {
  list_->clear();
  emit changed(0);
}

int MessageLog::count() const { return list_->count(); }

QString MessageLog::message(int i) const {
  const QListWidgetItem* item = list_->item(i);
  return item ? item->data(Qt::UserRole).toString() : QString();
}

}  // namespace tunnelmap::ui
