// Measures the two ways of surviving a damaged .oni recording (docs/robustness.md, "Checking
// .oni recordings or playing them in a child process"):
//   checked:  the product's way: core/io/oni_container's structural check, then OpenNI2's player
//             in the same process (OniFileSource);
//   child:    no check; OpenNI2's player runs in a forked child that sends the depth frames over a
//             pipe; a crash, an error or a hang (timeout) of the child becomes exit 3.
// On the unchanged recording and its 200 single-byte changes (tests/support/oni_variants.h) it
// counts each way's outcomes, and times opening and reading every frame of the unchanged one.
// Every run is made in a forked child here (a crash of the checked way must not end the
// measurement); the checked way's time is then measured in this process, as the product runs it.
//
//   LD_LIBRARY_PATH=build/openni2 build/bench/tunnelmap_oni_isolation REC.oni [--runs N] [--timeout-ms T]
#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <OpenNI.h>

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <functional>
#include <iterator>
#include <string>
#include <vector>

#include "core/io/input_options.h"
#include "core/io/oni_container.h"
#include "core/io/read_options.h"
#include "core/util/error.h"
#include "sensors/openni/oni_file_source.h"
#include "sensors/openni/openni_context.h"
#include "tests/support/oni_variants.h"

namespace {

using namespace tunnelmap;
using Clock = std::chrono::steady_clock;

// What the parent saw of one child run.
struct Run {
  enum Kind { Exit0, Exit3, Signal, Timeout } kind = Exit3;
  std::string frames;  // the depth frames' bytes, concatenated
  double ms = 0;
};

bool write_all(int fd, const void* data, std::size_t n) {
  const char* p = static_cast<const char*>(data);
  while (n > 0) {
    const ssize_t w = ::write(fd, p, n);
    if (w <= 0) return false;
    p += w;
    n -= static_cast<std::size_t>(w);
  }
  return true;
}

// The product's way, inside the child: check, then play every frame in this process.
int read_checked(const std::string& path, int out) {
  try {
    const openni2::OniFileSource source(path, ReadOptions());
    for (std::size_t i = 0; i < source.size(); ++i) {
      const DepthFrame f = source.load(i);
      const std::vector<std::uint16_t> raw(f.depth.begin(), f.depth.end());  // file units, as recorded
      if (!write_all(out, raw.data(), raw.size() * sizeof(raw[0]))) return 4;
    }
    return 0;
  } catch (const InputError&) {
    return 3;
  }
}

// The child way: OpenNI2's player as OniFileSource sets it up (manual speed, repeat on, colour and
// depth waited on together), without the check.
int read_unchecked(const std::string& path, int out) {
  try {
    openni2::ensure_initialized();
  } catch (const InputError&) {
    return 3;
  }
  openni::Device device;
  if (device.open(path.c_str()) != openni::STATUS_OK) return 3;
  openni::PlaybackControl* playback = device.getPlaybackControl();
  openni::VideoStream depth, color;
  if (!playback || depth.create(device, openni::SENSOR_DEPTH) != openni::STATUS_OK) return 3;
  playback->setRepeatEnabled(true);
  playback->setSpeed(-1.0f);
  const int frames = playback->getNumberOfFrames(depth);
  if (frames <= 0) return 3;
  if (device.hasSensor(openni::SENSOR_COLOR) && color.create(device, openni::SENSOR_COLOR) == openni::STATUS_OK &&
      color.start() != openni::STATUS_OK)
    color.destroy();
  if (depth.start() != openni::STATUS_OK) return 3;
  openni::VideoStream* streams[] = {&color, &depth};
  const int first = color.isValid() ? 0 : 1;
  for (int read = 0; read < frames;) {
    int ready = -1;
    openni::VideoFrameRef f;
    if (openni::OpenNI::waitForAnyStream(streams + first, 2 - first, &ready, 2000) != openni::STATUS_OK) return 3;
    if (streams[first + ready]->readFrame(&f) != openni::STATUS_OK || !f.isValid()) return 3;
    if (streams[first + ready] != &depth) continue;
    if (f.getFrameIndex() != read + 1) return 3;
    if (!write_all(out, f.getData(), static_cast<std::size_t>(f.getDataSize()))) return 4;
    ++read;
  }
  _exit(0);  // skip the player's teardown: the parent has what it needs
}

// Forks `body` with a pipe for the frames; collects them, kills the child after `timeout_ms`.
Run in_child(const std::function<int(int)>& body, int timeout_ms) {
  int fds[2];
  if (pipe(fds) != 0) std::perror("pipe"), std::exit(1);
  const auto start = Clock::now();
  const pid_t pid = fork();
  if (pid == 0) {
    close(fds[0]);
    const int null_fd = ::open("/dev/null", O_WRONLY);
    dup2(null_fd, 1);
    dup2(null_fd, 2);
    _exit(body(fds[1]));
  }
  close(fds[1]);
  Run r;
  bool timed_out = false;
  char buf[1 << 16];
  for (;;) {
    const int left = timeout_ms - static_cast<int>(std::chrono::duration_cast<std::chrono::milliseconds>(Clock::now() - start).count());
    pollfd p{fds[0], POLLIN, 0};
    if (left <= 0 || poll(&p, 1, left) == 0) {
      kill(pid, SIGKILL);
      timed_out = true;
      break;
    }
    const ssize_t n = read(fds[0], buf, sizeof buf);
    if (n <= 0) break;
    r.frames.append(buf, static_cast<std::size_t>(n));
  }
  close(fds[0]);
  int status = 0;
  waitpid(pid, &status, 0);
  r.ms = std::chrono::duration<double, std::milli>(Clock::now() - start).count();
  if (timed_out)
    r.kind = Run::Timeout;
  else if (WIFSIGNALED(status))
    r.kind = Run::Signal;
  else
    r.kind = WEXITSTATUS(status) == 0 ? Run::Exit0 : Run::Exit3;
  return r;
}

std::string read_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

void write_file(const std::string& path, const std::string& bytes) {
  std::ofstream(path, std::ios::binary | std::ios::trunc) << bytes;
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

struct Tally {
  int same = 0, different = 0, exit3 = 0, signal = 0, timeout = 0;
  void add(const Run& r, const std::string& good_frames) {
    if (r.kind == Run::Exit0) (r.frames == good_frames ? same : different)++;
    if (r.kind == Run::Exit3) ++exit3;
    if (r.kind == Run::Signal) ++signal;
    if (r.kind == Run::Timeout) ++timeout;
  }
  void print(const char* name) const {
    std::printf("| %s | %d | %d | %d | %d | %d |\n", name, same, different, exit3, signal, timeout);
  }
};

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2) {
    std::fprintf(stderr, "usage: %s REC.oni [--runs N] [--timeout-ms T]\n", argv[0]);
    return 2;
  }
  const std::string original = argv[1];
  int runs = 20, timeout_ms = 10000;
  for (int i = 2; i + 1 < argc; i += 2) {
    if (std::strcmp(argv[i], "--runs") == 0) runs = std::atoi(argv[i + 1]);
    if (std::strcmp(argv[i], "--timeout-ms") == 0) timeout_ms = std::atoi(argv[i + 1]);
  }
  const auto checked = [](const std::string& path) { return [path](int out) { return read_checked(path, out); }; };
  const auto child = [](const std::string& path) { return [path](int out) { return read_unchecked(path, out); }; };

