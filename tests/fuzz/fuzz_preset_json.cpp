// libFuzzer target: parameter presets as the CLI and GUI load them (file -> JSON -> range checks).
#include <cstdint>

#include "core/params/parameters.h"
#include "core/util/error.h"
#include "tests/fuzz/fuzz_util.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace tunnelmap;
  const std::string path = (fuzz::scratch_dir("preset") / "preset.json").string();
  fuzz::write_bytes(path, data, size);
  Parameters p;
  try {
    p.load_json_file(path);
  } catch (const InputError&) {
  }
  return 0;
}
