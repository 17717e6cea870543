// libFuzzer target: the MCAP reader (core/recordings/mcap_recording) on whole files: magic,
// records, chunks (none, zstd, lz4), the summary section and its indexes, and the scan when
// they are broken. Every message delivered must lie inside the file's data and be counted.
#include <cstdint>
#include <cstdlib>
#include <map>

#include "core/recordings/recording.h"
#include "core/util/error.h"
#include "tests/fuzz/fuzz_util.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace tunnelmap;
  const auto path = fuzz::scratch_dir("mcap") / "input.mcap";
  fuzz::write_bytes(path, data, size);
  try {
    const auto rec = recordings::open_recording(path.string());
    std::uint64_t read = 0;
    rec->read_messages({}, [&](const recordings::MessageView& m) {
      if (m.size && !m.data) std::abort();
      if (!rec->summary().topic(m.topic)) std::abort();  // every message's topic is listed
      ++read;
      return read < 100000;
    });
  } catch (const InputError&) {
  }
  return 0;
}
