#include "ui/parameter_panel.h"

#include <QGroupBox>
#include <QHBoxLayout>
#include <QMessageBox>
#include <QPushButton>
#include <QScrollArea>
#include <QUndoStack>
#include <QVBoxLayout>

#include "core/engine/parameter_relevance.h"
#include "ui/parameter_row.h"

namespace tunnelmap::ui {

// One parameter change: undo restores the values before it, redo those after.
class ParameterChange : public QUndoCommand {
 public:
  ParameterChange(ParameterPanel* panel, Parameters before, Parameters after, const QString& what)
      : QUndoCommand(what), panel_(panel), before_(std::move(before)), after_(std::move(after)) {}
  void undo() override { panel_->apply(before_); }
  void redo() override {
    if (first_) first_ = false;  // pushed after the change was made: already applied
    else panel_->apply(after_);
  }

 private:
  ParameterPanel* panel_;
  Parameters before_, after_;
  bool first_ = true;
};

namespace {
QString group_title(const QString& prefix) {
  if (prefix == "cloud") return QObject::tr("Point cloud");
  if (prefix == "normals") return QObject::tr("Normals");
  if (prefix == "grow") return QObject::tr("Plane growing (PG&&C)");
  if (prefix == "tunnel") return QObject::tr("Tunnel detection");
  if (prefix == "zones") return QObject::tr("Zones");
  if (prefix == "ransac") return QObject::tr("RANSAC && LSE baseline");
  if (prefix == "qhull") return QObject::tr("Qhull baseline");
  if (prefix == "slam") return QObject::tr("Structure SLAM (posed sequences)");
  if (prefix == "map") return QObject::tr("Station map");
  if (prefix == "fusion") return QObject::tr("Fusion");
  return prefix;  // a group added to the table later still gets its rows
}
}  // namespace

ParameterPanel::ParameterPanel(QWidget* parent) : QWidget(parent) {
  undo_ = new QUndoStack(this);
  confirm_reset = [this] {
    return QMessageBox::question(this, tr("Reset all parameters?"),
                                 tr("Set every parameter back to its default? (Edit > Undo brings them back.)"),
                                 QMessageBox::Yes | QMessageBox::No, QMessageBox::No) == QMessageBox::Yes;
  };
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
      groups_[prefix] = box;
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
      update_relevance();
      emit parametersChanged(false);
    });
    const QString name = QString::fromStdString(spec.label.empty() ? spec.key : spec.label);
    connect(row, &ParameterRow::editFinished, this, [this, name](const QString&) {
      commit(tr("Change %1").arg(name));
      emit parametersChanged(true);
    });
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
    if (confirm_reset && !confirm_reset()) return;
    set_parameters(Parameters(), tr("Reset all"));
  });
  connect(load, &QPushButton::clicked, this, &ParameterPanel::loadPresetRequested);
  connect(save, &QPushButton::clicked, this, &ParameterPanel::savePresetRequested);
  update_relevance();
}

void ParameterPanel::set_method(Method method) {
  method_ = method;
  update_relevance();
}

void ParameterPanel::update_relevance() {
  QMap<QString, bool> group_shown;
  for (const ParameterSpec& spec : parameter_table()) {
    const QString key = QString::fromStdString(spec.key);
    const ParameterRelevance r = parameter_relevance(spec, params_, method_);
    ParameterRow* row = rows_[key];
    row->setHidden(r.relevance == Relevance::OtherMethod);
    row->set_unused_reason(QString::fromStdString(r.reason));
    group_shown[key.section('.', 0, 0)] |= r.relevance != Relevance::OtherMethod;
  }
  for (auto it = groups_.begin(); it != groups_.end(); ++it) it.value()->setHidden(!group_shown.value(it.key()));
}

void ParameterPanel::apply(const Parameters& p) {
  params_ = p;
  committed_ = p;
  for (auto it = rows_.begin(); it != rows_.end(); ++it) it.value()->set_value(p.get(it.key().toStdString()));
  update_relevance();
  emit parametersChanged(true);
}

void ParameterPanel::commit(const QString& what) {
  if (params_ == committed_) return;
  Parameters before = committed_;
  committed_ = params_;
  undo_->push(new ParameterChange(this, std::move(before), params_, what));
}

void ParameterPanel::set_parameters(const Parameters& p, const QString& what) {
  params_ = p;
  for (auto it = rows_.begin(); it != rows_.end(); ++it) it.value()->set_value(p.get(it.key().toStdString()));
  update_relevance();
  commit(what.isEmpty() ? tr("Set parameters") : what);
  emit parametersChanged(true);
}

void ParameterPanel::set_initial_parameters(const Parameters& p) {
  apply(p);
  undo_->clear();
}

}  // namespace tunnelmap::ui
