// libTunnelMapSim.so.0: an OpenNI2 driver module presenting the project's tunnel simulator as a
// PrimeSense-class camera (VGA depth in mm at 30 fps + registered RGB888; faster for soak tests),
// so that the whole OpenNI2 stack (enumeration, streams, Recorder, OniFile playback) can be
// tested without hardware. Protocol (URIs, pose command): sim_driver_protocol.h.
#define XN_NEW(type, arg) new type(arg)
#define XN_DELETE(p) delete (p)
#include <Driver/OniDriverAPI.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <map>
#include <memory>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include "core/sim/tunnel_simulator.h"
#include "sensors/openni/sim_driver/sim_driver_protocol.h"

namespace {
using namespace tunnelmap;

constexpr int kWidth = 640, kHeight = 480, kFps = 30;
constexpr int kMaxDepthMm = 65534;  // largest depth value emitted (0 = no depth)

struct SimDeviceOptions {
  std::string preset = "lab";
  int pose = -1;  // -1 = all of the preset's poses
  int disconnect_after = -1;
  bool color = true;
  unsigned seed = 1;
  int frames = 0;  // frame cycle length; 0 = the preset's
  int fps = kFps;  // frames sent per second; 0 = paced by the client (see run())
};

// Parses "tunnelmap-sim://PRESET?k=v&...". False for anything else (other drivers' URIs).
bool parse_uri(const std::string& uri, SimDeviceOptions& o) {
  const std::string scheme = simdriver::kUriScheme;
  if (uri.compare(0, scheme.size(), scheme) != 0) return false;
  std::string rest = uri.substr(scheme.size());
  const auto q = rest.find('?');
  o.preset = rest.substr(0, q);
  if (o.preset != "lab" && o.preset != "field") return false;
  if (q == std::string::npos) return true;
  std::string query = rest.substr(q + 1);
  std::size_t pos = 0;
  while (pos <= query.size()) {
    const auto amp = query.find('&', pos);
    const std::string kv = query.substr(pos, amp == std::string::npos ? std::string::npos : amp - pos);
    const auto eq = kv.find('=');
    if (eq == std::string::npos) return false;
    const std::string k = kv.substr(0, eq), v = kv.substr(eq + 1);
    char* end = nullptr;
    const long n = std::strtol(v.c_str(), &end, 10);
    if (v.empty() || *end != '\0') return false;
    if (k == "pose") o.pose = static_cast<int>(n);
    else if (k == "disconnect_after") o.disconnect_after = static_cast<int>(n);
    else if (k == "color") o.color = n != 0;
    else if (k == "seed") o.seed = static_cast<unsigned>(n);
    else if (k == "frames" && n >= 1 && n <= 300) o.frames = static_cast<int>(n);
    else if (k == "fps" && n >= 0 && n <= 1000) o.fps = static_cast<int>(n);
    else return false;
    if (amp == std::string::npos) break;
    pos = amp + 1;
  }
  return true;
}

SimConfig make_config(const SimDeviceOptions& o) {
  SimConfig c = SimConfig::from_preset(o.preset);
  c.seed = o.seed;
  if (o.frames > 0) c.frames = o.frames;
  if (o.pose >= 0) {
    if (o.pose >= static_cast<int>(c.poses.size())) return SimConfig();  // caught by caller
    c.poses = {c.poses[static_cast<std::size_t>(o.pose)]};
  }
  return c;
}

OniVideoMode vga_mode(OniPixelFormat format) {
  OniVideoMode m;
  m.pixelFormat = format;
  m.resolutionX = kWidth;
  m.resolutionY = kHeight;
  m.fps = kFps;
  return m;
}

// One simulator frame as the camera sends it: depth in mm (0 = none) and RGB888.
struct WireFrame {
  std::vector<OniDepthPixel> depth;
  std::vector<std::uint8_t> rgb;
};
using FrameCycle = std::vector<WireFrame>;

WireFrame to_wire(const SimFrame& sim) {
  WireFrame w;
  const std::size_t n = static_cast<std::size_t>(kWidth) * kHeight;
  w.depth.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    const float d = sim.frame.depth[i];
    w.depth[i] = (std::isfinite(d) && d > 0 && d <= kMaxDepthMm) ? static_cast<OniDepthPixel>(std::lround(d)) : 0;
  }
  if (sim.frame.has_rgb()) w.rgb.assign(sim.frame.rgb.begin(), sim.frame.rgb.end());
  else w.rgb.assign(n * 3, 128);
  return w;
}

