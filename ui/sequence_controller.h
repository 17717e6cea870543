#pragma once
// Process whole sequence: every frame of the input through core's RunEngine, the same loop and
// context rule as `detect` (station map for posed frames, recent frames otherwise), results
// delivered to the table as they come, with progress and Cancel. A cancelled run keeps the
// rows that finished.
#include <QObject>
#include <functional>

#include "core/baselines/method.h"

class QAction;
class QMenu;

namespace tunnelmap::ui {

class ResultsPanel;
struct WindowContext;

class SequenceController : public QObject {
  Q_OBJECT
 public:
  SequenceController(WindowContext& ctx, ResultsPanel* results);

  QAction* add_action(QMenu* menu);  // "Process whole sequence"
  void process_sequence();           // on the background job; nothing while another job runs
  std::function<Method()> method = [] { return Method::Pgc; };

 private:
  void finish(bool cancelled, int done, int frames);

  WindowContext& ctx_;
  ResultsPanel* results_;
};

}  // namespace tunnelmap::ui
