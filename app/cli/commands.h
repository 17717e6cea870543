#pragma once
// Each tunnelmap-cli subcommand lives in its own cmd_*.cpp and registers itself here.
// A command's callback stores its exit code in `CliContext::exit_code`; errors are thrown
// (InputError -> exit 3, ParameterError / CLI11 errors -> exit 2) and reported by main().
#include <CLI/CLI.hpp>

namespace tunnelmap::cli {

struct CliContext {
  int exit_code = 0;
};

void add_detect_command(CLI::App& app, CliContext& ctx);
void add_planes_command(CLI::App& app, CliContext& ctx);
void add_params_command(CLI::App& app, CliContext& ctx);
void add_simulate_command(CLI::App& app, CliContext& ctx);
void add_fuse_command(CLI::App& app, CliContext& ctx);
void add_map_command(CLI::App& app, CliContext& ctx);
void add_convert_command(CLI::App& app, CliContext& ctx);
void add_topics_command(CLI::App& app, CliContext& ctx);  // ROS bags (core/recordings)
void add_evaluate_command(CLI::App& app, CliContext& ctx);
void add_devices_command(CLI::App& app, CliContext& ctx);  // OpenNI2 (sensors/openni)
void add_record_command(CLI::App& app, CliContext& ctx);   // OpenNI2 (sensors/openni)

// `render` is handed to the tunnelmap-render executable before CLI11 parses (see cmd_render.cpp).
int run_render_verb(int argc, char** argv);

}  // namespace tunnelmap::cli
