#pragma once
// Enumerates the OpenNI2 devices (real cameras through the installed drivers, the simulated
// tunnel camera through libTunnelMapSim when its driver folder is in use).
#include <string>
#include <vector>

namespace tunnelmap::openni2 {

struct VideoModeInfo {
  std::string sensor;  // "depth" | "color" | "ir"
  int width = 0, height = 0, fps = 0;
  std::string pixel_format;  // e.g. "DEPTH_1_MM", "RGB888"
};

struct DeviceDescription {
  std::string uri, name, vendor;
  int usb_vendor_id = 0, usb_product_id = 0;
  std::vector<VideoModeInfo> modes;  // empty when the device could not be opened to ask
};

// InputError("OpenNI2", ...) when OpenNI2 cannot be initialised.
std::vector<DeviceDescription> list_devices(bool with_modes = true);

std::string pixel_format_name(int format);

}  // namespace tunnelmap::openni2
