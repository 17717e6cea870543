#include "sensors/openni/device_list.h"

#include <OpenNI.h>

#include "sensors/openni/openni_context.h"

namespace tunnelmap::openni2 {

std::string pixel_format_name(int format) {
  switch (format) {
    case openni::PIXEL_FORMAT_DEPTH_1_MM: return "DEPTH_1_MM";
    case openni::PIXEL_FORMAT_DEPTH_100_UM: return "DEPTH_100_UM";
    case openni::PIXEL_FORMAT_SHIFT_9_2: return "SHIFT_9_2";
    case openni::PIXEL_FORMAT_SHIFT_9_3: return "SHIFT_9_3";
    case openni::PIXEL_FORMAT_RGB888: return "RGB888";
    case openni::PIXEL_FORMAT_YUV422: return "YUV422";
    case openni::PIXEL_FORMAT_GRAY8: return "GRAY8";
    case openni::PIXEL_FORMAT_GRAY16: return "GRAY16";
    case openni::PIXEL_FORMAT_JPEG: return "JPEG";
    case openni::PIXEL_FORMAT_YUYV: return "YUYV";
    default: return "format" + std::to_string(format);
  }
}

std::vector<DeviceDescription> list_devices(bool with_modes) {
  ensure_initialized();
  openni::Array<openni::DeviceInfo> infos;
  openni::OpenNI::enumerateDevices(&infos);
  std::vector<DeviceDescription> out;
  for (int i = 0; i < infos.getSize(); ++i) {
    const openni::DeviceInfo& info = infos[i];
    DeviceDescription d;
    d.uri = info.getUri();
    d.name = info.getName();
    d.vendor = info.getVendor();
    d.usb_vendor_id = info.getUsbVendorId();
    d.usb_product_id = info.getUsbProductId();
    if (with_modes) {
      openni::Device device;
      if (device.open(info.getUri()) == openni::STATUS_OK) {
        const std::pair<openni::SensorType, const char*> sensors[] = {
            {openni::SENSOR_DEPTH, "depth"}, {openni::SENSOR_COLOR, "color"}, {openni::SENSOR_IR, "ir"}};
        for (const auto& [type, name] : sensors) {
          const openni::SensorInfo* si = device.getSensorInfo(type);
          if (si == nullptr) continue;
          const auto& modes = si->getSupportedVideoModes();
          for (int m = 0; m < modes.getSize(); ++m)
            d.modes.push_back({name, modes[m].getResolutionX(), modes[m].getResolutionY(), modes[m].getFps(),
                               pixel_format_name(modes[m].getPixelFormat())});
        }
        device.close();
      }
    }
    out.push_back(std::move(d));
  }
  return out;
}

}  // namespace tunnelmap::openni2
