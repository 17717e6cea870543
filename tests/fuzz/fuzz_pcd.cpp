// libFuzzer target: the organised PCD reader (our header checks, then PCL). PCL reads files
// only, so each input goes through a scratch file.
#include <cstdint>
#include <cstdlib>

#include "core/io/organized_pcd.h"
#include "core/util/error.h"
#include "tests/fuzz/fuzz_util.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace tunnelmap;
  const std::string path = (fuzz::scratch_dir("pcd") / "input.pcd").string();
  fuzz::write_bytes(path, data, size);
  try {
    const DepthFrame f = read_organized_pcd(path, ReadOptions{});
    if (f.depth.size() != static_cast<std::size_t>(f.width) * f.height) std::abort();
  } catch (const InputError&) {
  }
  return 0;
}
