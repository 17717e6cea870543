#include "bench/field_walk.h"

#include <filesystem>

#include "core/sim/sim_dataset_writer.h"

namespace tunnelmap::bench {

Dataset field_walk_dataset(const FieldWalk& walk) {
  namespace fs = std::filesystem;
  const fs::path dir = fs::temp_directory_path() / walk.name;
  if (!fs::exists(dir / "dataset.json")) {
    SimConfig c = SimConfig::from_preset("field");
    c.frames = walk.frames;
    c.diaphragm_x_m = walk.diaphragm_x_m;
    SimWalk w;
    w.start_x_m = 0.5;
    w.end_x_m = walk.end_x_m;
    w.stops = walk.stops;
    c.walk = w;
    write_sim_dataset(dir.string(), c);
  }
  return read_dataset(dir.string());
}

}  // namespace tunnelmap::bench
