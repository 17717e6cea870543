#include "ui/sequence_controller.h"

#include <QAction>
#include <QMainWindow>
#include <QMenu>

#include "core/engine/run_engine.h"
#include "ui/background_job.h"
#include "ui/parameter_panel.h"
#include "ui/results_panel.h"
#include "ui/window_context.h"
#include "ui/window_status.h"

namespace tunnelmap::ui {

SequenceController::SequenceController(WindowContext& ctx, ResultsPanel* results)
    : QObject(ctx.window), ctx_(ctx), results_(results) {}

QAction* SequenceController::add_action(QMenu* menu) {
  return menu->addAction(tr("Process whole &sequence"), this, &SequenceController::process_sequence);
}

void SequenceController::process_sequence() {
  if (!ctx_.source || ctx_.job->running()) return;
  const int n = static_cast<int>(ctx_.source->size());
  auto source = ctx_.source;
  const Parameters params = ctx_.params->parameters();
  const Method m = method();
  const std::atomic<bool>& cancel = ctx_.job->cancel_flag();
  ctx_.status->show_progress(n);
  ctx_.job->start([this, source, params, m, n, &cancel] {
    RunSettings settings;
    settings.params = params;
    settings.method = m;
    RunEngine engine(settings, source.get());
    int done = 0;
    engine.run(*source, [&](SequenceFrame& f) {
      const int i = static_cast<int>(f.index);
      const FrameRecord rec = f.ok() ? detection_record(i, f.frame.source, f.result, m)
                                     : error_record(i, source->describe(f.index), f.error_message, m);
      const QString error = f.ok() ? QString() : QString::fromStdString(f.error_message);
      done = i + 1;
      QMetaObject::invokeMethod(this, [this, rec, error, i, params] {
        results_->set_record(rec, params);
        ctx_.status->set_progress(i + 1);
        if (!error.isEmpty()) ctx_.status->show_error(error);
      });
      return !cancel.load();
    });
    const bool cancelled = cancel.load() && done < n;
    QMetaObject::invokeMethod(this, [this, cancelled, done, n] { finish(cancelled, done, n); });
  });
}

void SequenceController::finish(bool cancelled, int done, int frames) {
  ctx_.status->hide_progress();
  ctx_.job->finished();
  // One line per method and parameter set (never mixed); the status bar joins them.
  const QString line = results_->summary_text().replace('\n', "; ");
  ctx_.status->set_text(cancelled ? tr("Sequence cancelled after %1 of %2 frame(s) — %3").arg(done).arg(frames).arg(line)
                                  : line);
}

}  // namespace tunnelmap::ui