// The simulator's whole frame cycle, rendered on all cores once per process and configuration
// as soon as a device opens, so that streaming keeps 30 fps from its first frame: one render
// takes ~100 ms, three frame periods. The few most recent cycles are kept (~45 MB each), so
// reopening a device costs nothing. nullptr when `cancel` is raised first (device closed while
// rendering, e.g. by enumeration).
std::shared_ptr<const FrameCycle> frame_cycle(const SimDeviceOptions& o, const TunnelSimulator& sim,
                                              const std::atomic<bool>& cancel) {
  static std::mutex mutex;
  static std::vector<std::pair<std::string, std::shared_ptr<const FrameCycle>>> cache;  // newest last
  const std::string key = o.preset + "/" + std::to_string(o.pose) + "/" + std::to_string(o.seed) + "/" +
                          std::to_string(o.frames);
  std::lock_guard<std::mutex> lock(mutex);  // one render at a time: it uses every core already
  for (auto it = cache.begin(); it != cache.end(); ++it)
    if (it->first == key) {
      auto hit = *it;
      cache.erase(it);
      cache.push_back(hit);
      return hit.second;
    }
  auto cycle = std::make_shared<FrameCycle>(static_cast<std::size_t>(sim.frame_count()));
  std::atomic<int> next{0};
  auto worker = [&] {
    for (int k = next++; k < sim.frame_count() && !cancel; k = next++)
      (*cycle)[static_cast<std::size_t>(k)] = to_wire(sim.render(k));
  };
  std::vector<std::thread> pool;
  for (unsigned t = 1; t < std::max(2u, std::thread::hardware_concurrency()); ++t) pool.emplace_back(worker);
  worker();
  for (std::thread& t : pool) t.join();
  if (cancel) return nullptr;
  constexpr std::size_t kKept = 3;
  if (cache.size() >= kKept) cache.erase(cache.begin());
  cache.emplace_back(key, cycle);
  return cycle;
}

class SimDevice;

class SimStream : public oni::driver::StreamBase {
 public:
  // `emit_mutex` is the device's: held by its frame thread while it hands frames over.
  SimStream(OniSensorType type, const Intrinsics& K, std::mutex& emit_mutex)
      : type_(type), K_(K), emit_mutex_(emit_mutex) {}
  OniStatus start() override { running_ = true; return ONI_STATUS_OK; }
  // Returns only once no frame of this stream is being handed to OpenNI2, so that after a
  // client's VideoStream::stop no frame reaches its Recorder. OpenNI2 takes the stream's and the
  // recorder's locks in opposite orders when a frame arrives (stream, then recorder) and when a
  // recorder is destroyed (recorder, then stream): a frame in flight while a recording finishes
  // can deadlock both threads (a recording test hung for 120 s on a loaded machine).
  void stop() override {
    std::lock_guard<std::mutex> lock(emit_mutex_);
    running_ = false;
  }
  bool running() const { return running_; }
  OniSensorType type() const { return type_; }

  OniBool isPropertySupported(int id) override {
    switch (id) {
      case ONI_STREAM_PROPERTY_VIDEO_MODE: case ONI_STREAM_PROPERTY_HORIZONTAL_FOV:
      case ONI_STREAM_PROPERTY_VERTICAL_FOV: case ONI_STREAM_PROPERTY_MIRRORING:
      case ONI_STREAM_PROPERTY_STRIDE: case ONI_STREAM_PROPERTY_MAX_VALUE:
      case ONI_STREAM_PROPERTY_MIN_VALUE: case ONI_STREAM_PROPERTY_CROPPING: return TRUE;
      default: return FALSE;
    }
  }

