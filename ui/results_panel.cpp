#include "ui/results_panel.h"

#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QTableWidget>
#include <QVBoxLayout>
#include <algorithm>

#include "ui/results_plot.h"

namespace tunnelmap::ui {

ResultsPanel::ResultsPanel(QWidget* parent) : QWidget(parent) {
  auto* layout = new QHBoxLayout(this);
  auto* left = new QVBoxLayout;
  table_ = new QTableWidget(0, 7, this);
  table_->setHorizontalHeaderLabels({tr("Frame"), tr("Status"), tr("Width (m)"), tr("Height (m)"),
                                     tr("Planes"), tr("Time (ms)"), tr("Method")});
  table_->verticalHeader()->hide();
  table_->setEditTriggers(QAbstractItemView::NoEditTriggers);
  table_->setSelectionBehavior(QAbstractItemView::SelectRows);
  table_->horizontalHeader()->setStretchLastSection(true);
  summary_ = new QLabel(this);
  summary_->setObjectName("summary");
  left->addWidget(table_, 1);
  left->addWidget(summary_);
  poses_ = new QLabel(this);
  poses_->setObjectName("poseStatus");
  poses_->setTextInteractionFlags(Qt::TextSelectableByMouse);
  poses_->hide();
  left->addWidget(poses_);
  plot_ = new ResultsPlot(this);
  layout->addLayout(left, 3);
  layout->addWidget(plot_, 2);
  connect(table_, &QTableWidget::cellDoubleClicked, this, [this](int row, int) {
    if (row >= 0 && row < static_cast<int>(records_.size())) emit frameActivated(records_[row].index);
  });
  refresh();
}

void ResultsPanel::clear() {
  records_.clear();
  refresh();
}

void ResultsPanel::set_record(const FrameRecord& record) {
  auto it = std::find_if(records_.begin(), records_.end(),
                         [&](const FrameRecord& r) { return r.index == record.index; });
  if (it != records_.end())
    *it = record;
  else
    records_.insert(std::upper_bound(records_.begin(), records_.end(), record,
                                     [](const FrameRecord& a, const FrameRecord& b) { return a.index < b.index; }),
                    record);
  refresh();
}

void ResultsPanel::set_pose_status(const QStringList& lines) {
  poses_->setText(lines.join('\n'));
  poses_->setVisible(!lines.isEmpty());
}

QString ResultsPanel::pose_status_text() const { return poses_->text(); }

QString ResultsPanel::summary_text() const {
  const RunningStats s = running_stats(records_);
  if (s.detected == 0) return tr("%1 frame(s), no tunnel detected").arg(s.frames);
  return tr("%1/%2 detected — width %3 (%4) m, height %5 (%6) m")
      .arg(s.detected)
      .arg(s.frames)
      .arg(s.width_mean, 0, 'f', 3)
      .arg(s.width_std, 0, 'f', 3)
      .arg(s.height_mean, 0, 'f', 3)
      .arg(s.height_std, 0, 'f', 3);
}

void ResultsPanel::refresh() {
  table_->setRowCount(static_cast<int>(records_.size()));
  for (int row = 0; row < static_cast<int>(records_.size()); ++row) {
    const FrameRecord& r = records_[row];
    auto t = r.timings_ms.find("total");
    const QStringList cells = {QString::number(r.index), QString::fromStdString(r.status),
                               r.detected ? QString::number(r.width_m, 'f', 3) : "–",
                               r.detected ? QString::number(r.height_m, 'f', 3) : "–",
                               QString::number(r.planes),
                               t == r.timings_ms.end() ? "–" : QString::number(t->second, 'f', 1),
                               QString::fromUtf8(method_display_name(r.method))};
    for (int c = 0; c < cells.size(); ++c) table_->setItem(row, c, new QTableWidgetItem(cells[c]));
  }
  summary_->setText(summary_text());
  plot_->set_records(records_);
}

}  // namespace tunnelmap::ui
