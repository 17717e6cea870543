#include "core/report/detection_record.h"

#include <cmath>

namespace tunnelmap {

namespace {

std::optional<double> finite(double v) { return std::isfinite(v) ? std::optional<double>(v) : std::nullopt; }

std::optional<DimensionSource> known_source(const TunnelMap& m, DimensionSource s) {
  return m.detected && s != DimensionSource::Unseen ? std::optional<DimensionSource>(s) : std::nullopt;
}

}  // namespace

std::optional<double> DetectionRecord::measured_width_m() const {
  return width_source == DimensionSource::Measured ? width_m : std::nullopt;
}

std::optional<double> DetectionRecord::measured_height_m() const {
  return height_source == DimensionSource::Measured ? height_m : std::nullopt;
}

std::optional<double> DetectionRecord::total_ms() const {
  const auto it = timings_ms.find("total");
  return it != timings_ms.end() ? std::optional<double>(it->second) : std::nullopt;
}

DetectionRecord detection_record(int index, const std::string& source, const FrameResult& r, Method method) {
  const TunnelMap& m = r.map;
  DetectionRecord d;
  d.index = index;
  d.source = source;
  d.method = method;
  d.detected = m.detected;
  d.status = status_name(m.status);
  d.reason = m.reason;
  if (m.has_width()) d.width_m = m.width_m;
  if (m.has_height()) d.height_m = m.height_m;
  d.width_source = known_source(m, m.width_source);
  d.height_source = known_source(m, m.height_source);
  for (int c = 0; c < 4; ++c) {
    const Wall& w = m.walls[c];
    if (!w.found) continue;
    const WallClass cls = static_cast<WallClass>(c);
    if (m.detected) (w.source == DimensionSource::Measured ? d.measured_walls : d.inferred_walls).push_back(cls);
    d.walls.push_back({cls, w.source, w.normal, w.offset_m, w.clusters});
  }
  for (const TunnelPart& p : m.parts) d.parts.push_back({p.from_m, p.to_m, finite(p.width_m), finite(p.height_m)});
  d.planes = r.planes.planes.size();
  if (m.detected) d.axis = AxisRecord{m.axis_point, m.axis_dir, m.extent_min_m, m.extent_max_m};
  d.timings_ms = r.timings_ms;
  return d;
}

DetectionRecord error_record(int index, const std::string& source, const std::string& message, Method method) {
  DetectionRecord d;
  d.index = index;
  d.source = source;
  d.method = method;
  d.error = true;
  d.status = "error";
  d.reason = message;
  return d;
}

}  // namespace tunnelmap
