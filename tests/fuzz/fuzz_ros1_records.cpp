// libFuzzer target: the ROS 1 bag reader (core/recordings/ros1_recording) on whole files: the
// bag header, records, chunks (none, bz2, lz4), connections, chunk infos and index data, and
// the scan when the index is cut.
#include "tests/fuzz/fuzz_recording.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  tunnelmap::fuzz::read_recording_file(data, size, "ros1", ".bag");
  return 0;
}
