#pragma once
// Shared fixtures made by running tunnelmap-cli (tests/support/shared_fixture.h): each step's exit
// code, stdout and stderr are kept beside its outputs, so a test reads the run as if it had made
// it itself.
#include <string>
#include <vector>

#include "tests/support/cli_runner.h"
#include "tests/support/shared_fixture.h"

namespace tunnelmap::testing {

struct CliStep {
  std::string key;   // names the kept run: KEY.exit, KEY.out and KEY.err in the fixture
  std::string args;  // the CLI's arguments; "{dir}" stands for the fixture's folder
};

// Runs the steps in order into the fixture NAME, once per build of the CLI and the test program.
// A step that exits non-zero fails the make (the error names the step, its exit code and stderr),
// so only complete runs are kept.
SharedFixture shared_cli_fixture(const std::string& name, const std::vector<CliStep>& steps);

// The kept run of step KEY of a made fixture.
CliRun kept_cli_run(const SharedFixture& fixture, const std::string& key);

}  // namespace tunnelmap::testing
