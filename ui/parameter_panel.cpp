#include "ui/parameter_panel.h"

#include <QGroupBox>
#include <QHBoxLayout>
#include <QPushButton>
#include <QScrollArea>
#include <QVBoxLayout>

#include "ui/parameter_row.h"

namespace tunnelmap::ui {

namespace {
QString group_title(const QString& prefix) {
  if (prefix == "cloud") return QObject::tr("Point cloud");
  if (prefix == "normals") return QObject::tr("Normals");
  if (prefix == "grow") return QObject::tr("Plane growing (PG&&C)");
  if (prefix == "tunnel") return QObject::tr("Tunnel detection");
  if (prefix == "zones") return QObject::tr("Zones");
  return prefix;
}
}  // namespace

ParameterPanel::ParameterPanel(QWidget* parent) : QWidget(parent) {
  auto* outer = new QVBoxLayout(this);
  auto* scroll = new QScrollArea(this);
  scroll->setWidgetResizable(true);
  auto* inner = new QWidget(scroll);
  auto* layout = new QVBoxLayout(inner);
  QMap<QString, QVBoxLayout*> groups;
  for (const ParameterSpec& spec : parameter_table()) {
    const QString key = QString::fromStdString(spec.key);
    const QString prefix = key.section('.', 0, 0);
    if (!groups.contains(prefix)) {
      auto* box = new QGroupBox(group_title(prefix), inner);
      groups[prefix] = new QVBoxLayout(box);
      layout->addWidget(box);
    }
    auto* row = new ParameterRow(spec, inner);
    rows_[key] = row;
    groups[prefix]->addWidget(row);
    connect(row, &ParameterRow::valueEdited, this, [this](const QString& k, double v) {
      try {
        params_.set(k.toStdString(), v);
      } catch (const std::exception&) {
        rows_[k]->set_value(params_.get(k.toStdString()));  // keep the last valid value
        return;
      }
      emit parametersChanged(false);
    });
    connect(row, &ParameterRow::editFinished, this, [this] { emit parametersChanged(true); });
  }
  layout->addStretch(1);
  scroll->setWidget(inner);
  outer->addWidget(scroll, 1);
  auto* buttons = new QHBoxLayout;
  auto* reset_all = new QPushButton(tr("Reset all"), this);
  reset_all->setObjectName("resetAll");
  auto* load = new QPushButton(tr("Load preset…"), this);
  auto* save = new QPushButton(tr("Save preset…"), this);
  buttons->addWidget(reset_all);
  buttons->addWidget(load);
  buttons->addWidget(save);
  outer->addLayout(buttons);
  connect(reset_all, &QPushButton::clicked, this, [this] {
    Parameters defaults;
    set_parameters(defaults);
  });
  connect(load, &QPushButton::clicked, this, &ParameterPanel::loadPresetRequested);
  connect(save, &QPushButton::clicked, this, &ParameterPanel::savePresetRequested);
}

void ParameterPanel::set_parameters(const Parameters& p) {
  params_ = p;
  for (auto it = rows_.begin(); it != rows_.end(); ++it) it.value()->set_value(p.get(it.key().toStdString()));
  emit parametersChanged(true);
}

}  // namespace tunnelmap::ui
