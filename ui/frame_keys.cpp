#include "ui/frame_keys.h"

#include <QAction>
#include <QWidget>
#include <climits>

#include "ui/frame_controller.h"

namespace tunnelmap::ui {

void add_frame_keys(FrameController* frames, std::initializer_list<QWidget*> over) {
  constexpr int kPage = 10;
  const struct {
    const char* name;
    const char* text;
    QKeySequence key;
    int delta;  // INT_MIN / INT_MAX: first / last
  } keys[] = {
      {"nextFrame", "Next frame", QKeySequence(Qt::Key_Right), 1},
      {"previousFrame", "Previous frame", QKeySequence(Qt::Key_Left), -1},
      {"pageForward", "10 frames forward", QKeySequence(Qt::Key_PageDown), kPage},
      {"pageBack", "10 frames back", QKeySequence(Qt::Key_PageUp), -kPage},
      {"firstFrame", "First frame", QKeySequence(Qt::Key_Home), INT_MIN},
      {"lastFrame", "Last frame", QKeySequence(Qt::Key_End), INT_MAX},
  };
  for (const auto& k : keys) {
    auto* a = new QAction(QObject::tr(k.text), *over.begin());
    a->setObjectName(k.name);
    a->setShortcut(k.key);
    a->setShortcutContext(Qt::WidgetWithChildrenShortcut);
    const int delta = k.delta;
    QObject::connect(a, &QAction::triggered, frames, [frames, delta] {
      if (delta == INT_MIN) frames->select_frame(0);
      else if (delta == INT_MAX) frames->select_frame(frames->frame_count() - 1);
      else frames->step_frame(delta);
    });
    for (QWidget* w : over) w->addAction(a);
  }
}

}  // namespace tunnelmap::ui
