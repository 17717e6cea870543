#include "ui/frame_record.h"

#include <algorithm>

namespace tunnelmap::ui {

DetectionSummary summary_of(const std::vector<FrameRecord>& records, std::optional<double> gt_width_m,
                            std::optional<double> gt_height_m) {
  DetectionSummary summary;
  summary.gt_width_m = gt_width_m;
  summary.gt_height_m = gt_height_m;
  for (const FrameRecord& r : records) summary.add(r);
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
  std::vector<FrameRecord> rows;
  for (const FrameRecord& r : records)
    if (Group{r.method, r.param_set} == g) rows.push_back(r);
  return summary_of(rows, dataset ? dataset->gt_width_m : std::nullopt, dataset ? dataset->gt_height_m : std::nullopt);
}

}  // namespace

DetectionDocument results_document(const std::vector<FrameRecord>& records, const Parameters& params,
                                   const std::string& input, const Dataset* dataset,
                                   const std::function<std::optional<Parameters>(int)>& set_params) {
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
  DetectionDocument doc;
  doc.method = main.method;
  doc.input = input;
  doc.params = params;
  if (set_params && main.set > 0)
    if (const auto p = set_params(main.set)) doc.params = *p;
  doc.frames = records;
  doc.summary = group_summary(records, main, dataset);
  if (groups.size() > 1)
    for (const Group& g : groups)
      doc.summaries.push_back({g.method, g.set, set_params ? set_params(g.set) : std::nullopt,
                               group_summary(records, g, dataset)});
  return doc;
}

}  // namespace tunnelmap::ui
