#include "sensors/openni/live_device.h"

#include <algorithm>
#include <cstring>

#include "core/util/error.h"
#include "sensors/openni/openni_context.h"
#include "sensors/openni/sim_driver/sim_driver_protocol.h"
#include "sensors/openni/stream_conversion.h"

namespace tunnelmap::openni2 {

class LiveDevice::DisconnectWatch : public openni::OpenNI::DeviceDisconnectedListener {
 public:
  DisconnectWatch(std::string uri, std::atomic<bool>& flag) : uri_(std::move(uri)), flag_(flag) {
    openni::OpenNI::addDeviceDisconnectedListener(this);
  }
  ~DisconnectWatch() override { openni::OpenNI::removeDeviceDisconnectedListener(this); }
  void onDeviceDisconnected(const openni::DeviceInfo* info) override {
    if (info != nullptr && uri_ == info->getUri()) flag_ = true;
  }

 private:
  std::string uri_;
  std::atomic<bool>& flag_;
};

namespace {
constexpr int kFirstFrameTimeoutMs = 30000;

// VGA at 30 fps in the wanted format if the sensor offers it, else its current mode.
void choose_vga(openni::VideoStream& s, openni::PixelFormat format) {
  const auto& modes = s.getSensorInfo().getSupportedVideoModes();
  for (int i = 0; i < modes.getSize(); ++i)
    if (modes[i].getResolutionX() == 640 && modes[i].getResolutionY() == 480 && modes[i].getFps() == 30 &&
        modes[i].getPixelFormat() == format) {
      s.setVideoMode(modes[i]);
      return;
    }
}
}  // namespace

LiveDevice::LiveDevice(const std::string& uri, const ReadOptions& opt) {
  ensure_initialized();
  const bool any = uri.empty() || uri == "default";
  const std::string label = any ? "default device" : uri;
  if (device_.open(any ? openni::ANY_DEVICE : uri.c_str()) != openni::STATUS_OK)
    throw InputError(label, "cannot open OpenNI2 device: " + last_error());
  uri_ = device_.getDeviceInfo().getUri();
  name_ = device_.getDeviceInfo().getName();
  watch_ = std::make_unique<DisconnectWatch>(uri_, disconnected_);
  if (!device_.hasSensor(openni::SENSOR_DEPTH) || depth_.create(device_, openni::SENSOR_DEPTH) != openni::STATUS_OK)
    throw InputError(uri_, "device has no depth stream");
  choose_vga(depth_, openni::PIXEL_FORMAT_DEPTH_1_MM);
  depth_.setMirroringEnabled(false);
  if (device_.hasSensor(openni::SENSOR_COLOR) && color_.create(device_, openni::SENSOR_COLOR) == openni::STATUS_OK) {
    choose_vga(color_, openni::PIXEL_FORMAT_RGB888);
    color_.setMirroringEnabled(false);
    if (device_.isImageRegistrationModeSupported(openni::IMAGE_REGISTRATION_DEPTH_TO_COLOR))
      registered_ = device_.setImageRegistrationMode(openni::IMAGE_REGISTRATION_DEPTH_TO_COLOR) == openni::STATUS_OK;
  }
  const openni::VideoMode m = depth_.getVideoMode();
  K_ = stream_intrinsics(depth_, m.getResolutionX(), m.getResolutionY(), opt);
  has_pose_command_ = device_.isCommandSupported(simdriver::kCommandFramePose);
}

LiveDevice::~LiveDevice() {
  stop();
  if (color_.isValid()) color_.destroy();
  if (depth_.isValid()) depth_.destroy();
  watch_.reset();
  device_.close();
}

void LiveDevice::start() {
  if (started_) return;
  if (depth_.start() != openni::STATUS_OK) throw InputError(uri_, "cannot start the depth stream: " + last_error());
  if (color_.isValid() && color_.start() != openni::STATUS_OK) color_.destroy();  // depth alone still works
  started_ = true;
}

void LiveDevice::stop() {
  if (!started_) return;
  // Depth first: a frame arriving meanwhile then adds at most a colour frame without its depth
  // frame (ignored on playback), never a depth frame without its own colour.
  depth_.stop();
  if (color_.isValid()) color_.stop();
  started_ = false;
}

DepthFrame LiveDevice::read(int timeout_ms) {
  if (!started_) start();
  auto unplugged = [&] {
    return InputError(uri_, "device disconnected after " + std::to_string(frames_read_) + " frames");
  };
  // Cameras take a while to deliver their first frame (the simulated one renders its frame cycle
  // first, a few seconds on a loaded machine).
  const int wait_ms = frames_read_ == 0 ? std::max(timeout_ms, kFirstFrameTimeoutMs) : timeout_ms;
  if (!wait_for_frame(depth_, wait_ms)) {
    if (disconnected_) throw unplugged();
    throw InputError(uri_, "no depth frame within " + std::to_string(wait_ms) + " ms");
  }
  openni::VideoFrameRef f;
  if (depth_.readFrame(&f) != openni::STATUS_OK) throw InputError(uri_, "cannot read a depth frame: " + last_error());
  if (color_.isValid()) {
    openni::VideoFrameRef c;
    while (wait_for_frame(color_, 0) && color_.readFrame(&c) == openni::STATUS_OK) last_color_ = c;
  }
  DepthFrame d = depth_frame_from(f, K_, uri_);
  attach_color(d, last_color_);
  if (has_pose_command_) {
    simdriver::FramePoseRequest r;
    r.frame_index = f.getFrameIndex();
    if (device_.invoke(simdriver::kCommandFramePose, &r, sizeof r) == openni::STATUS_OK) {
      Eigen::Matrix4d T;
      std::memcpy(T.data(), r.camera_to_world, sizeof r.camera_to_world);
      d.pose = Eigen::Isometry3d(T);
    }
  }
  ++frames_read_;
  return d;
}

}  // namespace tunnelmap::openni2
