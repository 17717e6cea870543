#include "sensors/openni/oni_file_source.h"

#include <filesystem>

#include "core/io/oni_container.h"
#include "core/util/error.h"
#include "sensors/openni/openni_context.h"
#include "sensors/openni/stream_conversion.h"

namespace tunnelmap::openni2 {

namespace {
// A playback frame is normally there in milliseconds; generous for a loaded CI machine.
constexpr int kFrameTimeoutMs = 2000;
}  // namespace

// Random access without PlaybackControl::seek: Debian's libOpenNI2 2.2 (Device::invoke) passes
// the OniFile driver an uninitialised stream pointer with every seek (its translated Seek struct
// is block-scoped and used after its lifetime, and GCC drops the store), which crashes or hangs
// the player thread. Going back therefore reopens the recording and going forward reads and
// drops frames; both are cheap next to detection (docs/openni.md).
struct OniFileSource::Player {
  openni::Device device;
  openni::VideoStream depth, color;
  openni::VideoFrameRef last_color;
  std::size_t next = 0;  // index of the frame the next read returns
  int frames = 0;        // depth frames in the recording
  // Streams first while the player thread is parked: with manual speed it waits for the next
  // trigger inside OnNodeNewData, where stream removal is locked. (Its MainLoop walks the stream
  // list without a lock, so it must never spin there: repeat stays on, see open_player.)
  ~Player() {
    for (openni::VideoStream* s : {&color, &depth})
      if (s->isValid()) {
        s->stop();
        s->destroy();
      }
    device.close();
  }
};

OniFileSource::OniFileSource(std::string path, ReadOptions opt) : path_(std::move(path)) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path_, ec)) throw InputError(path_, "not found");
  // OpenNI's player trusts the file and can crash or hang the process on a damaged one.
  oni::check_recording_file(path_, opt.max_image_pixels);
  ensure_initialized();
  player_ = open_player();
  count_ = static_cast<std::size_t>(player_->frames);
  has_color_ = player_->color.isValid();
  const openni::VideoMode m = player_->depth.getVideoMode();
  K_ = stream_intrinsics(player_->depth, m.getResolutionX(), m.getResolutionY(), opt);
}

OniFileSource::~OniFileSource() = default;

std::unique_ptr<OniFileSource::Player> OniFileSource::open_player() const {
  auto p = std::make_unique<Player>();
  if (p->device.open(path_.c_str()) != openni::STATUS_OK) {
    // OpenNI2's player gives no reason for a truncated file; say what it most likely is.
    const std::string why = last_error();
    throw InputError(path_, "not a readable OpenNI2 recording (" +
                                (why.empty() ? std::string("truncated or corrupt file") : why) + ")");
  }
  openni::PlaybackControl* playback = p->device.getPlaybackControl();
  if (playback == nullptr) throw InputError(path_, "not an OpenNI2 recording");
  if (!p->device.hasSensor(openni::SENSOR_DEPTH) || p->depth.create(p->device, openni::SENSOR_DEPTH) != openni::STATUS_OK)
    throw InputError(path_, "recording has no depth stream");
  // Repeat on, although load() never reads past the last frame: a non-repeating player spins
  // through MainLoop at the end of the file, racing stream destruction (see ~Player).
  playback->setRepeatEnabled(true);
  playback->setSpeed(-1.0f);  // manual: the player hands over the next record when a reader waits
  p->frames = playback->getNumberOfFrames(p->depth);
  if (p->frames <= 0) throw InputError(path_, "recording has no depth frames");
  if (p->device.hasSensor(openni::SENSOR_COLOR) && p->color.create(p->device, openni::SENSOR_COLOR) == openni::STATUS_OK &&
      p->color.start() != openni::STATUS_OK)
    p->color.destroy();  // depth alone still plays
  if (p->depth.start() != openni::STATUS_OK) throw InputError(path_, "cannot play the depth stream: " + last_error());
  return p;
}

// Frames are taken one record at a time in file order: waiting on depth and colour together,
// OpenNI pokes the player (manual speed) only while neither stream holds an unread frame, so the
// player is never more than one record ahead and no frame is replaced before it is read.
// Waiting on depth alone would let colour frames trigger extra pokes that skip depth frames.
DepthFrame OniFileSource::read_next() const {
  Player& p = *player_;
  const auto unreadable = [&] {
    const std::size_t i = p.next;
    player_.reset();  // start over on the next load
    return InputError(path_, "frame " + std::to_string(i) + " cannot be read (truncated recording?)");
  };
  // Colour first: on equal timestamps OpenNI returns the first stream, so a depth frame's own
  // colour frame (recorded just before it) is read before the depth frame.
  openni::VideoStream* streams[] = {&p.color, &p.depth};
  const int first = p.color.isValid() ? 0 : 1;
  openni::VideoFrameRef f;
  for (;;) {
    int ready = -1;
    if (openni::OpenNI::waitForAnyStream(streams + first, 2 - first, &ready, kFrameTimeoutMs) != openni::STATUS_OK)
      throw unreadable();
    openni::VideoStream& s = *streams[first + ready];
    if (s.readFrame(&f) != openni::STATUS_OK || !f.isValid()) throw unreadable();
    if (&s == &p.depth) break;
    p.last_color = f;
  }
  // OniFile numbers each stream's frames 1, 2, ... in file order. Anything else means the player
  // skipped or, at a truncated end, started over (repeat is on): not the frame asked for.
  if (f.getFrameIndex() != static_cast<int>(p.next) + 1) throw unreadable();
  ++p.next;
  DepthFrame d = depth_frame_from(f, K_, path_);
  attach_color(d, p.last_color);
  return d;
}

DepthFrame OniFileSource::load(std::size_t i) const {
  if (i >= count_)
    throw InputError(path_, "frame " + std::to_string(i) + " out of range (" + std::to_string(count_) + " frames)");
  if (!player_ || player_->next > i) {
    player_.reset();  // one player (and its thread) at a time
    player_ = open_player();
  }
  while (player_->next < i) read_next();
  return read_next();
}

std::string OniFileSource::describe(std::size_t i) const {
  return "frame " + std::to_string(i) + "/" + std::to_string(count_) + " (" + path_ + ")";
}

}  // namespace tunnelmap::openni2
