// libFuzzer target: the message decoders (core/recordings/ros_messages, message_reader) and
// the image decoders behind them, on arbitrary bytes in both wire formats (CDR and ROS 1).
// A decoder either returns values that fit its message or throws TruncatedData.
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <string>

#include "core/recordings/byte_cursor.h"
#include "core/recordings/depth_image_decode.h"
#include "core/recordings/ros_messages.h"

namespace {

using namespace tunnelmap::recordings;

template <typename Decode>
void attempt(Decode&& decode) {
  try {
    decode();
  } catch (const TruncatedData&) {
  }
}

void check_image_pixels(const RosImage& img) {
  attempt([&] {
    const DecodedDepth d = decode_depth_image(img);
    if (d.depth.size() != static_cast<std::size_t>(d.width) * d.height) std::abort();
  });
  attempt([&] {
    int w = 0, h = 0;
    const auto rgb = decode_color_image(img, w, h);
    if (rgb.size() != static_cast<std::size_t>(w) * h * 3) std::abort();
  });
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string topic = "/fuzz";
  const MessageView m{topic, 0, data, size};
  for (MessageEncoding e : {MessageEncoding::Cdr, MessageEncoding::Ros1}) {
    attempt([&] {
      const RosImage img = decode_image(m, e);
      if (img.data + img.size > data + size) std::abort();
      check_image_pixels(img);
    });
    attempt([&] {
      const RosCompressedImage img = decode_compressed_image(m, e);
      if (img.size > size) std::abort();
      attempt([&] { decode_compressed_depth(img, 4096LL * 4096LL); });
    });
    attempt([&] {
      const RosCameraInfo info = decode_camera_info(m, e);
      if (info.d.size() > size / 8) std::abort();
    });
    attempt([&] {
      for (const RosTransform& t : decode_tf_message(m, e))
        if (!t.transform.linear().allFinite()) std::abort();  // a rotation is always a unit quaternion
    });
    attempt([&] { decode_transform_stamped(m, e); });
    attempt([&] { decode_pose_stamped(m, e); });
    attempt([&] { decode_odometry(m, e); });
    attempt([&] {
      const RosImu imu = decode_imu(m, e);
      if (imu.linear_acceleration && !imu.linear_acceleration->allFinite()) std::abort();  // kept only when finite
    });
  }
  return 0;
}
