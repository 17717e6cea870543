#include "ui/report/report_format.h"

#include <QStringList>
#include <cmath>

namespace tunnelmap::report {

QString fixed(double v, int decimals) {
  if (!std::isfinite(v)) return QStringLiteral("-");
  // Avoid "-0.000" for values that round to zero.
  const double scale = std::pow(10.0, decimals);
  if (std::round(v * scale) == 0.0) v = 0.0;
  return QString::number(v, 'f', decimals);
}

QString metres(double v) { return fixed(v, 3); }

QString signed_mm(const std::optional<double>& mm) {
  if (!mm || !std::isfinite(*mm)) return QStringLiteral("-");
  const QString text = fixed(*mm, 1);
  return (*mm >= 0.05 ? QStringLiteral("+") : QString()) + text;
}

QString source_label(DimensionSource s) {
  switch (s) {
    case DimensionSource::Measured: return QStringLiteral("measured");
    case DimensionSource::Context: return QStringLiteral("context");
    case DimensionSource::Design: return QStringLiteral("design");
    case DimensionSource::Unseen: break;
  }
  return QStringLiteral("unseen");
}

QString frame_list(const std::vector<int>& frames) {
  QStringList parts;
  for (std::size_t i = 0; i < frames.size();) {
    std::size_t j = i;
    while (j + 1 < frames.size() && frames[j + 1] == frames[j] + 1) ++j;
    parts << (j == i ? QString::number(frames[i])
                     : QString::number(frames[i]) + QStringLiteral("-") + QString::number(frames[j]));
    i = j + 1;
  }
  return parts.isEmpty() ? QStringLiteral("-") : parts.join(QStringLiteral(", "));
}

QString design_text(const StationMapOptions& o) {
  if (o.design_width_m && o.design_height_m)
    return metres(*o.design_width_m) + QStringLiteral(" \u00d7 ") + metres(*o.design_height_m) +
           QStringLiteral(" m (W \u00d7 H)");
  if (o.design_width_m) return QStringLiteral("width ") + metres(*o.design_width_m) + QStringLiteral(" m, height none");
  if (o.design_height_m) return QStringLiteral("width none, height ") + metres(*o.design_height_m) + QStringLiteral(" m");
  return QStringLiteral("none");
}

bool beyond_tolerance(const std::optional<double>& dev_mm, double tolerance_mm) {
  return dev_mm && std::isfinite(*dev_mm) && std::abs(*dev_mm) > tolerance_mm;
}

std::optional<double> deviation_mm(double value_m, const std::optional<double>& design_m) {
  if (!design_m || !std::isfinite(value_m)) return std::nullopt;
  return (value_m - *design_m) * 1000.0;
}

}  // namespace tunnelmap::report
