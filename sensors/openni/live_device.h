#pragma once
// A live OpenNI2 device: VGA depth (mm) at 30 fps plus colour when the device has it,
// depth-to-colour registration when supported, mirroring off, intrinsics from the stream's FOV.
// Frames of the simulated camera (libTunnelMapSim) also carry the simulator's pose.
#include <OpenNI.h>

#include <atomic>
#include <memory>
#include <string>

#include "core/frame/depth_frame.h"
#include "core/io/read_options.h"

namespace tunnelmap::openni2 {

class LiveDevice {
 public:
  // `uri` empty or "default": the first device. Streams are created but not started.
  // InputError(uri, reason) when there is no such device or it has no usable depth stream.
  explicit LiveDevice(const std::string& uri, const ReadOptions& opt = {});
  ~LiveDevice();
  LiveDevice(const LiveDevice&) = delete;
  LiveDevice& operator=(const LiveDevice&) = delete;

  void start();  // starts depth (and colour); InputError on failure
  void stop();

  // The next depth frame (with the newest colour frame when the device has colour).
  // InputError(uri, "device disconnected after N frames") once the device is unplugged, or
  // "no frame within T ms" when it stops delivering (the first frame may take up to 30 s).
  DepthFrame read(int timeout_ms = 2000);

  const std::string& uri() const { return uri_; }
  const std::string& name() const { return name_; }
  bool has_color() const { return color_.isValid(); }
  bool registered() const { return registered_; }
  const Intrinsics& intrinsics() const { return K_; }
  int frames_read() const { return frames_read_; }
  bool disconnected() const { return disconnected_; }

  // For recording (Recorder::attach) while streaming.
  openni::VideoStream& depth_stream() { return depth_; }
  openni::VideoStream* color_stream() { return color_.isValid() ? &color_ : nullptr; }

 private:
  class DisconnectWatch;
  std::string uri_, name_;
  openni::Device device_;
  openni::VideoStream depth_, color_;
  openni::VideoFrameRef last_color_;
  Intrinsics K_;
  bool registered_ = false, has_pose_command_ = false, started_ = false;
  int frames_read_ = 0;
  std::atomic<bool> disconnected_{false};
  std::unique_ptr<DisconnectWatch> watch_;
};

}  // namespace tunnelmap::openni2
