#pragma once
// A simulated field girder walked along x with exact poses, written once to $TMPDIR/<name>
// (kept between bench runs) and read from there.
#include <string>
#include <vector>

#include "core/io/dataset.h"

namespace tunnelmap::bench {

struct FieldWalk {
  const char* name;        // folder under the temporary directory
  int frames;              // spread over the stops
  int stops;
  double end_x_m;          // from 0.5 m
  std::vector<double> diaphragm_x_m;
};

Dataset field_walk_dataset(const FieldWalk& walk);

}  // namespace tunnelmap::bench
