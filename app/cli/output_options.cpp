#include "app/cli/output_options.h"

#include "core/util/output_path.h"

namespace tunnelmap::cli {

CLI::Option* add_output_option(CLI::App* cmd, const std::string& name, std::string& path,
                               const std::string& description) {
  const CLI::Validator non_empty(
      [](std::string& value) { return value.empty() ? std::string("empty output path") : std::string(); },
      "FILE");
  return cmd->add_option(name, path, description)->check(non_empty);
}

void check_outputs(const std::vector<std::string>& inputs, const std::vector<std::string>& outputs) {
  for (const std::string& out : outputs)
    if (!out.empty()) check_output_path(out);
  check_outputs_apart(inputs, outputs);
}

}  // namespace tunnelmap::cli
