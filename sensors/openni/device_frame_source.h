#pragma once
// A live device as a FrameSource of N frames, for `detect --device URI --frames N`: frames are
// read in order as they arrive (load(i) must be called with i = 0, 1, 2, ...).
#include <memory>
#include <string>

#include "core/io/frame_source.h"
#include "sensors/openni/live_device.h"

namespace tunnelmap::openni2 {

class DeviceFrameSource : public FrameSource {
 public:
  DeviceFrameSource(const std::string& uri, std::size_t frames, const ReadOptions& opt);
  std::size_t size() const override { return frames_; }
  DepthFrame load(std::size_t i) const override;  // InputError when out of order or unplugged
  std::string describe(std::size_t i) const override;
  LiveDevice& device() const { return *device_; }

 private:
  std::unique_ptr<LiveDevice> device_;
  std::size_t frames_;
  mutable std::size_t next_ = 0;
};

}  // namespace tunnelmap::openni2
