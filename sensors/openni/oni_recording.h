#pragma once
// Recording a live device to an OpenNI2 .oni file (openni::Recorder, OniFile format: plays in
// OpenNI2's own tools). The file is written under a temporary name beside the target and renamed
// when the recording is finished, so an interrupted run never leaves a half-written OUT.oni.
#include <OpenNI.h>

#include <functional>
#include <string>

#include "sensors/openni/live_device.h"

namespace tunnelmap::openni2 {

// Records the device's depth (+ colour) streams from construction until finish(). Used by the
// CLI (record_oni) and by the GUI's start/stop recording while the live view keeps reading.
// Finish or drop it only while the device's streams are stopped: OpenNI2 locks a stream and its
// recorder in one order when a frame arrives and in the other when the recorder is destroyed,
// so a frame arriving then can deadlock both (LatestFrameGrabber::with_streams_paused).
class OniRecording {
 public:
  // InputError naming `out_path` when it cannot be written or OpenNI2 refuses to record.
  OniRecording(LiveDevice& device, std::string out_path);
  ~OniRecording();  // not finished: the temporary file is removed
  OniRecording(const OniRecording&) = delete;
  OniRecording& operator=(const OniRecording&) = delete;

  void finish();  // stops, flushes and renames to the target; InputError on failure
  const std::string& path() const { return out_; }

 private:
  std::string out_, tmp_;
  openni::Recorder recorder_;
  bool finished_ = false;
};

struct RecordResult {
  int frames = 0;             // depth frames read while recording
  bool disconnected = false;  // the device went away before `frames` were recorded
};

// Opens `uri` ("" = first device), records `frames` depth frames (+ colour) to `out_path`.
// When the device is unplugged mid-way, what was recorded is kept in `out_path` and an
// InputError says how many frames it holds. `progress(n)` after each frame.
RecordResult record_oni(const std::string& uri, int frames, const std::string& out_path,
                        const std::function<void(int)>& progress = {});

}  // namespace tunnelmap::openni2
