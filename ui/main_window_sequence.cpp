// MainWindow, Process whole sequence: every frame of the input through core's RunEngine, the
// same loop and context rule as `detect` (station map for posed frames, recent frames
// otherwise), results delivered to the table as they come, with progress and Cancel. A
// cancelled run keeps the rows that finished.
#include <QLabel>
#include <QProgressBar>
#include <QPushButton>
#include <QtConcurrent/QtConcurrentRun>

#include "core/engine/run_engine.h"
#include "ui/main_window.h"
#include "ui/parameter_panel.h"
#include "ui/results_panel.h"

namespace tunnelmap::ui {

void MainWindow::process_sequence() {
  if (!source_ || sequence_running_) return;
  sequence_running_ = true;
  cancel_.store(false);
  const int n = static_cast<int>(source_->size());
  progress_->setRange(0, n);
  progress_->setValue(0);
  progress_->show();
  cancel_button_->show();
  auto source = source_;
  const Parameters params = params_->parameters();
  const Method method = method_;
  sequence_future_ = QtConcurrent::run([this, source, params, method, n] {
    RunSettings settings;
    settings.params = params;
    settings.method = method;
    RunEngine engine(settings, source.get());
    int done = 0;
    engine.run(*source, [&](SequenceFrame& f) {
      const int i = static_cast<int>(f.index);
      const FrameRecord rec = f.ok() ? detection_record(i, f.frame.source, f.result, method)
                                     : error_record(i, source->describe(f.index), f.error_message, method);
      const QString error = f.ok() ? QString() : QString::fromStdString(f.error_message);
      done = i + 1;
      QMetaObject::invokeMethod(this, [this, rec, error, i, params] {
        results_->set_record(rec, params);
        progress_->setValue(i + 1);
        if (!error.isEmpty()) show_error(error);
      });
      return !cancel_.load();
    });
    const bool cancelled = cancel_.load() && done < n;
    QMetaObject::invokeMethod(this, [this, cancelled, done, n] {
      progress_->hide();
      cancel_button_->hide();
      sequence_running_ = false;
      const QString summary = results_->summary_text();
      // One line per method and parameter set (never mixed); the status bar joins them.
      const QString line = QString(summary).replace('\n', "; ");
      status_label_->setText(cancelled ? tr("Sequence cancelled after %1 of %2 frame(s) — %3").arg(done).arg(n).arg(line)
                                       : line);
    });
  });
}

}  // namespace tunnelmap::ui
