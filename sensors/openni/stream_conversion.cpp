#include "sensors/openni/stream_conversion.h"

#include <cmath>
#include <cstring>

#include "core/util/error.h"
#include "sensors/openni/device_list.h"

namespace tunnelmap::openni2 {

Intrinsics stream_intrinsics(openni::VideoStream& stream, int width, int height, const ReadOptions& opt) {
  if (opt.intrinsics) return intrinsics_for_image(opt, width, height);
  const float hfov = stream.getHorizontalFieldOfView();
  const float vfov = stream.getVerticalFieldOfView();
  if (!(hfov > 0.1f && hfov < 3.0f && vfov > 0.1f && vfov < 3.0f)) return default_intrinsics(width, height);
  Intrinsics K;
  K.width = width;
  K.height = height;
  K.fx = width / 2.0 / std::tan(hfov / 2.0);
  K.fy = height / 2.0 / std::tan(vfov / 2.0);
  K.cx = (width - 1) / 2.0;
  K.cy = (height - 1) / 2.0;
  return K;
}

DepthFrame depth_frame_from(const openni::VideoFrameRef& f, const Intrinsics& K, const std::string& source) {
  const int format = f.getVideoMode().getPixelFormat();
  double units = 0;
  if (format == openni::PIXEL_FORMAT_DEPTH_1_MM) units = 1000.0;
  if (format == openni::PIXEL_FORMAT_DEPTH_100_UM) units = 10000.0;
  if (units == 0) throw InputError(source, "depth pixel format " + pixel_format_name(format) + " is not supported");
  DepthFrame d;
  d.width = f.getWidth();
  d.height = f.getHeight();
  if (d.width <= 0 || d.height <= 0 || f.getData() == nullptr) throw InputError(source, "empty depth frame");
  d.depth_units_per_m = units;
  d.depth.resize(static_cast<std::size_t>(d.width) * d.height);
  const auto* base = static_cast<const std::uint8_t*>(f.getData());
  const int stride = f.getStrideInBytes() > 0 ? f.getStrideInBytes() : d.width * 2;
  if (f.getDataSize() < stride * (d.height - 1) + d.width * 2) throw InputError(source, "depth frame is truncated");
  for (int v = 0; v < d.height; ++v) {
    const auto* row = reinterpret_cast<const openni::DepthPixel*>(base + static_cast<std::size_t>(v) * stride);
    for (int u = 0; u < d.width; ++u) d.depth[static_cast<std::size_t>(v) * d.width + u] = row[u];
  }
  d.intrinsics = K;
  d.intrinsics.width = d.width;
  d.intrinsics.height = d.height;
  d.timestamp_s = static_cast<double>(f.getTimestamp()) * 1e-6;
  d.source = source;
  return d;
}

void attach_color(DepthFrame& frame, const openni::VideoFrameRef& c) {
  if (!c.isValid() || c.getVideoMode().getPixelFormat() != openni::PIXEL_FORMAT_RGB888) return;
  if (c.getWidth() != frame.width || c.getHeight() != frame.height) return;
  const int stride = c.getStrideInBytes() > 0 ? c.getStrideInBytes() : frame.width * 3;
  if (c.getDataSize() < stride * (frame.height - 1) + frame.width * 3) return;
  frame.rgb.resize(static_cast<std::size_t>(frame.width) * frame.height * 3);
  const auto* base = static_cast<const std::uint8_t*>(c.getData());
  for (int v = 0; v < frame.height; ++v)
    std::memcpy(frame.rgb.data() + static_cast<std::size_t>(v) * frame.width * 3,
                base + static_cast<std::size_t>(v) * stride, static_cast<std::size_t>(frame.width) * 3);
}

bool wait_for_frame(openni::VideoStream& stream, int timeout_ms) {
  openni::VideoStream* streams[] = {&stream};
  int ready = -1;
  return openni::OpenNI::waitForAnyStream(streams, 1, &ready, timeout_ms) == openni::STATUS_OK && ready == 0;
}

}  // namespace tunnelmap::openni2
