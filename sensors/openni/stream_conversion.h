#pragma once
// OpenNI2 frames -> DepthFrame, and the stream's pinhole intrinsics from its field of view.
#include <OpenNI.h>

#include <string>

#include "core/frame/depth_frame.h"
#include "core/io/read_options.h"

namespace tunnelmap::openni2 {

// fx = (W/2) / tan(HFOV/2), principal point at the image centre; the PrimeSense VGA default
// when the stream reports no FOV. User intrinsics (ReadOptions) win.
Intrinsics stream_intrinsics(openni::VideoStream& stream, int width, int height, const ReadOptions& opt);

// Depth in mm (DEPTH_1_MM) or 0.1 mm (DEPTH_100_UM); InputError naming `source` otherwise.
DepthFrame depth_frame_from(const openni::VideoFrameRef& frame, const Intrinsics& K, const std::string& source);

// Adds an RGB888 frame of the same size as colour (ignored otherwise).
void attach_color(DepthFrame& frame, const openni::VideoFrameRef& color);

// Waits up to `timeout_ms` for a frame on `stream`; false on timeout or error.
bool wait_for_frame(openni::VideoStream& stream, int timeout_ms);

}  // namespace tunnelmap::openni2
