#pragma once
// Runs the real tunnelmap-cli in a child process under the limits a hostile input must not
// break through: an address-space limit, a timeout, optionally a file-size limit (a full disk)
// and a signal sent while it works.
#include <chrono>
#include <functional>
#include <string>
#include <vector>

namespace tunnelmap::hostile {

struct Limits {
  std::chrono::milliseconds timeout{60000};
  // RLIMIT_AS of the child; not applied under a sanitizer, which reserves terabytes of
  // address space up front.
  unsigned long long address_space_bytes = 3ull << 30;
  // RLIMIT_FSIZE of the child (0 = none): writes past it fail with EFBIG, as on a full disk
  // (SIGXFSZ is ignored, as `ulimit -f` in a shell that traps it).
  unsigned long long file_size_bytes = 0;
  // Sent once when `signal_when` first returns true (polled every few milliseconds), asked only
  // once the program blocks the signal (main() has begun: a signal before that would test the
  // dynamic loader, not the program).
  int signal = 0;
  std::function<bool()> signal_when;
};

struct Outcome {
  int exit_code = -1;    // -1 when killed by a signal
  int term_signal = 0;   // the signal that killed it, 0 if it exited
  bool timed_out = false;
  bool signal_sent = false;
  long max_rss_kb = 0;
  std::string out, err;
};

// `environment`: "NAME=VALUE" entries added to (or replacing those of) the test's own.
Outcome run_cli(const std::vector<std::string>& args, const Limits& limits = {},
                const std::string& working_dir = {}, const std::vector<std::string>& environment = {});

}  // namespace tunnelmap::hostile
