#include "sensors/openni/device_frame_source.h"

#include "core/util/error.h"

namespace tunnelmap::openni2 {

DeviceFrameSource::DeviceFrameSource(const std::string& uri, std::size_t frames, const ReadOptions& opt)
    : device_(std::make_unique<LiveDevice>(uri, opt)), frames_(frames) {
  if (frames == 0) throw ParameterError("--frames must be a positive number of frames");
  device_->start();
}

DepthFrame DeviceFrameSource::load(std::size_t i) const {
  if (i != next_) throw InputError(device_->uri(), "live frames can only be read in order");
  DepthFrame f = device_->read();
  ++next_;
  return f;
}

std::string DeviceFrameSource::describe(std::size_t i) const {
  return "frame " + std::to_string(i) + "/" + std::to_string(frames_) + " (" + device_->uri() + ")";
}

}  // namespace tunnelmap::openni2
