// libFuzzer target: the ROS 1 bag reader (core/recordings/ros1_recording) on whole files: the
// bag header, records, chunks (none, bz2, lz4), connections, chunk infos and index data, and
// the scan when the index is cut. Every message delivered must be on a listed topic.
#include <cstdint>
#include <cstdlib>
#include <map>

#include "core/recordings/recording.h"
#include "core/util/error.h"
#include "tests/fuzz/fuzz_util.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace tunnelmap;
  const auto path = fuzz::scratch_dir("ros1") / "input.bag";
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
