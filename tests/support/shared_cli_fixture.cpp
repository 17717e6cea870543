#include "tests/support/shared_cli_fixture.h"

#include <fstream>

#include "core/util/build_paths.h"

namespace tunnelmap::testing {

namespace {

std::string with_dir(std::string args, const std::string& dir) {
  const std::string quoted = "'" + dir + "'";  // the build tree may lie under a path with spaces
  for (std::size_t at = args.find("{dir}"); at != std::string::npos; at = args.find("{dir}", at + quoted.size()))
    args.replace(at, 5, quoted);
  return args;
}

// What the products depend on: the command lines (with "{dir}" unexpanded, the same for every
// process), the CLI that ran them and the test program that asked for them.
std::string fingerprint(const std::string& name, const std::vector<CliStep>& steps) {
  std::string f = name + "\n" + file_stamp(TUNNELMAP_CLI_PATH) + "\n" + test_binary_stamp() + "\n";
  for (const CliStep& s : steps) f += s.key + ": " + s.args + "\n";
  return f;
}

bool keep(const std::filesystem::path& dir, const std::string& key, const CliRun& run) {
  std::ofstream code(dir / (key + ".exit")), out(dir / (key + ".out"), std::ios::binary),
      err(dir / (key + ".err"), std::ios::binary);
  code << run.exit_code;
  out << run.out;
  err << run.err;
  code.close(), out.close(), err.close();
  return code && out && err;  // a full disk must fail the make, not keep a truncated run
}

}  // namespace

SharedFixture shared_cli_fixture(const std::string& name, const std::vector<CliStep>& steps) {
  return shared_fixture(name, fingerprint(name, steps), [&](const std::filesystem::path& dir) -> std::string {
    for (const CliStep& s : steps) {
      const CliRun run = run_cli(with_dir(s.args, dir.string()));
      if (run.exit_code != 0)
        return "tunnelmap-cli " + s.key + " exited " + std::to_string(run.exit_code) + ": " + run.err;
      if (!keep(dir, s.key, run)) return "cannot keep the run of " + s.key + " in " + dir.string();
    }
    return "";
  });
}

CliRun kept_cli_run(const SharedFixture& fixture, const std::string& key) {
  CliRun run;
  std::ifstream(fixture.file(key + ".exit")) >> run.exit_code;
  run.out = slurp(fixture.file(key + ".out"));
  run.err = slurp(fixture.file(key + ".err"));
  return run;
}

}  // namespace tunnelmap::testing
