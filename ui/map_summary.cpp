#include "ui/map_summary.h"

#include <QObject>

namespace tunnelmap::ui {

QString map_summary(const TunnelMap& m) {
  if (!m.detected) return QString::fromUtf8(status_name(m.status));
  const auto dim = [](bool known, double v) {
    return known ? QObject::tr("%1 m").arg(v, 0, 'f', 3) : QObject::tr("unknown");
  };
  const QString dims = QObject::tr("width %1, height %2").arg(dim(m.has_width(), m.width_m), dim(m.has_height(), m.height_m));
  return m.status == TunnelStatus::Partial ? QObject::tr("partial (%1): %2").arg(QString::fromStdString(m.reason), dims) : dims;
}

}  // namespace tunnelmap::ui
