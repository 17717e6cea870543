// libFuzzer target: the structural check of OpenNI recordings (core/io/oni_container) and the
// frame payload checks under it (core/io/oni_payload). An input starting with the NI10 marker
// is checked as a whole recording; any other input is checked as one frame payload, its first
// byte choosing the codec and the frame's bytes per pixel, so the decoders are reached directly.
#include <cstdint>
#include <cstdlib>
#include <cstring>

#include "core/io/input_options.h"
#include "core/io/oni_container.h"
#include "core/io/oni_payload.h"
#include "core/util/error.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace tunnelmap;
  if (size >= 4 && std::memcmp(data, "NI10", 4) == 0) {
    try {
      oni::check_recording(data, size, "fuzz.oni", input_keys::max_image_pixels.default_value);
    } catch (const InputError& e) {
      if (e.file() != "fuzz.oni" || std::strchr(e.what(), '\n') != nullptr) std::abort();  // one line naming the file
    }
    return 0;
  }
  if (size < 1) return 0;
  static const oni::Codec codecs[] = {oni::Codec::Uncompressed, oni::Codec::Depth16z, oni::Codec::Depth16zTable,
                                      oni::Codec::Jpeg};
  const oni::FrameShape shape{8, 6, (data[0] & 0x04) ? 3u : 2u};
  oni::payload_problem(codecs[data[0] & 0x03], data + 1, size - 1, shape);
  return 0;
}
