// `tunnelmap-cli params`: prints the parameter table (the single source of truth).
#include <cstdio>
#include <iostream>
#include <nlohmann/json.hpp>

#include "app/cli/commands.h"
#include "core/params/parameters.h"

namespace tunnelmap::cli {

void add_params_command(CLI::App& app, CliContext& ctx) {
  auto* cmd = app.add_subcommand("params", "Print every tunable parameter: key, default, unit, range, description");
  static bool as_json = false;
  static std::string params_file;
  cmd->add_flag("--json", as_json, "Print the table as JSON");
  cmd->add_option("--params", params_file, "Also show the values of this preset");
  cmd->callback([&ctx] {
    Parameters current;
    if (!params_file.empty()) current.load_json_file(params_file);
    if (as_json) {
      nlohmann::json j = nlohmann::json::array();
      for (const auto& s : parameter_table())
        j.push_back({{"key", s.key}, {"unit", s.unit}, {"default", s.default_value}, {"min", s.min},
                     {"max", s.max}, {"step", s.step}, {"integer", s.integer},
                     {"stage", stage_name(s.stage)}, {"label", s.label},
                     {"description", s.description}, {"value", current.get(s.key)}});
      std::cout << j.dump(2) << "\n";
    } else {
      std::printf("%-28s %10s %-7s %-22s %s\n", "key", "default", "unit", "range", "description");
      for (const auto& s : parameter_table()) {
        char range[64];
        std::snprintf(range, sizeof range, "[%g, %g]", s.min, s.max);
        char def[32];
        std::snprintf(def, sizeof def, "%g", s.default_value);
        std::printf("%-28s %10s %-7s %-22s %s", s.key.c_str(), def, s.unit.c_str(), range, s.description.c_str());
        if (!params_file.empty() && current.get(s.key) != s.default_value)
          std::printf(" (preset: %g)", current.get(s.key));
        std::printf("\n");
      }
    }
    ctx.exit_code = 0;
  });
}

}  // namespace tunnelmap::cli
