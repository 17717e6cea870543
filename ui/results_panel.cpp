#include "ui/results_panel.h"

#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QSignalBlocker>
#include <QTableWidget>
#include <QVBoxLayout>
#include <algorithm>
#include <cmath>


namespace tunnelmap::ui {

ResultsPanel::ResultsPanel(QWidget* parent) : QWidget(parent) {
  auto* layout = new QHBoxLayout(this);
  auto* left = new QVBoxLayout;
  table_ = new QTableWidget(0, 8, this);
  table_->setHorizontalHeaderLabels({tr("Frame"), tr("Status"), tr("Width (m)"), tr("Height (m)"),
                                     tr("Planes"), tr("Time (ms)"), tr("Method"), tr("Params")});
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
  table_->setSelectionMode(QAbstractItemView::SingleSelection);
  // A click on a row shows its frame (only user changes: set_current blocks the signal).
  connect(table_, &QTableWidget::currentCellChanged, this, [this](int row, int, int, int) {
    if (row >= 0 && row < static_cast<int>(records_.size()) && records_[row].index != current_)
      emit frameActivated(records_[row].index);
  });
  connect(plot_, &ResultsPlot::frameClicked, this, &ResultsPanel::frameActivated);
  refresh();
}

void ResultsPanel::clear() {
  records_.clear();
  param_sets_.clear();
  current_ = -1;
  plot_->set_current(-1);
  refresh();
}

void ResultsPanel::set_frame_count(int count) { plot_->set_frame_count(count); }

void ResultsPanel::set_current(int index) {
  current_ = index;
  plot_->set_current(index);
  select_current_row();
}

int ResultsPanel::selected_frame() const {
  const int row = table_->currentRow();
  return row >= 0 && row < static_cast<int>(records_.size()) && table_->selectionModel()->isRowSelected(row, QModelIndex())
             ? records_[row].index
             : -1;
}

void ResultsPanel::select_current_row() {
  const QSignalBlocker block(table_);
  const auto it = std::find_if(records_.begin(), records_.end(), [&](const FrameRecord& r) { return r.index == current_; });
  if (it == records_.end()) {
    table_->clearSelection();
    table_->setCurrentCell(-1, -1);
    return;
  }
  const int row = static_cast<int>(it - records_.begin());
  table_->setCurrentCell(row, 0);
  table_->selectRow(row);
  table_->scrollToItem(table_->item(row, 0));
}

void ResultsPanel::set_ground_truth(std::optional<double> width_m, std::optional<double> height_m) {
  gt_width_m_ = width_m;
  gt_height_m_ = height_m;
  refresh();
}

void ResultsPanel::set_record(FrameRecord record, const Parameters& params) {
  auto set = std::find(param_sets_.begin(), param_sets_.end(), params);
  if (set == param_sets_.end()) set = param_sets_.insert(param_sets_.end(), params);
  record.param_set = static_cast<int>(set - param_sets_.begin()) + 1;
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
  if (records_.empty()) return tr("no frame processed");
  // Groups in order of first appearance: a mean over two methods or parameter sets means nothing.
  std::vector<std::pair<Method, int>> groups;
  for (const auto& r : records_)
    if (std::find(groups.begin(), groups.end(), std::make_pair(r.method, r.param_set)) == groups.end())
      groups.emplace_back(r.method, r.param_set);
  QStringList lines;
  for (const auto& [method, set] : groups) {
    std::vector<FrameRecord> group;
    for (const auto& r : records_)
      if (r.method == method && r.param_set == set) group.push_back(r);
    const DetectionSummary s = summary_of(group, gt_width_m_, gt_height_m_);
    QString line = tr("%1, params #%2: ").arg(QString::fromUtf8(method_display_name(method))).arg(set);
    if (s.detected == 0) {
      lines << line + tr("%1 frame(s), no tunnel detected").arg(s.frames);
      continue;
    }
    // As `detect` prints it: means over the measured widths and heights only, each with the
    // number of frames it covers; unknown when no frame measured it.
    line += tr("%1/%2 detected").arg(s.detected).arg(s.frames);
    const auto stat = [this](const QString& name, int n, const std::optional<double>& mean,
                             const std::optional<double>& sd) {
      if (!mean) return tr(" — %1 unknown (measured in no frame)").arg(name);
      return tr(" — %1 %2 (%3) m over %4 frame(s)")
          .arg(name)
          .arg(*mean, 0, 'f', 3)
          .arg(sd ? QString::number(*sd, 'f', 3) : QString("–"))
          .arg(n);
    };
    line += stat(tr("width"), s.width_frames, s.width_mean_m, s.width_std_m);
    line += stat(tr("height"), s.height_frames, s.height_mean_m, s.height_std_m);
    if (s.width_abs_error_mean_m || s.height_abs_error_mean_m) {
      const auto mm = [](const std::optional<double>& v) { return v ? QString::number(*v * 1000, 'f', 1) : QString("–"); };
      line += tr(", mean abs error %1 / %2 mm vs ground truth").arg(mm(s.width_abs_error_mean_m)).arg(mm(s.height_abs_error_mean_m));
    }
    lines << line;
  }
  return lines.join('\n');
}

void ResultsPanel::refresh() {
  const QSignalBlocker block(table_);  // rebuilding rows is no user selection
  table_->setRowCount(static_cast<int>(records_.size()));
  for (int row = 0; row < static_cast<int>(records_.size()); ++row) {
    const FrameRecord& r = records_[row];
    const auto total = r.total_ms();
    // Frames numbered from 1, as on the timeline; a known value with where it came from unless
    // measured ("0.820 design"); unknown "–".
    const auto value = [](const std::optional<double>& v, const std::optional<DimensionSource>& source) {
      if (!v) return QString("–");
      QString text = QString::number(*v, 'f', 3);
      if (source && *source != DimensionSource::Measured) text += QString(" ") + dimension_source_name(*source);
      return text;
    };
    const QStringList cells = {QString::number(r.index + 1), QString::fromStdString(r.status),
                               value(r.width_m, r.width_source), value(r.height_m, r.height_source),
                               r.error ? "–" : QString::number(r.planes),
                               total ? QString::number(*total, 'f', 1) : "–",
                               QString::fromUtf8(method_display_name(r.method)),
                               r.param_set > 0 ? QString("#%1").arg(r.param_set) : "–"};
    for (int c = 0; c < cells.size(); ++c) table_->setItem(row, c, new QTableWidgetItem(cells[c]));
  }
  select_current_row();
  summary_->setText(summary_text());
  plot_->set_records(records_);
}

}  // namespace tunnelmap::ui
