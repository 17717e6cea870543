#pragma once
// The 3D scene alone rendered off-screen at any size and written as a PNG (atomically).
#include <QString>

namespace tunnelmap::ui {

class View3DWidget;

// InputError(path, problem) for a size outside 16..8192 per side or a failed render or write.
void export_view3d_png(View3DWidget* view, const QString& path, int width, int height);

}  // namespace tunnelmap::ui
