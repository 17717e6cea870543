// tunnelmap-cli: headless front end of the pipeline. Exit codes: 0 ok, 2 bad usage,
// 3 unreadable or invalid input; every error is one line on stderr naming file and problem.
#include <iostream>
#include <string>

#include "app/cli/commands.h"
#include "app/cli/error_line.h"
#include "core/util/error.h"
#include "core/util/temp_registry.h"
#include "sensors/openni/register_openni.h"

int main(int argc, char** argv) {
  using namespace tunnelmap;
  if (argc >= 2 && std::string(argv[1]) == "render") return cli::run_render_verb(argc, argv);
  // Before any thread starts: SIGINT/SIGTERM remove the run's temporary files, exit 130/143.
  install_interrupt_cleanup("tunnelmap-cli");
  CLI::App app{"TunnelMap: maps rectangular steel tunnels from depth frames (PG&C)",
               "tunnelmap-cli"};
  app.set_version_flag("--version", std::string("tunnelmap-cli ") + TUNNELMAP_VERSION);
  app.require_subcommand(1);
  cli::CliContext ctx;
  cli::add_detect_command(app, ctx);
  cli::add_planes_command(app, ctx);
  cli::add_params_command(app, ctx);
  cli::add_simulate_command(app, ctx);
  cli::add_fuse_command(app, ctx);
  cli::add_map_command(app, ctx);
  cli::add_convert_command(app, ctx);
  cli::add_topics_command(app, ctx);
  cli::add_evaluate_command(app, ctx);
  cli::add_devices_command(app, ctx);
  cli::add_record_command(app, ctx);
  openni2::register_openni_inputs();  // INPUT may be an .oni recording
  app.footer("Also: tunnelmap-cli render INPUT --screenshot FILE.png [--view along|side|top] [--size WxH] [--layers ...]\n"
             "      (headless OSMesa rendering; see tunnelmap-cli render --help)");
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForVersion& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    std::cerr << "tunnelmap-cli: " << cli::error_line(e.what()) << " (see --help)\n";
    return 2;
  } catch (const ParameterError& e) {
    std::cerr << "tunnelmap-cli: " << cli::error_line(e.what()) << "\n";
    return 2;
  } catch (const InputError& e) {
    std::cerr << "tunnelmap-cli: " << cli::error_line(e.what()) << "\n";
    return 3;
  } catch (const std::exception& e) {
    std::cerr << "tunnelmap-cli: internal error: " << cli::error_line(e.what()) << "\n";
    return 4;
  }
  return ctx.exit_code;
}
