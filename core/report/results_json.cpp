#include "core/report/results_json.h"

#include "core/report/json_numbers.h"
#include "core/report/statistics.h"
#include "core/util/atomic_file.h"

#include <cmath>

namespace tunnelmap {

namespace {
const auto& vec = json_vec;

nlohmann::json timings_json(const StageTimings& t) {
  nlohmann::json j = nlohmann::json::object();
  for (const auto& [k, v] : t) j[k] = round_to(v, 1e-3);
  return j;
}

}  // namespace

nlohmann::json detection_frame_json(std::size_t index, const std::string& source,
                                    const FrameResult& r) {
  const TunnelMap& m = r.map;
  nlohmann::json j;
  j["index"] = index;
  j["source"] = source;
  j["detected"] = m.detected;
  j["status"] = status_name(m.status);
  if (!m.reason.empty()) j["reason"] = m.reason;
  j["width_m"] = m.has_width() ? nlohmann::json(round_to(m.width_m, 1e-5)) : nlohmann::json(nullptr);
  j["height_m"] = m.has_height() ? nlohmann::json(round_to(m.height_m, 1e-5)) : nlohmann::json(nullptr);
  const auto source_name = [&](DimensionSource s) {
    return m.detected && s != DimensionSource::Unseen ? nlohmann::json(dimension_source_name(s))
                                                      : nlohmann::json(nullptr);
  };
  j["width_source"] = source_name(m.width_source);
  j["height_source"] = source_name(m.height_source);
  nlohmann::json measured = nlohmann::json::array(), inferred = nlohmann::json::array();
  for (int c = 0; c < 4; ++c) {
    const Wall& w = m.walls[c];
    if (!m.detected || !w.found) continue;
    (w.source == DimensionSource::Measured ? measured : inferred)
        .push_back(wall_class_name(static_cast<WallClass>(c)));
  }
  j["measured_walls"] = measured;
  j["inferred_walls"] = inferred;
  if (!m.parts.empty()) {  // posed frames: each section the frame saw, measured separately
    nlohmann::json parts = nlohmann::json::array();
    const auto num = [](double v) {
      return std::isfinite(v) ? nlohmann::json(round_to(v, 1e-5)) : nlohmann::json(nullptr);
    };
    for (const TunnelPart& p : m.parts)
      parts.push_back({{"from_m", round_to(p.from_m, 1e-4)},
                       {"to_m", round_to(p.to_m, 1e-4)},
                       {"width_m", num(p.width_m)},
                       {"height_m", num(p.height_m)}});
    j["parts"] = parts;
  }
  j["planes"] = r.planes.planes.size();
  nlohmann::json walls = nlohmann::json::object();
  for (int c = 0; c < 4; ++c) {
    const Wall& w = m.walls[c];
    if (!w.found) continue;
    nlohmann::json wj;
    wj["source"] = dimension_source_name(w.source);
    wj["normal"] = vec(w.normal);
    wj["offset_m"] = round_to(w.offset_m, 1e-6);
    nlohmann::json clusters = nlohmann::json::array();
    for (const ZoneCluster& c : w.clusters)
      clusters.push_back({{"offset_m", round_to(c.offset_m, 1e-6)}, {"planes", c.planes}, {"points", c.points}});
    wj["zone_clusters"] = clusters;
    walls[wall_class_name(static_cast<WallClass>(c))] = wj;
  }
  j["walls"] = walls;
  j["frame"] = "camera";
  if (m.detected) {
    j["axis"] = {{"point", vec(m.axis_point)}, {"direction", vec(m.axis_dir)},
                 {"extent_m", {round_to(m.extent_min_m, 1e-4), round_to(m.extent_max_m, 1e-4)}}};
  }
  j["timings_ms"] = timings_json(r.timings_ms);
  return j;
}

nlohmann::json planes_frame_json(std::size_t index, const std::string& source,
                                 const PlaneSegments& planes, const StageTimings& timings_ms) {
  nlohmann::json j;
  j["index"] = index;
  j["source"] = source;
  nlohmann::json list = nlohmann::json::array();
  for (const PlaneSegment& p : planes.planes) {
    list.push_back({{"id", p.id},
                    {"normal", vec(p.normal)},
                    {"centroid", vec(p.centroid)},
                    {"offset_m", round_to(p.offset_m, 1e-6)},
                    {"points", p.points},
                    {"area_m2", round_to(p.area_m2, 1e-6)},
                    {"rms_m", round_to(p.rms_m, 1e-6)},
                    {"contour_vertices", p.contour.size()},
                    {"edge_on", p.edge_on}});
  }
  j["planes"] = list;
  j["timings_ms"] = timings_json(timings_ms);
  return j;
}

SummaryEntry summary_entry(const FrameResult& r) {
  SummaryEntry e;
  const auto total = r.timings_ms.find("total");
  e.total_ms = total != r.timings_ms.end() ? total->second : 0.0;
  e.detected = r.map.detected;
  e.partial = r.map.detected && r.map.status == TunnelStatus::Partial;
  // Statistics of what was measured: an inferred value is the context's or the design's.
  if (r.map.width_measured()) e.width_m = r.map.width_m;
  if (r.map.height_measured()) e.height_m = r.map.height_m;
  return e;
}

void DetectionSummary::add(const SummaryEntry& e) {
  ++frames;
  totals_.push_back(e.total_ms);
  if (!e.detected) return;
  ++detected;
  if (e.partial) ++partial;
  if (e.width_m) widths_.push_back(*e.width_m);
  if (e.height_m) heights_.push_back(*e.height_m);
}

void DetectionSummary::finish() {
  const MeanSigma w = mean_sigma(widths_), h = mean_sigma(heights_);
  width_mean_m = w.mean;
  width_std_m = w.sigma;
  height_mean_m = h.mean;
  height_std_m = h.sigma;
  total_ms_median = median(totals_);
  width_abs_error_mean_m = gt_width_m ? mean_abs_error(widths_, *gt_width_m) : 0.0;
  height_abs_error_mean_m = gt_height_m ? mean_abs_error(heights_, *gt_height_m) : 0.0;
}

nlohmann::json DetectionSummary::to_json() const {
  nlohmann::json j;
  j["frames"] = frames;
  j["detected"] = detected;
  j["partial"] = partial;
  j["width_mean_m"] = round_to(width_mean_m, 1e-5);
  j["width_std_m"] = round_to(width_std_m, 1e-5);
  j["height_mean_m"] = round_to(height_mean_m, 1e-5);
  j["height_std_m"] = round_to(height_std_m, 1e-5);
  j["total_ms_median"] = round_to(total_ms_median, 1e-3);
  if (gt_width_m && gt_height_m) {
    j["ground_truth"] = {{"width_m", *gt_width_m}, {"height_m", *gt_height_m}};
    j["width_abs_error_mean_m"] = round_to(width_abs_error_mean_m, 1e-5);
    j["height_abs_error_mean_m"] = round_to(height_abs_error_mean_m, 1e-5);
  }
  return j;
}

nlohmann::json detection_document(const nlohmann::json& params, const nlohmann::json& frames,
                                  const DetectionSummary& summary, const std::string& input) {
  nlohmann::json doc;
  doc["tool"] = "tunnelmap";
  doc["version"] = TUNNELMAP_VERSION;
  doc["method"] = "pgc";
  doc["input"] = input;
  doc["params"] = params;
  doc["frames"] = frames;
  doc["summary"] = summary.to_json();
  return doc;
}

void write_detection_json(const std::string& path, const nlohmann::json& document) {
  write_file_atomically(path, [&](std::ostream& out) { out << document.dump(2) << "\n"; });
}

}  // namespace tunnelmap
