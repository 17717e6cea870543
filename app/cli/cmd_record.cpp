// `tunnelmap-cli record [--device URI] --frames N OUT.oni`: records depth (+ colour) from a live
// OpenNI2 device to an OpenNI2 recording, written atomically (temporary file, then rename).
#include <cstdio>
#include <string>

#include "app/cli/commands.h"
#include "app/cli/input_options.h"
#include "sensors/openni/oni_recording.h"

namespace tunnelmap::cli {

namespace {
struct RecordOptions {
  std::string device = "default";
  int frames = 0;
  std::string out;
};
}  // namespace

void add_record_command(CLI::App& app, CliContext& ctx) {
  static RecordOptions o;
  auto* cmd = app.add_subcommand("record", "Record depth (+ colour) from an OpenNI2 device to an .oni file");
  cmd->add_option("OUT", o.out, "Output recording (.oni)")->required();
  cmd->add_option("--device", o.device, "Device URI (see `devices`; default: the first device)");
  cmd->add_option("--frames", o.frames, "Number of depth frames to record")->required()->check(CLI::PositiveNumber);
  cmd->callback([&ctx] {
    Progress progress(static_cast<std::size_t>(o.frames));
    const auto r = openni2::record_oni(o.device, o.frames, o.out,
                                       [&](int n) { progress.step(static_cast<std::size_t>(n)); });
    std::printf("recorded %d frames from %s to %s\n", r.frames, o.device.c_str(), o.out.c_str());
    ctx.exit_code = 0;
  });
}

}  // namespace tunnelmap::cli
