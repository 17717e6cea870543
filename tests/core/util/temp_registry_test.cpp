// An interrupt that comes between a temporary's registration and its creation: the cleanup waits
// for the creation, so the path never appears after the sweep; and a finished temporary is
// never renamed over an earlier output once an interrupt has come. Run in a child process, since the
// cleanup ends the process.
#include "core/util/temp_registry.h"

#include <fcntl.h>
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <string>
#include <thread>

#include "tests/support/io_temp_dir.h"

namespace tunnelmap {
namespace {

namespace fs = std::filesystem;

// Forks; the child installs the cleanup, then runs `body`. Returns the child's exit status.
int run_in_child(const std::function<void()>& body) {
  const pid_t pid = fork();
  if (pid == 0) {
    const int null_fd = open("/dev/null", O_WRONLY);
    dup2(null_fd, 2);  // the cleanup's one line
    install_interrupt_cleanup("test");
    body();
    _exit(0);
  }
  int status = 0;
  waitpid(pid, &status, 0);
  return WIFEXITED(status) ? WEXITSTATUS(status) : -WTERMSIG(status);
}

TEST(TempRegistry, AnInterruptDuringACreationRemovesWhatItCreated) {
  testing::IoTempDir tmp;
  const fs::path file = tmp.path() / "out.ply.tmp-1", finished = tmp.path() / "creation-finished";
  const int status = run_in_child([&] {
    TempRegistry::create(file, [&] {
      kill(getpid(), SIGINT);  // taken by the watcher thread at once
      std::this_thread::sleep_for(std::chrono::milliseconds(300));  // a sweep now would miss the file
      std::ofstream(file) << "written after the signal";
      std::ofstream(finished) << "";  // not a temporary: stays
    });
    std::this_thread::sleep_for(std::chrono::seconds(10));  // the cleanup exits before this ends
  });
  EXPECT_EQ(status, 128 + SIGINT);
  EXPECT_TRUE(fs::exists(finished)) << "the cleanup exited in the middle of the creation";
  EXPECT_FALSE(fs::exists(file));
}

TEST(TempRegistry, ACreationAfterAnInterruptWaitsForTheExit) {
  testing::IoTempDir tmp;
  const fs::path file = tmp.path() / "late.tmp-2";
  const int status = run_in_child([&] {
    kill(getpid(), SIGTERM);
    std::this_thread::sleep_for(std::chrono::milliseconds(300));  // the cleanup is running or done
    TempRegistry::create(file, [&] { std::ofstream(file) << "never"; });
    _exit(0);
  });
  EXPECT_EQ(status, 128 + SIGTERM);
  EXPECT_FALSE(fs::exists(file));
}

TEST(TempRegistry, AnInterruptNeverLetsARunReplaceAnEarlierOutput) {
  // A temporary is written whole; then the signal comes while another thread still creates its
  // own, which the cleanup waits for. Renamed over the earlier output during that wait, the
  // finished temporary would escape the sweep: the interrupted run would replace the output.
  testing::IoTempDir tmp;
  const fs::path target = tmp.path() / "report.pdf", file = tmp.path() / "report.tmp-3.pdf";
  const fs::path other = tmp.path() / "mesh.tmp-4.ply";
  std::ofstream(target) << "old";
  const int status = run_in_child([&] {
    TempRegistry::create(file, [&] { std::ofstream(file) << "new"; });
    std::thread([&] {
      TempRegistry::create(other, [&] {
        std::this_thread::sleep_for(std::chrono::milliseconds(600));
        std::ofstream(other) << "mesh";
      });
    }).detach();
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
    kill(getpid(), SIGTERM);
    std::this_thread::sleep_for(std::chrono::milliseconds(100));  // the cleanup waits for `other`
    TempRegistry::publish(file, [&] {
      fs::rename(file, target);
      return true;
    });
    std::this_thread::sleep_for(std::chrono::seconds(10));
  });
  EXPECT_EQ(status, 128 + SIGTERM);
  std::string text;
  std::ifstream(target) >> text;
  EXPECT_EQ(text, "old");
  EXPECT_FALSE(fs::exists(file));
  EXPECT_FALSE(fs::exists(other));
}

}  // namespace
}  // namespace tunnelmap
