#include "sensors/openni/register_openni.h"

#include "core/io/frame_source.h"
#include "sensors/openni/oni_file_source.h"

namespace tunnelmap::openni2 {

void register_openni_inputs() {
  register_frame_source(".oni", [](const std::string& path, const ReadOptions& opt) -> std::unique_ptr<FrameSource> {
    return std::make_unique<OniFileSource>(path, opt);
  });
}

}  // namespace tunnelmap::openni2
