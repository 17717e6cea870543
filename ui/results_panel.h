#pragma once
// Results panel: one table row per processed frame (frame number from 1 as on the timeline,
// status, width, height, planes, time, method, parameter set), the mean(σ) of width and height
// over detected frames (paper Table 1) — one summary line per method and parameter set, never
// mixed, with the error against ground truth when known — and a plot. The selected row and the plot's marker follow the
// shown frame (set_current); clicking a row or the plot asks for that frame (frameActivated).
#include <QWidget>
#include <optional>
#include <vector>

#include "core/params/parameters.h"

#include "ui/frame_record.h"
#include "ui/results_plot.h"

class QLabel;
class QTableWidget;

namespace tunnelmap::ui {

class ResultsPanel : public QWidget {
  Q_OBJECT
 public:
  explicit ResultsPanel(QWidget* parent = nullptr);

  void clear();
  // Adds or replaces the row of record.index; `params` made it (numbered #1, #2, … per input).
  void set_record(FrameRecord record, const Parameters& params);
  void set_ground_truth(std::optional<double> width_m, std::optional<double> height_m);
  const std::vector<FrameRecord>& records() const { return records_; }
  // The parameters of set `k` (FrameRecord::param_set, from 1); empty when unknown.
  std::optional<Parameters> parameter_set(int k) const {
    return k >= 1 && k <= static_cast<int>(param_sets_.size()) ? std::optional<Parameters>(param_sets_[k - 1])
                                                                : std::nullopt;
  }
  QString summary_text() const;  // one line per (method, parameter set), in order of appearance
  // Fusion: one line per arm pose ("ok" or "move and rescan: …"); empty hides the list.
  void set_pose_status(const QStringList& lines);
  QString pose_status_text() const;
  void set_frame_count(int count);
  void set_current(int index);  // 0-based; selects its row (if any) without frameActivated
  int current() const { return current_; }
  int selected_frame() const;   // the selected row's frame index, -1 when none
  QTableWidget* table() const { return table_; }
  ResultsPlot* plot() const { return plot_; }

 signals:
  void frameActivated(int index);

 private:
  void refresh();

  void select_current_row();

  std::vector<FrameRecord> records_;  // sorted by index
  std::vector<Parameters> param_sets_;  // param_set k is param_sets_[k - 1]
  std::optional<double> gt_width_m_, gt_height_m_;
  int current_ = -1;
  QTableWidget* table_;
  QLabel* summary_;
  QLabel* poses_;
  ResultsPlot* plot_;
};

}  // namespace tunnelmap::ui
