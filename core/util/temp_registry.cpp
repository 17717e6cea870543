#include "core/util/temp_registry.h"

#include <signal.h>
#include <spawn.h>
#include <unistd.h>

#include <condition_variable>
#include <cstdio>
#include <mutex>
#include <set>
#include <stdexcept>
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

// Creations in progress (registered, `make` still running), the cleanup's wait for them, and
// whether an interrupt has come. Guarded by registry_mutex().
struct Creations {
  int running = 0;
  bool interrupted = false;
  std::condition_variable done;
};
Creations& creations() {
  static Creations c;
  return c;
}
thread_local int creating_depth = 0;  // this thread is inside `make` (a nested creation goes on)

sigset_t interrupt_signals() {
  sigset_t set;
  sigemptyset(&set);
  sigaddset(&set, SIGINT);
  sigaddset(&set, SIGTERM);
  return set;
}

// Moves `p` out of the way of threads still writing into it before emptying it: a write into
// the old path then fails (its folder is gone) instead of adding files while the folder is
// emptied. A folder such a thread recreates (create_directories) is moved and removed again.
void remove_under_writers(const fs::path& p) {
  const fs::path trash = p.parent_path() / (p.filename().string() + ".interrupted-" + std::to_string(::getpid()));
  for (int attempt = 0; attempt < 10; ++attempt) {
    std::error_code ec;
    if (!fs::exists(fs::symlink_status(p, ec))) return;
    fs::rename(p, trash, ec);
    const fs::path& victim = ec ? p : trash;
    fs::remove_all(victim, ec);
    if (victim == trash && fs::exists(fs::symlink_status(trash, ec))) fs::remove_all(trash, ec);
  }
}

[[noreturn]] void clean_up_and_exit(int signal, const std::string& program) {
  // First every creation in progress finishes (its path then exists and is registered); new
  // ones wait. Then the lock is held until _exit: no other thread can register (and then
  // create) a new temporary after the sweep.
  std::unique_lock<std::mutex> lock(registry_mutex());
  Creations& c = creations();
  c.interrupted = true;
  c.done.wait(lock, [&] { return c.running == 0; });
  for (const fs::path& p : live_paths()) remove_under_writers(p);
  std::fprintf(stderr, "%s: interrupted by %s; temporary files removed, earlier outputs kept\n", program.c_str(),
               signal == SIGINT ? "SIGINT" : "SIGTERM");
  std::fflush(stderr);
  _exit(128 + signal);
}

}  // namespace

void TempRegistry::create(const fs::path& path, const std::function<void()>& make) {
  const fs::path absolute = fs::absolute(path);
  Creations& c = creations();
  {
    std::unique_lock<std::mutex> lock(registry_mutex());
    // After an interrupt only creations nested in a running one go on (the cleanup waits for
    // the outer one); any other waits here for the exit.
    if (creating_depth == 0) c.done.wait(lock, [&] { return !c.interrupted; });
    live_paths().insert(absolute);
    ++c.running;
  }
  struct Finish {
    Creations& c;
    ~Finish() {
      --creating_depth;
      const std::lock_guard<std::mutex> lock(registry_mutex());
      if (--c.running == 0) c.done.notify_all();
    }
  };
  ++creating_depth;
  const Finish finish{c};
  make();
}

namespace {
void forget(const fs::path& path) {  // the caller holds registry_mutex()
  auto& paths = live_paths();
  const auto it = paths.find(fs::absolute(path));
  if (it != paths.end()) paths.erase(it);
}
}  // namespace

void TempRegistry::remove(const fs::path& path) {
  const std::lock_guard<std::mutex> lock(registry_mutex());
  forget(path);
}

void TempRegistry::publish(const fs::path& path, const std::function<bool()>& publish) {
  std::unique_lock<std::mutex> lock(registry_mutex());
  Creations& c = creations();
  if (c.interrupted) {
    if (creating_depth > 0) throw std::runtime_error("interrupted");
    c.done.wait(lock, [] { return false; });  // the cleanup removes `path` and exits
  }
  if (publish()) forget(path);
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
