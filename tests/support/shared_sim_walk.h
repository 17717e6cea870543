#pragma once
// A simulated walk written once per test build into a shared fixture (tests/support/
// shared_fixture.h) and read as a dataset: the short girder walks the fusion tests share.
#include <memory>
#include <string>

#include "core/io/dataset.h"
#include "tests/support/shared_fixture.h"

namespace tunnelmap::testing {

struct SimWalkSpec {
  std::string preset = "lab";  // simulator preset
  int frames = 8;
  double start_x_m = 0.0, end_x_m = 3.0;
  int stops = 4;
};

// The walk's dataset; null with `error` set when the fixture could not be made.
std::unique_ptr<Dataset> shared_sim_walk(const std::string& fixture_name, const SimWalkSpec& spec, std::string& error);

}  // namespace tunnelmap::testing