  OniStatus getProperty(int id, void* data, int* size) override {
    auto put = [&](const auto& v) {
      if (*size != static_cast<int>(sizeof v)) return ONI_STATUS_BAD_PARAMETER;
      std::memcpy(data, &v, sizeof v);
      return ONI_STATUS_OK;
    };
    switch (id) {
      case ONI_STREAM_PROPERTY_VIDEO_MODE: return put(mode());
      case ONI_STREAM_PROPERTY_HORIZONTAL_FOV: return put(static_cast<float>(2 * std::atan(K_.width / (2 * K_.fx))));
      case ONI_STREAM_PROPERTY_VERTICAL_FOV: return put(static_cast<float>(2 * std::atan(K_.height / (2 * K_.fy))));
      case ONI_STREAM_PROPERTY_MIRRORING: return put(OniBool(FALSE));
      case ONI_STREAM_PROPERTY_STRIDE: return put(int(kWidth * bytes_per_pixel()));
      // The full range emitted (far tunnel walls exceed a PrimeSense's 10 m): the Recorder's
      // lossless depth codec clips at this value.
      case ONI_STREAM_PROPERTY_MAX_VALUE: return put(int(type_ == ONI_SENSOR_DEPTH ? kMaxDepthMm : 255));
      case ONI_STREAM_PROPERTY_MIN_VALUE: return put(int(0));
      // Reported although the camera never crops: OpenNI2's Recorder writes the "xnCropping" record
      // only for streams that answer this property, and the OniFile player (PlayerStream::
      // OnNewDataCallback) silently drops every frame of a stream without it (docs/openni.md).
      case ONI_STREAM_PROPERTY_CROPPING: return put(OniCropping{FALSE, 0, 0, kWidth, kHeight});
      default: return ONI_STATUS_NOT_SUPPORTED;
    }
  }

  OniStatus setProperty(int id, const void* data, int size) override {
    if (id == ONI_STREAM_PROPERTY_CROPPING && size == sizeof(OniCropping))
      return static_cast<const OniCropping*>(data)->enabled ? ONI_STATUS_NOT_SUPPORTED : ONI_STATUS_OK;
    if (id == ONI_STREAM_PROPERTY_MIRRORING && size == sizeof(OniBool))
      return *static_cast<const OniBool*>(data) ? ONI_STATUS_NOT_SUPPORTED : ONI_STATUS_OK;
    if (id == ONI_STREAM_PROPERTY_VIDEO_MODE && size == sizeof(OniVideoMode)) {
      const auto* m = static_cast<const OniVideoMode*>(data);
      const OniVideoMode mine = mode();
      return (m->pixelFormat == mine.pixelFormat && m->resolutionX == kWidth && m->resolutionY == kHeight &&
              m->fps == kFps) ? ONI_STATUS_OK : ONI_STATUS_NOT_SUPPORTED;
    }
    return ONI_STATUS_NOT_SUPPORTED;
  }

  // Called from the device's frame thread.
  void emit(const WireFrame& w, int index) {
    OniFrame* f = getServices().acquireFrame();
    if (f == nullptr) return;
    const int n = kWidth * kHeight;
    if (type_ == ONI_SENSOR_DEPTH) std::memcpy(f->data, w.depth.data(), w.depth.size() * sizeof(OniDepthPixel));
    else std::memcpy(f->data, w.rgb.data(), w.rgb.size());
    f->dataSize = n * bytes_per_pixel();
    f->sensorType = type_;
    f->timestamp = static_cast<uint64_t>(index) * 1000000ull / kFps;
    f->frameIndex = index;
    f->width = kWidth;
    f->height = kHeight;
    f->videoMode = mode();
    f->croppingEnabled = FALSE;
    f->cropOriginX = f->cropOriginY = 0;
    f->stride = kWidth * bytes_per_pixel();
    raiseNewFrame(f);
    getServices().releaseFrame(f);
  }

