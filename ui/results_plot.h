#pragma once
// A small line plot of width and height (metres) per frame.
#include <QWidget>
#include <vector>

#include "ui/frame_record.h"

namespace tunnelmap::ui {

class ResultsPlot : public QWidget {
  Q_OBJECT
 public:
  explicit ResultsPlot(QWidget* parent = nullptr);
  void set_records(const std::vector<FrameRecord>& records);

 protected:
  void paintEvent(QPaintEvent*) override;

 private:
  std::vector<FrameRecord> records_;
};

}  // namespace tunnelmap::ui
