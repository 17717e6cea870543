// MainWindow, Process whole sequence: every frame of the input through core's SequenceRunner
// (frames detected in parallel, the tunnel context of earlier frames applied in frame order, so
// the rows equal a serial run), results delivered to the table as they come, with progress and
// Cancel. A cancelled run keeps the rows that finished.
#include <QLabel>
#include <QProgressBar>
#include <QPushButton>
#include <QtConcurrent/QtConcurrentRun>

#include "core/baselines/method_runner.h"
#include "core/pipeline/sequence_runner.h"
#include "core/tunnel/tunnel_detector.h"
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
    MethodRunner runner(method, params);
    if (const Dataset* ds = source->dataset()) runner.set_world_up(ds->up);
    TunnelContext context;
    SequenceRunner::Work work;
    SequenceRunner::Ordered in_order;
    if (method == Method::Qhull) {
      // Qhull checks the context inside its fit: it runs in frame order.
      in_order = [&runner, &context](SequenceFrame& f) { runner.run(f.frame, f.result, &context); };
    } else {
      work = [runner](const DepthFrame& frame, FrameResult& r) { runner.run(frame, r, nullptr); };
      in_order = [&context, opt = tunnel_options(params)](SequenceFrame& f) {
        apply_tunnel_context(f.result.map, opt, context);
        if (f.result.map.detected) context.accept(f.result.map);
      };
    }
    SequenceOptions options;
    options.serial_loading = !source->dataset();  // recordings have a read position
    SequenceRunner sequence(std::move(work), std::move(in_order), options);
    int done = 0;
    sequence.run(*source, [&](SequenceFrame& f) {
      const int i = static_cast<int>(f.index);
      FrameRecord rec;
      QString error;
      if (f.ok()) {
        rec = FrameRecord::from(i, f.result, method, f.frame.source);
      } else {
        rec.index = i;
        rec.method = method;
        rec.status = "error";
        error = QString::fromStdString(f.error_message);
      }
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