 private:
  int bytes_per_pixel() const { return type_ == ONI_SENSOR_DEPTH ? 2 : 3; }
  OniVideoMode mode() const {
    return vga_mode(type_ == ONI_SENSOR_DEPTH ? ONI_PIXEL_FORMAT_DEPTH_1_MM : ONI_PIXEL_FORMAT_RGB888);
  }
  OniSensorType type_;
  Intrinsics K_;
  std::mutex& emit_mutex_;
  std::atomic<bool> running_{false};
};

class SimDriver;

class SimDevice : public oni::driver::DeviceBase {
 public:
  SimDevice(SimDriver* driver, OniDeviceInfo info, const SimDeviceOptions& o)
      : driver_(driver), info_(info), options_(o), sim_(make_config(o)) {
    depth_mode_ = vga_mode(ONI_PIXEL_FORMAT_DEPTH_1_MM);
    color_mode_ = vga_mode(ONI_PIXEL_FORMAT_RGB888);
    sensors_[0] = {ONI_SENSOR_DEPTH, 1, &depth_mode_};
    sensors_[1] = {ONI_SENSOR_COLOR, 1, &color_mode_};
    thread_ = std::thread([this] { run(); });
  }
  ~SimDevice() override {
    {
      std::lock_guard<std::mutex> lock(ack_mutex_);
      quit_ = true;
    }
    ack_cv_.notify_all();
    thread_.join();
  }

  OniStatus getSensorInfoList(OniSensorInfo** infos, int* count) override {
    *infos = sensors_;
    *count = options_.color ? 2 : 1;
    return ONI_STATUS_OK;
  }

  oni::driver::StreamBase* createStream(OniSensorType type) override {
    if (type != ONI_SENSOR_DEPTH && !(type == ONI_SENSOR_COLOR && options_.color)) return nullptr;
    auto* s = new SimStream(type, Intrinsics::primesense_vga(), mutex_);
    std::lock_guard<std::mutex> lock(mutex_);
    streams_.push_back(s);
    return s;
  }

  void destroyStream(oni::driver::StreamBase* stream) override {
    {
      std::lock_guard<std::mutex> lock(mutex_);
      for (auto it = streams_.begin(); it != streams_.end(); ++it)
        if (*it == stream) { streams_.erase(it); break; }
    }
    delete stream;
  }

  OniBool isPropertySupported(int id) override {
    return id == ONI_DEVICE_PROPERTY_IMAGE_REGISTRATION || id == ONI_DEVICE_PROPERTY_DRIVER_VERSION ||
           id == ONI_DEVICE_PROPERTY_SERIAL_NUMBER;
  }
  OniStatus getProperty(int id, void* data, int* size) override {
    if (id == ONI_DEVICE_PROPERTY_IMAGE_REGISTRATION && *size == sizeof(OniImageRegistrationMode)) {
      *static_cast<OniImageRegistrationMode*>(data) = registration_;
      return ONI_STATUS_OK;
    }
    if (id == ONI_DEVICE_PROPERTY_DRIVER_VERSION && *size == sizeof(OniVersion)) {
      *static_cast<OniVersion*>(data) = OniVersion{0, 1, 0, 0};
      return ONI_STATUS_OK;
    }
    if (id == ONI_DEVICE_PROPERTY_SERIAL_NUMBER && *size > 0) {
      std::strncpy(static_cast<char*>(data), ("SIM-" + options_.preset).c_str(), static_cast<std::size_t>(*size));
      static_cast<char*>(data)[*size - 1] = '\0';
      return ONI_STATUS_OK;
    }
    return ONI_STATUS_NOT_SUPPORTED;
  }
  OniStatus setProperty(int id, const void* data, int size) override {
    if (id == ONI_DEVICE_PROPERTY_IMAGE_REGISTRATION && size == sizeof(OniImageRegistrationMode)) {
      registration_ = *static_cast<const OniImageRegistrationMode*>(data);
      return ONI_STATUS_OK;
    }
    return ONI_STATUS_NOT_SUPPORTED;
  }
  // Colour is rendered registered to depth already, so both modes are honoured.
  OniBool isImageRegistrationModeSupported(OniImageRegistrationMode) override { return TRUE; }

