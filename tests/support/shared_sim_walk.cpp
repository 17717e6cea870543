#include "tests/support/shared_sim_walk.h"

#include <sstream>

#include "core/sim/sim_dataset_writer.h"

namespace tunnelmap::testing {

std::unique_ptr<Dataset> shared_sim_walk(const std::string& fixture_name, const SimWalkSpec& spec, std::string& error) {
  std::ostringstream what;
  what << spec.preset << ", " << spec.frames << " frames, walk " << spec.start_x_m << "-" << spec.end_x_m << " m in "
       << spec.stops << " stops\n"
       << test_binary_stamp();
  const SharedFixture shared = shared_fixture(fixture_name, what.str(), [&spec](const std::filesystem::path& dir) {
    SimConfig c = SimConfig::from_preset(spec.preset);
    c.frames = spec.frames;
    SimWalk w;
    w.start_x_m = spec.start_x_m;
    w.end_x_m = spec.end_x_m;
    w.stops = spec.stops;
    c.walk = w;
    write_sim_dataset((dir / "walk").string(), c);
    return std::string();
  });
  error = shared.error;
  if (!shared.ok()) return nullptr;
  return std::make_unique<Dataset>(read_dataset(shared.file("walk")));
}

}  // namespace tunnelmap::testing
