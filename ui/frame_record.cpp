#include "ui/frame_record.h"

#include "core/report/json_numbers.h"

#include <algorithm>

namespace tunnelmap::ui {

FrameRecord FrameRecord::from(int index, const FrameResult& r, Method method, const std::string& source) {
  FrameRecord f;
  f.index = index;
  f.method = method;
  // A partial map with a dimension unknown has no width/height to tabulate or average.
  f.detected = r.map.has_width() && r.map.has_height();
  f.status = status_name(r.map.status);  // the stable name, as in CLI output
  f.width_m = r.map.width_m;
  f.height_m = r.map.height_m;
  f.planes = static_cast<int>(r.planes.planes.size());
  f.timings_ms = r.timings_ms;
  f.result = detection_frame_json(static_cast<std::size_t>(index), source, r);
  f.summary = summary_entry(r);
  return f;
}

DetectionSummary summary_of(const std::vector<FrameRecord>& records, std::optional<double> gt_width_m,
                            std::optional<double> gt_height_m) {
  DetectionSummary summary;
  summary.gt_width_m = gt_width_m;
  summary.gt_height_m = gt_height_m;
  for (const FrameRecord& r : records) summary.add(r.summary);
  summary.finish();
  return summary;
}

namespace {

struct Group {
  Method method;
  int set;
  bool operator==(const Group& o) const { return method == o.method && set == o.set; }
};

DetectionSummary group_summary(const std::vector<FrameRecord>& records, const Group& g, const Dataset* dataset) {
  DetectionSummary summary;
  if (dataset) {
    summary.gt_width_m = dataset->gt_width_m;
    summary.gt_height_m = dataset->gt_height_m;
  }
  for (const FrameRecord& r : records) {
    if (!(Group{r.method, r.param_set} == g)) continue;
    // The row's timings: after a partial re-run they are the whole pipeline's (main_window.cpp).
    SummaryEntry entry = r.summary;
    const auto total = r.timings_ms.find("total");
    entry.total_ms = total != r.timings_ms.end() ? total->second : 0.0;
    summary.add(entry);
  }
  summary.finish();
  return summary;
}

}  // namespace

nlohmann::json results_document(const std::vector<FrameRecord>& records, const nlohmann::json& params,
                                const std::string& input, const Dataset* dataset,
                                const std::function<nlohmann::json(int)>& set_params) {
  std::vector<Group> groups;
  for (const FrameRecord& r : records)
    if (std::find(groups.begin(), groups.end(), Group{r.method, r.param_set}) == groups.end())
      groups.push_back({r.method, r.param_set});
  Group main = groups.empty() ? Group{Method::Pgc, 0} : groups.front();
  if (set_params)
    for (const Group& g : groups)
      if (set_params(g.set) == params) {
        main = g;
        break;
      }
  nlohmann::json frames = nlohmann::json::array();
  for (const FrameRecord& r : records) {
    nlohmann::json f = r.result;
    if (f.is_null()) {  // a frame that could not be read: no result, only why
      f = {{"index", r.index}, {"detected", false}, {"status", r.status}};
    } else {
      nlohmann::json timings = nlohmann::json::object();
      for (const auto& [stage, ms] : r.timings_ms) timings[stage] = round_to(ms, 1e-3);
      f["timings_ms"] = timings;
    }
    if (r.method != main.method) f["method"] = method_name(r.method);
    if (groups.size() > 1) f["param_set"] = r.param_set;
    frames.push_back(std::move(f));
  }
  nlohmann::json main_params = params;
  if (set_params && main.set > 0 && !set_params(main.set).is_null()) main_params = set_params(main.set);
  nlohmann::json doc = detection_document(main_params, frames, group_summary(records, main, dataset), input);
  doc["method"] = method_name(main.method);
  if (groups.size() > 1) {
    nlohmann::json all = nlohmann::json::array();
    for (const Group& g : groups) {
      nlohmann::json entry = {{"method", method_name(g.method)}, {"param_set", g.set}};
      if (set_params) entry["params"] = set_params(g.set);
      entry["summary"] = group_summary(records, g, dataset).to_json();
      all.push_back(std::move(entry));
    }
    doc["summaries"] = all;
  }
  return doc;
}

}  // namespace tunnelmap::ui