  OniBool isCommandSupported(int id) override { return id == simdriver::kCommandFramePose; }
  OniStatus invoke(int id, void* data, int size) override {
    if (id != simdriver::kCommandFramePose || size != sizeof(simdriver::FramePoseRequest))
      return ONI_STATUS_NOT_SUPPORTED;
    auto* r = static_cast<simdriver::FramePoseRequest*>(data);
    if (r->frame_index < 0) return ONI_STATUS_BAD_PARAMETER;
    {
      std::lock_guard<std::mutex> lock(ack_mutex_);
      asked_ = std::max(asked_, r->frame_index);
    }
    ack_cv_.notify_all();
    const Eigen::Matrix4d T = sim_.pose(r->frame_index % sim_.frame_count()).matrix();
    std::memcpy(r->camera_to_world, T.data(), sizeof r->camera_to_world);
    r->world_up[0] = 0, r->world_up[1] = 0, r->world_up[2] = 1;
    return ONI_STATUS_OK;
  }

  const OniDeviceInfo& info() const { return info_; }

 private:
  // Renders the frame cycle, then sends one of its frames per tick while any stream runs (a
  // stream started earlier waits for the cycle); the simulator's frames repeat with its period.
  void run();
  bool wait_until_read(int index);  // fps=0; false when the device closes

  SimDriver* driver_;
  OniDeviceInfo info_;
  SimDeviceOptions options_;
  TunnelSimulator sim_;
  OniVideoMode depth_mode_, color_mode_;
  OniSensorInfo sensors_[2];
  OniImageRegistrationMode registration_ = ONI_IMAGE_REGISTRATION_OFF;
  std::mutex mutex_;
  std::vector<SimStream*> streams_;
  std::shared_ptr<const FrameCycle> cycle_;  // frame k of the simulator, ready to send (run())
  // fps=0: the newest frame index whose pose the client asked for (it has read that frame).
  std::mutex ack_mutex_;
  std::condition_variable ack_cv_;
  int asked_ = -1;
  std::atomic<bool> quit_{false};
  std::thread thread_;
};

class SimDriver : public oni::driver::DriverBase {
 public:
  explicit SimDriver(OniDriverServices* services) : DriverBase(services) {}

  OniStatus initialize(oni::driver::DeviceConnectedCallback connected,
                       oni::driver::DeviceDisconnectedCallback disconnected,
                       oni::driver::DeviceStateChangedCallback state_changed, void* cookie) override {
    DriverBase::initialize(connected, disconnected, state_changed, cookie);
    for (const char* preset : {"lab", "field"}) announce(std::string(simdriver::kUriScheme) + preset);
    return ONI_STATUS_OK;
  }

  OniStatus tryDevice(const char* uri) override {
    SimDeviceOptions o;
    if (uri == nullptr || !parse_uri(uri, o)) return ONI_STATUS_ERROR;
    announce(uri);
    return ONI_STATUS_OK;
  }

  oni::driver::DeviceBase* deviceOpen(const char* uri, const char* /*mode*/) override {
    SimDeviceOptions o;
    if (uri == nullptr || !parse_uri(uri, o)) return nullptr;
    auto it = infos_.find(uri);
    if (it == infos_.end()) return nullptr;
    try {
      if (o.pose >= static_cast<int>(SimConfig::from_preset(o.preset).poses.size())) {
        getServices().errorLoggerAppend("%s: pose %d does not exist", uri, o.pose);
        return nullptr;
      }
      return new SimDevice(this, it->second, o);
    } catch (const std::exception& e) {
      getServices().errorLoggerAppend("%s: %s", uri, e.what());
      return nullptr;
    }
  }

