// libFuzzer target: the MCAP reader (core/recordings/mcap_recording) on whole files: magic,
// records, chunks (none, zstd, lz4), the summary section and its indexes, and the scan when
// they are broken.
#include "tests/fuzz/fuzz_recording.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  tunnelmap::fuzz::read_recording_file(data, size, "mcap", ".mcap");
  return 0;
}
