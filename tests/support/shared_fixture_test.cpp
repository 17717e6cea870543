// The shared fixture: made once however many processes or threads ask at the same time, made
// anew when what made it changes, never kept when its maker failed; CLI runs kept whole.
#include <gtest/gtest.h>

#include <sys/wait.h>
#include <unistd.h>

#include <atomic>
#include <chrono>
#include <fstream>
#include <thread>
#include <vector>

#include "tests/support/cli_runner.h"
#include "tests/support/io_temp_dir.h"
#include "tests/support/shared_cli_fixture.h"
#include "tests/support/shared_fixture.h"

namespace tunnelmap::testing {
namespace {

namespace fs = std::filesystem;

// A maker that takes a while (so a second caller arrives while it runs), notes each call in
// `log` (appended, so calls from several processes all count) and writes one product.
FixtureMaker slow_maker(const std::string& log) {
  return [log](const fs::path& dir) {
    std::ofstream(log, std::ios::app) << "made\n";
    std::this_thread::sleep_for(std::chrono::milliseconds(300));
    std::ofstream(dir / "product.txt") << "complete";
    return std::string();
  };
}

int entries(const fs::path& dir) {
  int n = 0;
  for ([[maybe_unused]] const auto& e : fs::directory_iterator(dir)) ++n;
  return n;
}

TEST(SharedFixture, TwoProcessesAskingAtOnceMakeItOnceAndBothReadItWhole) {
  IoTempDir tmp;
  const std::string log = tmp.file("makers.log");
  auto ask = [&] { return shared_fixture_in(tmp.path() / "root", "walk", "fp", slow_maker(log)); };
  const pid_t child = ::fork();
  ASSERT_GE(child, 0);
  if (child == 0) {  // exit 0 made it, 1 reused it, 2 saw it incomplete
    const SharedFixture f = ask();
    _exit(f.ok() && slurp(f.file("product.txt")) == "complete" ? (f.reused ? 1 : 0) : 2);
  }
  const SharedFixture mine = ask();
  int status = 0;
  ASSERT_EQ(::waitpid(child, &status, 0), child);
  ASSERT_TRUE(WIFEXITED(status));
  ASSERT_NE(WEXITSTATUS(status), 2);
  ASSERT_TRUE(mine.ok()) << mine.error;
  EXPECT_EQ(slurp(mine.file("product.txt")), "complete");
  EXPECT_NE(mine.reused, WEXITSTATUS(status) == 1) << "exactly one of the two made it";
  EXPECT_EQ(slurp(log), "made\n");
}

TEST(SharedFixture, ThreadsAskingAtOnceMakeItOnce) {
  IoTempDir tmp;
  const std::string log = tmp.file("makers.log");
  std::vector<SharedFixture> got(4);
  std::vector<std::thread> threads;
  for (SharedFixture& g : got)
    threads.emplace_back([&] { g = shared_fixture_in(tmp.path() / "root", "walk", "fp", slow_maker(log)); });
  for (std::thread& t : threads) t.join();
  int reused = 0;
  for (const SharedFixture& g : got) {
    ASSERT_TRUE(g.ok()) << g.error;
    EXPECT_EQ(g.dir, got[0].dir);
    EXPECT_EQ(slurp(g.file("product.txt")), "complete");
    reused += g.reused;
  }
  EXPECT_EQ(reused, 3);
  EXPECT_EQ(slurp(log), "made\n");
}

TEST(SharedFixture, AChangedFingerprintMakesItAnewAndDropsTheOldOne) {
  IoTempDir tmp;
  const std::string log = tmp.file("makers.log");
  const fs::path root = tmp.path() / "root";
  const SharedFixture a = shared_fixture_in(root, "walk", "cli 100 1", slow_maker(log));
  const SharedFixture again = shared_fixture_in(root, "walk", "cli 100 1", slow_maker(log));
  EXPECT_FALSE(a.reused);
  EXPECT_TRUE(again.reused);
  EXPECT_EQ(again.dir, a.dir);
  const SharedFixture rebuilt = shared_fixture_in(root, "walk", "cli 100 2", slow_maker(log));
  ASSERT_TRUE(rebuilt.ok()) << rebuilt.error;
  EXPECT_FALSE(rebuilt.reused);
  EXPECT_NE(rebuilt.dir, a.dir);
  EXPECT_FALSE(fs::exists(a.dir));
  EXPECT_EQ(entries(root / "walk"), 1);
  EXPECT_EQ(slurp(log), "made\nmade\n");
  // Another name is another fixture, even with the same fingerprint.
  EXPECT_FALSE(shared_fixture_in(root, "girder", "cli 100 2", slow_maker(log)).reused);
}

TEST(SharedFixture, AFailedOrThrowingMakerIsNotKept) {
  IoTempDir tmp;
  const fs::path root = tmp.path() / "root";
  int calls = 0;
  const SharedFixture failed = shared_fixture_in(root, "walk", "fp", [&](const fs::path& dir) {
    ++calls;
    std::ofstream(dir / "product.txt") << "half";
    return std::string("simulate exited 3");
  });
  EXPECT_FALSE(failed.ok());
  EXPECT_EQ(failed.error, "simulate exited 3");
  EXPECT_TRUE(failed.dir.empty());
  EXPECT_EQ(entries(root / "walk"), 0) << "the half-made folder is removed";
  const SharedFixture threw = shared_fixture_in(root, "walk", "fp", [&](const fs::path&) -> std::string {
    ++calls;
    throw std::runtime_error("disk full");
  });
  EXPECT_NE(threw.error.find("disk full"), std::string::npos) << threw.error;
  const SharedFixture made = shared_fixture_in(root, "walk", "fp", [&](const fs::path& dir) {
    ++calls;
    std::ofstream(dir / "product.txt") << "complete";
    return std::string();
  });
  ASSERT_TRUE(made.ok()) << made.error;
  EXPECT_FALSE(made.reused);
  EXPECT_EQ(calls, 3);
  EXPECT_EQ(slurp(made.file("product.txt")), "complete");
}

TEST(SharedFixture, AFolderAMakerLeftWhenItDiedIsRemovedNotRead) {
  IoTempDir tmp;
  const fs::path root = tmp.path() / "root";
  const pid_t child = ::fork();
  ASSERT_GE(child, 0);
  if (child == 0) _exit(0);
  ASSERT_EQ(::waitpid(child, nullptr, 0), child);  // a process id that no longer runs
  const fs::path left = root / "walk" / (".tmp-" + std::to_string(child) + "-0");
  fs::create_directories(left);
  const SharedFixture f = shared_fixture_in(root, "walk", "fp", slow_maker(tmp.file("log")));
  ASSERT_TRUE(f.ok()) << f.error;
  EXPECT_FALSE(f.reused);
  EXPECT_FALSE(fs::exists(left));
}

TEST(SharedCliFixture, KeepsEachStepsExitCodeAndOutputsAndNeverAFailedRun) {
  const SharedFixture f = shared_cli_fixture("SharedCliFixture.params", {{"params", "params --json"}});
  ASSERT_TRUE(f.ok()) << f.error;
  const CliRun kept = kept_cli_run(f, "params"), fresh = run_cli("params --json");
  EXPECT_EQ(kept.exit_code, 0);
  EXPECT_EQ(kept.out, fresh.out);
  EXPECT_EQ(kept.err, fresh.err);
  const std::vector<CliStep> failing = {{"sim", "simulate {dir}/walk --frames 2 --quiet"},
                                        {"map", "map {dir}/missing"}};
  const SharedFixture bad = shared_cli_fixture("SharedCliFixture.failing", failing);
  EXPECT_FALSE(bad.ok());
  EXPECT_EQ(bad.error.rfind("tunnelmap-cli map exited 3: ", 0), 0u) << bad.error;
  EXPECT_FALSE(shared_cli_fixture("SharedCliFixture.failing", failing).reused) << "made again, not kept";
}

}  // namespace
}  // namespace tunnelmap::testing
