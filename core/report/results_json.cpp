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

namespace {
nlohmann::json number(const std::optional<double>& v, double unit) {
  return v ? nlohmann::json(round_to(*v, unit)) : nlohmann::json(nullptr);
}
nlohmann::json source_name(const std::optional<DimensionSource>& s) {
  return s ? nlohmann::json(dimension_source_name(*s)) : nlohmann::json(nullptr);
}
nlohmann::json wall_names(const std::vector<WallClass>& walls) {
  nlohmann::json names = nlohmann::json::array();
  for (WallClass c : walls) names.push_back(wall_class_name(c));
  return names;
}
}  // namespace

nlohmann::json detection_record_json(const DetectionRecord& d) {
  nlohmann::json j;
  j["index"] = d.index;
  j["source"] = d.source;
  j["detected"] = d.detected;
  j["status"] = d.status;
  if (!d.reason.empty()) j["reason"] = d.reason;
  j["width_m"] = number(d.width_m, 1e-5);
  j["height_m"] = number(d.height_m, 1e-5);
  j["width_source"] = source_name(d.width_source);
  j["height_source"] = source_name(d.height_source);
  if (d.error) return j;  // nothing was measured
  j["measured_walls"] = wall_names(d.measured_walls);
  j["inferred_walls"] = wall_names(d.inferred_walls);
  if (!d.parts.empty()) {  // posed frames: each section the frame saw, measured separately
    nlohmann::json parts = nlohmann::json::array();
    for (const PartRecord& p : d.parts)
      parts.push_back({{"from_m", round_to(p.from_m, 1e-4)},
                       {"to_m", round_to(p.to_m, 1e-4)},
                       {"width_m", number(p.width_m, 1e-5)},
                       {"height_m", number(p.height_m, 1e-5)}});
    j["parts"] = parts;
  }
  j["planes"] = d.planes;
  nlohmann::json walls = nlohmann::json::object();
  for (const WallRecord& w : d.walls) {
    nlohmann::json wj;
    wj["source"] = dimension_source_name(w.source);
    wj["normal"] = vec(w.normal);
    wj["offset_m"] = round_to(w.offset_m, 1e-6);
    nlohmann::json clusters = nlohmann::json::array();
    for (const ZoneCluster& c : w.clusters)
      clusters.push_back({{"offset_m", round_to(c.offset_m, 1e-6)}, {"planes", c.planes}, {"points", c.points}});
    wj["zone_clusters"] = clusters;
    walls[wall_class_name(w.wall)] = wj;
  }
  j["walls"] = walls;
  j["frame"] = "camera";
  if (d.axis)
    j["axis"] = {{"point", vec(d.axis->point)}, {"direction", vec(d.axis->direction)},
                 {"extent_m", {round_to(d.axis->extent_min_m, 1e-4), round_to(d.axis->extent_max_m, 1e-4)}}};
  j["timings_ms"] = timings_json(d.timings_ms);
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

void DetectionSummary::add(const DetectionRecord& r) {
  ++frames;
  if (const auto total = r.total_ms()) totals_.push_back(*total);
  if (!r.detected) return;
  ++detected;
  if (r.partial()) ++partial;
  // Statistics of what was measured: an inferred value is the context's or the design's.
  if (const auto w = r.measured_width_m()) widths_.push_back(*w);
  if (const auto h = r.measured_height_m()) heights_.push_back(*h);
}

void DetectionSummary::finish() {
  const auto stats = [](const std::vector<double>& values, const std::optional<double>& truth, int& count,
                        std::optional<double>& mean, std::optional<double>& sigma, std::optional<double>& error) {
    count = static_cast<int>(values.size());
    mean = sigma = error = std::nullopt;
    if (values.empty()) return;
    const MeanSigma ms = mean_sigma(values);
    mean = ms.mean;
    if (values.size() >= 2) sigma = ms.sigma;  // a sample deviation needs two values
    if (truth) error = mean_abs_error(values, *truth);
  };
  stats(widths_, gt_width_m, width_frames, width_mean_m, width_std_m, width_abs_error_mean_m);
  stats(heights_, gt_height_m, height_frames, height_mean_m, height_std_m, height_abs_error_mean_m);
  total_ms_median = totals_.empty() ? std::nullopt : std::optional<double>(median(totals_));
}

nlohmann::json summary_json(const DetectionSummary& s) {
  nlohmann::json j;
  j["frames"] = s.frames;
  j["detected"] = s.detected;
  j["partial"] = s.partial;
  j["width_frames"] = s.width_frames;
  j["height_frames"] = s.height_frames;
  j["width_mean_m"] = number(s.width_mean_m, 1e-5);
  j["width_std_m"] = number(s.width_std_m, 1e-5);
  j["height_mean_m"] = number(s.height_mean_m, 1e-5);
  j["height_std_m"] = number(s.height_std_m, 1e-5);
  j["total_ms_median"] = number(s.total_ms_median, 1e-3);
  if (s.gt_width_m && s.gt_height_m) {
    j["ground_truth"] = {{"width_m", *s.gt_width_m}, {"height_m", *s.gt_height_m}};
    j["width_abs_error_mean_m"] = number(s.width_abs_error_mean_m, 1e-5);
    j["height_abs_error_mean_m"] = number(s.height_abs_error_mean_m, 1e-5);
  }
  return j;
}

nlohmann::json detection_document_json(const DetectionDocument& d) {
  nlohmann::json doc;
  doc["tool"] = "tunnelmap";
  doc["version"] = TUNNELMAP_VERSION;
  doc["method"] = method_name(d.method);
  doc["input"] = d.input;
  doc["params"] = d.params.to_json();
  nlohmann::json frames = nlohmann::json::array();
  for (const DetectionRecord& r : d.frames) {
    nlohmann::json f = detection_record_json(r);
    if (r.method != d.method) f["method"] = method_name(r.method);
    if (!d.summaries.empty()) f["param_set"] = r.param_set;
    frames.push_back(std::move(f));
  }
  doc["frames"] = std::move(frames);
  doc["summary"] = summary_json(d.summary);
  if (!d.summaries.empty()) {
    nlohmann::json all = nlohmann::json::array();
    for (const GroupSummary& g : d.summaries) {
      nlohmann::json entry = {{"method", method_name(g.method)}, {"param_set", g.param_set}};
      entry["params"] = g.params ? g.params->to_json() : nlohmann::json(nullptr);
      entry["summary"] = summary_json(g.summary);
      all.push_back(std::move(entry));
    }
    doc["summaries"] = std::move(all);
  }
  return doc;
}

void write_detection_json(const std::string& path, const DetectionDocument& document) {
  const nlohmann::json doc = detection_document_json(document);
  write_file_atomically(path, [&](std::ostream& out) { out << doc.dump(2) << "\n"; });
}

}  // namespace tunnelmap
