// tunnelmap_recording_rss: a recording is read as a stream, never loaded whole. A zstd MCAP of
// --frames VGA 32FC1 depth images (1.2 MB each, with camera info; written by the tests' MCAP
// writer in a child process, so its buffers never count here) is read through RecordingFrames,
// every frame decoded. Prints the bag's size, the depth bytes read and the peak RSS; exits 1 if
// the peak exceeds --max-peak-mb (the default bag, 600 frames, is about 600 MB on disk: six
// times the bound the test sets).
#include <sys/wait.h>
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>

#include "core/recordings/recording.h"
#include "core/recordings/recording_frames.h"
#include "tests/support/cdr_writer.h"
#include "tests/support/mcap_writer.h"
#include "tests/allocation/process_memory.h"

using namespace tunnelmap;
namespace fs = std::filesystem;

using testing::status_mb;

namespace {

constexpr std::uint32_t kWidth = 640, kHeight = 480;

// A wall at 1-3 m with millimetre noise in the low bits, so that zstd cannot shrink it much.
std::vector<std::uint8_t> depth_image(int frame) {
  std::vector<std::uint8_t> bytes(static_cast<std::size_t>(kWidth) * kHeight * 4);
  std::uint32_t state = 2463534242u + static_cast<std::uint32_t>(frame);
  for (std::size_t k = 0; k < static_cast<std::size_t>(kWidth) * kHeight; ++k) {
    state ^= state << 13, state ^= state >> 17, state ^= state << 5;
    const float metres = 1.0f + 2.0f * static_cast<float>(k % kWidth) / kWidth + (state % 1000) * 1e-6f;
    std::memcpy(&bytes[k * 4], &metres, 4);
  }
  return bytes;
}

void write_bag(const std::string& path, int frames) {
  testing::McapWriter writer(path, {});
  for (int i = 0; i < frames; ++i) {
    const std::int64_t t = 1700000000LL * 1000000000LL + i * 33333333LL;
    writer.write("/camera/depth/camera_info", "sensor_msgs/msg/CameraInfo", static_cast<std::uint64_t>(t),
                 testing::cdr_camera_info(t, "camera_depth_optical_frame", kWidth, kHeight, 570.3, 570.3, 319.5, 239.5));
    writer.write("/camera/depth/image_raw", "sensor_msgs/msg/Image", static_cast<std::uint64_t>(t),
                 testing::cdr_image(t, "camera_depth_optical_frame", kWidth, kHeight, "32FC1", kWidth * 4, depth_image(i)));
  }
  writer.close();
}

// The writer keeps its file in memory until close(): a child process, so that never counts here.
bool write_bag_in_child(const std::string& path, int frames) {
  const pid_t pid = fork();
  if (pid < 0) return false;
  if (pid == 0) {
    try {
      write_bag(path, frames);
      std::_Exit(0);
    } catch (const std::exception& e) {
      std::fprintf(stderr, "writing %s: %s\n", path.c_str(), e.what());
      std::_Exit(1);
    }
  }
  int status = 0;
  return waitpid(pid, &status, 0) == pid && WIFEXITED(status) && WEXITSTATUS(status) == 0;
}

}  // namespace

int main(int argc, char** argv) {
  int frames = 600;
  double max_peak_mb = 100.0;
  for (int i = 1; i + 1 < argc; i += 2) {
    const std::string flag = argv[i];
    if (flag == "--frames") frames = std::atoi(argv[i + 1]);
    else if (flag == "--max-peak-mb") max_peak_mb = std::atof(argv[i + 1]);
  }
  const fs::path dir = fs::temp_directory_path() / ("tunnelmap-recording-rss-" + std::to_string(getpid()));
  fs::create_directories(dir);
  const std::string bag = (dir / "depth.mcap").string();
  if (!write_bag_in_child(bag, frames)) {
    std::fprintf(stderr, "could not write %s\n", bag.c_str());
    fs::remove_all(dir);
    return 2;
  }
  std::size_t read = 0;
  double depth_mb = 0.0;
  try {
    const auto rec = recordings::open_recording(bag);
    const recordings::RecordingFrames stream(*rec, recordings::RecordingOptions{}, ReadOptions{});
    stream.for_each_frame([&](DepthFrame& f) {
      ++read;
      depth_mb += f.depth.size() * 4.0 / (1024.0 * 1024.0);
      return true;
    });
  } catch (const std::exception& e) {
    std::fprintf(stderr, "%s\n", e.what());
    fs::remove_all(dir);
    return 2;
  }
  const double bag_mb = static_cast<double>(fs::file_size(bag)) / (1024.0 * 1024.0);
  fs::remove_all(dir);
  const double peak = status_mb("VmHWM");
  std::printf("bag %.0f MB on disk, %zu of %d frames read (%.0f MB of depth), peak RSS %.1f MB (limit %.0f)\n", bag_mb,
              read, frames, depth_mb, peak, max_peak_mb);
  if (read != static_cast<std::size_t>(frames)) return 1;
  return peak <= max_peak_mb ? 0 : 1;
}
