#pragma once
// Output options of the commands, one set of rules for all (core/util/output_path.h): an empty
// path is refused while parsing, and before any work every output is checked and compared
// with the inputs and with the other outputs.
#include <CLI/CLI.hpp>
#include <string>
#include <vector>

namespace tunnelmap::cli {

// Adds an output file option; `--json ''` is bad usage, not "no output".
CLI::Option* add_output_option(CLI::App* cmd, const std::string& name, std::string& path,
                               const std::string& description);

// check_output_path on every non-empty output, then check_outputs_apart: OutputPathError (exit 2).
void check_outputs(const std::vector<std::string>& inputs, const std::vector<std::string>& outputs);

}  // namespace tunnelmap::cli
