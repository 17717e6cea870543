#include "core/util/temp_registry.h"

#include <signal.h>
#include <spawn.h>
#include <unistd.h>

#include <cstdio>
#include <mutex>
#include <set>
#include <thread>

namespace tunnelmap {

namespace fs = std::filesystem;

namespace {

std::mutex& registry_mutex() {
  static std::mutex m;
  return m;
}

std::multiset<fs::path>& live_paths() {
  static std::multiset<fs::path> paths;
  return paths;
}

sigset_t interrupt_signals() {
  sigset_t set;
  sigemptyset(&set);
  sigaddset(&set, SIGINT);
  sigaddset(&set, SIGTERM);
  return set;
}

[[noreturn]] void clean_up_and_exit(int signal, const std::string& program) {
  // Holding the lock until _exit: no other thread can register (and then create) a new
  // temporary after the sweep.
  registry_mutex().lock();
  for (const fs::path& p : live_paths()) {
    // Other threads still run: a file written into a folder while it is being emptied makes
    // the first attempt fail ("not empty"); the second finds the folder quiet.
    std::error_code ec;
    if (fs::remove_all(p, ec) == static_cast<std::uintmax_t>(-1) || ec) fs::remove_all(p, ec);
  }
  std::fprintf(stderr, "%s: interrupted by %s; temporary files removed, earlier outputs kept\n", program.c_str(),
               signal == SIGINT ? "SIGINT" : "SIGTERM");
  std::fflush(stderr);
  _exit(128 + signal);
}

}  // namespace

void TempRegistry::add(const fs::path& path) {
  const std::lock_guard<std::mutex> lock(registry_mutex());
  live_paths().insert(fs::absolute(path));
}

void TempRegistry::remove(const fs::path& path) {
  const std::lock_guard<std::mutex> lock(registry_mutex());
  auto& paths = live_paths();
  const auto it = paths.find(fs::absolute(path));
  if (it != paths.end()) paths.erase(it);
}

void install_interrupt_cleanup(const std::string& program) {
  const sigset_t set = interrupt_signals();
  pthread_sigmask(SIG_BLOCK, &set, nullptr);
  std::thread([set, program] {
    int signal = 0;
    while (sigwait(&set, &signal) != 0) {
    }
    clean_up_and_exit(signal, program);
  }).detach();
}

void unblock_interrupts_for_child(posix_spawnattr_t* attr) {
  sigset_t none;
  sigemptyset(&none);
  posix_spawnattr_setsigmask(attr, &none);
  short flags = 0;
  posix_spawnattr_getflags(attr, &flags);
  posix_spawnattr_setflags(attr, flags | POSIX_SPAWN_SETSIGMASK);
}

}  // namespace tunnelmap
