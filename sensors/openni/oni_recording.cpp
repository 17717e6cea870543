#include "sensors/openni/oni_recording.h"

#include <unistd.h>

#include <exception>
#include <filesystem>

#include "core/util/atomic_file.h"
#include "core/util/error.h"
#include "core/util/sibling_name.h"
#include "sensors/openni/oni_file_source.h"
#include "sensors/openni/openni_context.h"

namespace tunnelmap::openni2 {
namespace fs = std::filesystem;

OniRecording::OniRecording(LiveDevice& device, std::string out_path) : out_(std::move(out_path)) {
  check_output_path(out_);
  // Same folder (rename stays atomic), ".oni" suffix kept for tools that look at it.
  const fs::path target(out_);
  tmp_ = sibling_name(target, ".", ".tmp-" + std::to_string(getpid()) + ".oni", false).string();
  if (recorder_.create(tmp_.c_str()) != openni::STATUS_OK)
    throw InputError(out_, "cannot create the recording: " + last_error());
  if (recorder_.attach(device.depth_stream()) != openni::STATUS_OK)
    throw InputError(out_, "cannot record the depth stream: " + last_error());
  if (openni::VideoStream* c = device.color_stream())
    if (recorder_.attach(*c, true) != openni::STATUS_OK)
      throw InputError(out_, "cannot record the colour stream: " + last_error());
  if (recorder_.start() != openni::STATUS_OK) throw InputError(out_, "cannot start recording: " + last_error());
}

OniRecording::~OniRecording() {
  if (finished_) return;
  recorder_.stop();
  recorder_.destroy();
  std::error_code ec;
  fs::remove(tmp_, ec);
}

void OniRecording::finish() {
  if (finished_) return;
  finished_ = true;
  recorder_.stop();
  recorder_.destroy();  // joins the recorder's writer thread: the file is complete after this
  std::error_code ec;
  fs::rename(tmp_, out_, ec);
  if (ec) {
    fs::remove(tmp_, ec);
    throw InputError(out_, "cannot write the recording: " + ec.message());
  }
}

RecordResult record_oni(const std::string& uri, int frames, const std::string& out_path,
                        const std::function<void(int)>& progress) {
  if (frames <= 0) throw ParameterError("--frames must be a positive number of frames");
  check_output_path(out_path);
  LiveDevice device(uri);
  RecordResult result;
  std::string failure;
  {
    OniRecording recording(device, out_path);  // attached before the streams start: nothing missed
    device.start();
    std::exception_ptr nothing_recorded;
    try {
      while (result.frames < frames) {
        device.read();
        ++result.frames;
        if (progress) progress(result.frames);
      }
    } catch (const InputError& e) {
      result.disconnected = device.disconnected();
      failure = e.problem();
      if (result.frames == 0) nothing_recorded = std::current_exception();  // nothing worth keeping
    } catch (...) {
      device.stop();  // before the recording is dropped (see OniRecording)
      throw;
    }
    device.stop();
    if (nothing_recorded) std::rethrow_exception(nothing_recorded);
    recording.finish();
  }
  if (!failure.empty()) {
    // The recorder takes every frame the device sent; under load the loop above reads fewer
    // (a live stream keeps only the newest), so the count is the file's own.
    std::size_t recorded = static_cast<std::size_t>(result.frames);
    try {
      recorded = OniFileSource(out_path, ReadOptions()).size();
    } catch (const InputError&) {  // unreadable: keep the count read
    }
    throw InputError(device.uri(), failure + "; the " + std::to_string(recorded) +
                                       " frames recorded so far are in " + out_path);
  }
  return result;
}

}  // namespace tunnelmap::openni2
