#pragma once
// One-line description of a tunnel map for the status bar.
#include <QString>

#include "core/tunnel/tunnel_map.h"

namespace tunnelmap::ui {

// "width 0.820 m, height 1.300 m", "partial (reason): width 0.820 m, height unknown", or the
// status when nothing was detected.
QString map_summary(const TunnelMap& m);

}  // namespace tunnelmap::ui
