#pragma once
// Results panel: one table row per processed frame (status, width, height, planes, time), the
// running mean(σ) of width and height over detected frames (paper Table 1), and a plot.
#include <QWidget>
#include <vector>

#include "ui/frame_record.h"

class QLabel;
class QTableWidget;

namespace tunnelmap::ui {

class ResultsPlot;

class ResultsPanel : public QWidget {
  Q_OBJECT
 public:
  explicit ResultsPanel(QWidget* parent = nullptr);

  void clear();
  void set_record(const FrameRecord& record);  // adds or replaces the row of record.index
  const std::vector<FrameRecord>& records() const { return records_; }
  QString summary_text() const;
  // Fusion: one line per arm pose ("ok" or "move and rescan: …"); empty hides the list.
  void set_pose_status(const QStringList& lines);
  QString pose_status_text() const;

 signals:
  void frameActivated(int index);

 private:
  void refresh();

  std::vector<FrameRecord> records_;  // sorted by index
  QTableWidget* table_;
  QLabel* summary_;
  QLabel* poses_;
  ResultsPlot* plot_;
};

}  // namespace tunnelmap::ui
