#include "tests/support/mapped_girder.h"

#include <string>

#include "core/io/dataset.h"
#include "core/mapping/dataset_mapping.h"
#include "core/params/parameters.h"
#include "core/pipeline/pipeline.h"
#include "core/sim/sim_dataset_writer.h"
#include "core/util/build_paths.h"
#include "tests/support/io_temp_dir.h"

namespace tunnelmap::testing {

namespace {

// The girder's dataset, written and read back, and its mapping.
struct MappedDataset {
  Dataset dataset;
  DatasetMapping mapping;
};

MappedDataset map_girder_dataset(const SimConfig& girder) {
  IoTempDir tmp;
  write_sim_dataset(tmp.file("girder"), girder);
  MappedDataset out;
  out.dataset = read_dataset(tmp.file("girder"));
  Parameters params;
  params.load_json_file(std::string(TUNNELMAP_TEST_DATA_DIR) + "/presets/field.json");
  Pipeline pipeline(params);
  out.mapping = map_dataset(out.dataset, pipeline, true);
  return out;
}

}  // namespace

StationMap map_simulated_girder(const SimConfig& girder) { return map_girder_dataset(girder).mapping.mapped.stations; }

GirderScore score_simulated_girder(const SimConfig& girder) {
  const MappedDataset m = map_girder_dataset(girder);
  return score_girder(m.mapping, m.dataset.ground_truth, m.dataset.raw["frames"]);
}

}  // namespace tunnelmap::testing
