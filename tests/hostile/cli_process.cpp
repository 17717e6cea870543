#include "tests/hostile/cli_process.h"

#include <fcntl.h>
#include <signal.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <fstream>
#include <sstream>
#include <thread>

#include "core/util/build_paths.h"
#include "tests/allocation/sanitizer_detect.h"
#include "tests/support/io_temp_dir.h"

namespace tunnelmap::hostile {

namespace {

std::string slurp(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// In the child between fork and exec: only async-signal-safe calls.
[[noreturn]] void exec_child(const std::vector<char*>& argv, char* const* envp, const Limits& limits,
                             const std::string& out, const std::string& err, const std::string& working_dir) {
#ifndef TUNNELMAP_SANITIZED
  const rlimit as{limits.address_space_bytes, limits.address_space_bytes};
  setrlimit(RLIMIT_AS, &as);
#endif
  if (limits.file_size_bytes) {
    const rlimit fsize{limits.file_size_bytes, limits.file_size_bytes};
    setrlimit(RLIMIT_FSIZE, &fsize);
    signal(SIGXFSZ, SIG_IGN);  // an ignored signal stays ignored across exec
  }
  if (!working_dir.empty() && chdir(working_dir.c_str()) != 0) _exit(126);
  const int in_fd = open("/dev/null", O_RDONLY);
  const int out_fd = open(out.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  const int err_fd = open(err.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  dup2(in_fd, 0);
  dup2(out_fd, 1);
  dup2(err_fd, 2);
  execve(argv[0], argv.data(), envp);
  _exit(127);
}

// True once the process's main thread blocks `signal` (/proc/PID/status, "SigBlk:" in hex).
bool blocks(pid_t pid, int signal) {
  std::ifstream status("/proc/" + std::to_string(pid) + "/status");
  for (std::string line; std::getline(status, line);)
    if (line.rfind("SigBlk:", 0) == 0) return (std::stoull(line.substr(7), nullptr, 16) >> (signal - 1)) & 1;
  return false;
}

// The test's environment with `extra` ("NAME=VALUE") added, a name given there replacing its own.
std::vector<std::string> child_environment(const std::vector<std::string>& extra) {
  std::vector<std::string> env;
  for (char** e = environ; *e != nullptr; ++e) {
    const std::string entry = *e;
    const std::string name = entry.substr(0, entry.find('=') + 1);
    bool replaced = false;
    for (const std::string& x : extra) replaced = replaced || x.rfind(name, 0) == 0;
    if (!replaced) env.push_back(entry);
  }
  env.insert(env.end(), extra.begin(), extra.end());
  return env;
}

}  // namespace

Outcome run_cli(const std::vector<std::string>& args, const Limits& limits, const std::string& working_dir,
                const std::vector<std::string>& environment) {
  testing::IoTempDir io;
  const std::string out = io.file("stdout"), err = io.file("stderr");
  std::vector<std::string> all{TUNNELMAP_CLI_PATH};
  all.insert(all.end(), args.begin(), args.end());
  std::vector<char*> argv;
  for (std::string& a : all) argv.push_back(a.data());
  argv.push_back(nullptr);
  std::vector<std::string> env = child_environment(environment);
  std::vector<char*> envp;
  for (std::string& e : env) envp.push_back(e.data());
  envp.push_back(nullptr);

  const auto start = std::chrono::steady_clock::now();
  const pid_t pid = fork();
  if (pid == 0) exec_child(argv, envp.data(), limits, out, err, working_dir);
  Outcome o;
  int status = 0;
  rusage usage{};
  while (wait4(pid, &status, WNOHANG, &usage) == 0) {
    if (limits.signal && !o.signal_sent && blocks(pid, limits.signal) &&
        (!limits.signal_when || limits.signal_when())) {
      kill(pid, limits.signal);
      o.signal_sent = true;
    }
    if (std::chrono::steady_clock::now() - start > limits.timeout && !o.timed_out) {
      kill(pid, SIGKILL);
      o.timed_out = true;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
  }
  if (WIFEXITED(status)) o.exit_code = WEXITSTATUS(status);
  if (WIFSIGNALED(status)) o.term_signal = WTERMSIG(status);
  o.max_rss_kb = usage.ru_maxrss;
  o.out = slurp(out);
  o.err = slurp(err);
  return o;
}

}  // namespace tunnelmap::hostile
