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

StationMap map_simulated_girder(const SimConfig& girder) {
  IoTempDir tmp;
  write_sim_dataset(tmp.file("girder"), girder);
  const Dataset ds = read_dataset(tmp.file("girder"));
  Parameters params;
  params.load_json_file(std::string(TUNNELMAP_TEST_DATA_DIR) + "/presets/field.json");
  Pipeline pipeline(params);
  return map_dataset(ds, pipeline, true).mapped.stations;
}

}  // namespace tunnelmap::testing
