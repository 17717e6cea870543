// `tunnelmap-cli devices`: the OpenNI2 devices with URI, name, vendor and video modes.
#include <cstdio>

#include "app/cli/commands.h"
#include "sensors/openni/device_list.h"

namespace tunnelmap::cli {

void add_devices_command(CLI::App& app, CliContext& ctx) {
  auto* cmd = app.add_subcommand("devices", "List OpenNI2 depth cameras (URI, name, vendor, video modes)");
  cmd->callback([&ctx] {
    const auto devices = openni2::list_devices();
    if (devices.empty()) std::printf("no OpenNI2 devices found\n");
    for (const auto& d : devices) {
      std::printf("%s\n  name: %s\n  vendor: %s\n", d.uri.c_str(), d.name.c_str(), d.vendor.c_str());
      if (d.usb_vendor_id != 0 || d.usb_product_id != 0)
        std::printf("  usb: %04x:%04x\n", d.usb_vendor_id, d.usb_product_id);
      for (const auto& m : d.modes)
        std::printf("  %s: %dx%d @ %d fps %s\n", m.sensor.c_str(), m.width, m.height, m.fps, m.pixel_format.c_str());
    }
    ctx.exit_code = 0;
  });
}

}  // namespace tunnelmap::cli
