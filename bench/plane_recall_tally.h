#pragma once
// Counters of tunnelmap_plane_recall for one preset x grid step, and the markdown report over
// all of them. The headline is the docs/recall.md definition (SegmentationOptions::by_size);
// the incidence and normal-pixel views only explain where the misses are.
#include <map>
#include <string>
#include <vector>

#include "core/evaluation/segmentation_metrics.h"

namespace tunnelmap::recall {

// Incidence bands of the miss breakdown: <= 60, 60-80, 80-85, > 85 degrees.
constexpr int kIncidenceBands = 4;
int incidence_band(double incidence_deg);
const char* incidence_band_label(int band);

struct Count {
  long counted = 0, found = 0;
  long missed() const { return counted - found; }
  double recall() const { return counted ? double(found) / counted : 0.0; }
  void add(bool was_found) { ++counted, found += was_found ? 1 : 0; }
};

struct RunTally {
  std::string preset;
  int grid_step = 1;
  int min_points = 0;  // grow.min_points of the run: the normal-pixel view's threshold
  long frames = 0;
  SegmentationScore score;          // headline: the docs/recall.md definition
  Count bands[kIncidenceBands];     // counted surfaces by incidence band
  std::map<std::string, Count> by_name;  // counted surfaces by simulator surface name
  Count up_to_80_deg;               // supplementary: only surfaces seen at <= 80 degrees
  Count with_normals;               // supplementary: only surfaces with >= min_points normals

  // One true surface of one frame; `normal_pixels` = its pixels carrying a normal.
  void add_surface(const SurfaceDetail& d, const std::string& name, long normal_pixels);
};

// The whole report; `settings` is one line describing the run (seeds, stride, --set ...).
std::string markdown_report(const std::vector<RunTally>& runs, const std::string& settings);

}  // namespace tunnelmap::recall