  // The unchanged recording: both ways must read the same frames.
  const Run good_checked = in_child(checked(original), timeout_ms), good_child = in_child(child(original), timeout_ms);
  if (good_checked.kind != Run::Exit0 || good_child.kind != Run::Exit0 || good_checked.frames != good_child.frames) {
    std::fprintf(stderr, "the unchanged recording does not read the same both ways (%d/%zu bytes, %d/%zu bytes)\n",
                 int(good_checked.kind), good_checked.frames.size(), int(good_child.kind), good_child.frames.size());
    return 1;
  }
  const std::string& good_frames = good_checked.frames;

  const std::string bytes = read_file(original);
  const std::vector<std::size_t> at = testing::oni_change_positions(bytes);
  const std::string variant = original + ".variant.oni";
  Tally tally_checked, tally_child;
  int refused_but_playable = 0;  // the child read the recorded frames, the check refused the file
  std::vector<double> variant_ms_checked, variant_ms_child;
  for (std::size_t k = 0; k < at.size(); ++k) {
    write_file(variant, testing::oni_changed(bytes, at[k], k));
    const Run a = in_child(checked(variant), timeout_ms), b = in_child(child(variant), timeout_ms);
    tally_checked.add(a, good_frames);
    tally_child.add(b, good_frames);
    variant_ms_checked.push_back(a.ms);
    variant_ms_child.push_back(b.ms);
    const bool child_intact = b.kind == Run::Exit0 && b.frames == good_frames;
    if (child_intact && a.kind != Run::Exit0) ++refused_but_playable;
    if (!child_intact)
      std::fprintf(stderr, "byte %zu: child %s (%zu frame bytes received), checked %s\n", at[k],
                   b.kind == Run::Signal    ? "crashed"
                   : b.kind == Run::Timeout ? "hung"
                   : b.kind == Run::Exit3   ? "exit 3"
                                            : "read changed frames",
                   b.frames.size(), a.kind == Run::Exit0 ? "exit 0" : a.kind == Run::Exit3 ? "exit 3" : "FAILED");
  }
  std::remove(variant.c_str());
  std::printf("%zu single-byte changes of %s (%zu bytes), timeout %d ms\n\n", at.size(), original.c_str(), bytes.size(),
              timeout_ms);
  std::printf("| way | exit 0, frames as recorded | exit 0, frames changed | exit 3 | killed by a signal | hung (killed at the timeout) |\n");
  std::printf("|---|---|---|---|---|---|\n");
  tally_checked.print("checked, in process");
  tally_child.print("child process, unchecked");
  std::printf("\nrefused by the check although the child read the recorded frames: %d\n", refused_but_playable);
  std::printf("median wall time per changed file: checked %.1f ms, child %.1f ms (each in a forked child here)\n",
              median(variant_ms_checked), median(variant_ms_child));

  // Open and read every frame of the unchanged recording: the child way forks and initialises
  // OpenNI2 in every child; the checked way, as the product runs it, in this process.
  std::vector<double> child_ms, checked_ms;
  for (int i = 0; i < runs; ++i) child_ms.push_back(in_child(child(original), timeout_ms).ms);
  openni2::ensure_initialized();  // once per process in the product too
  std::vector<double> check_only_ms;
  for (int i = 0; i < runs; ++i) {
    const auto t0 = Clock::now();
    oni::check_recording_file(original, input_keys::max_image_pixels.default_value);
    const auto t1 = Clock::now();
    const openni2::OniFileSource source(original, ReadOptions());
    for (std::size_t f = 0; f < source.size(); ++f) source.load(f);
    const auto t2 = Clock::now();
    check_only_ms.push_back(std::chrono::duration<double, std::milli>(t1 - t0).count());
    // t1..t2 is the product's whole open (OniFileSource checks the file first) and read.
    checked_ms.push_back(std::chrono::duration<double, std::milli>(t2 - t1).count());
  }
  std::printf("unchanged recording, open and read all frames, median of %d: checked in process %.2f ms "
              "(of which the check %.2f ms), child process %.2f ms\n",
              runs, median(checked_ms), median(check_only_ms), median(child_ms));
  return 0;
}