  void deviceClose(oni::driver::DeviceBase* device) override { delete device; }
  void shutdown() override {}

  void unplugged(const OniDeviceInfo& info) {
    std::lock_guard<std::mutex> lock(mutex_);
    infos_.erase(info.uri);
    deviceDisconnected(&info);
  }

 private:
  void announce(const std::string& uri) {
    std::lock_guard<std::mutex> lock(mutex_);
    OniDeviceInfo& info = infos_[uri];
    std::memset(&info, 0, sizeof info);
    std::strncpy(info.uri, uri.c_str(), ONI_MAX_STR - 1);
    std::strncpy(info.vendor, simdriver::kVendor, ONI_MAX_STR - 1);
    std::strncpy(info.name, "Simulated tunnel camera", ONI_MAX_STR - 1);
    info.usbVendorId = 0;
    info.usbProductId = 0;
    deviceConnected(&info);
  }
  std::mutex mutex_;
  std::map<std::string, OniDeviceInfo> infos_;
};

// fps=0 sends frame k+1 once the client asked for the pose of frame k (LiveDevice::read does for
// every frame it reads): OpenNI2 keeps only a stream's newest frame, so a timer-paced camera
// loses frames whenever the reader is slower, while this one never does and runs as fast as the
// reader (soak tests, however slow the reader: no time-out, or a slow reader would lose frames
// again). A client that never asks gets the next frame only after kAckTimeout: a reader that
// missed frame k (OpenNI2 hands it the newest, and a stop can race a send) would otherwise wait
// for k + 1 forever while this waits for its ask of k (seen once as a 120 s hang of a
// recording test under AddressSanitizer on a loaded machine).
bool SimDevice::wait_until_read(int index) {
  constexpr auto kAckTimeout = std::chrono::seconds(10);
  std::unique_lock<std::mutex> lock(ack_mutex_);
  ack_cv_.wait_for(lock, kAckTimeout, [&] { return quit_ || asked_ >= index; });
  return !quit_;
}

void SimDevice::run() {
  using clock = std::chrono::steady_clock;
  const bool paced_by_client = options_.fps == 0;
  const auto period = std::chrono::microseconds(1000000 / std::max(1, options_.fps));
  auto next = clock::now();
  int index = 0, emitted = 0;
  bool unplugged = false;
  cycle_ = frame_cycle(options_, sim_, quit_);
  if (!cycle_) return;  // closed while rendering
  next = clock::now();
  while (!quit_) {
    bool any = false;
    {
      std::lock_guard<std::mutex> lock(mutex_);
      for (SimStream* s : streams_) any = any || s->running();
    }
    if (!any || unplugged) {
      std::this_thread::sleep_for(std::chrono::milliseconds(5));
      next = clock::now();
      continue;
    }
    if (paced_by_client) {
      if (index > 0 && !wait_until_read(index - 1)) break;
    } else {
      std::this_thread::sleep_until(next);
      next += period;
      if (clock::now() > next + 3 * period) next = clock::now();  // fell behind: do not burst
    }
    const WireFrame& frame = (*cycle_)[static_cast<std::size_t>(index % sim_.frame_count())];
    {
      std::lock_guard<std::mutex> lock(mutex_);
      // Colour first, then depth: a client that stops after the N-th depth frame has its colour.
      for (OniSensorType t : {ONI_SENSOR_COLOR, ONI_SENSOR_DEPTH})
        for (SimStream* s : streams_)
          if (s->running() && s->type() == t) s->emit(frame, index);
    }
    ++index;
    if (++emitted == options_.disconnect_after) {
      unplugged = true;
      driver_->unplugged(info_);
    }
  }
}

}  // namespace

ONI_EXPORT_DRIVER(SimDriver)
