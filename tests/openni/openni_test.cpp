// End to end through the real OpenNI2 stack with no hardware: OpenNI2 loads the project's
// simulated tunnel camera (libTunnelMapSim.so.0) from the build's driver folder (the test binary's
// RUNPATH selects the build's private libOpenNI2 copy, see sensors/openni/CMakeLists.txt). Only
// the public OpenNI2 API is used: enumerate, stream, record an .oni, play it back, detect.
#include <gtest/gtest.h>
#include <OpenNI.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <thread>
#include <vector>

#include "core/io/frame_source.h"
#include "core/params/parameters.h"
#include "core/pipeline/pipeline.h"
#include "core/sim/tunnel_simulator.h"
#include "core/util/build_paths.h"
#include "core/util/error.h"
#include "sensors/openni/device_frame_source.h"
#include "sensors/openni/device_list.h"
#include "sensors/openni/latest_frame_grabber.h"
#include "sensors/openni/oni_file_source.h"
#include "sensors/openni/oni_recording.h"
#include "sensors/openni/openni_context.h"
#include "sensors/openni/register_openni.h"
#include "tests/support/cli_runner.h"

using namespace tunnelmap;
namespace fs = std::filesystem;

namespace {
const std::string kPresets = std::string(TUNNELMAP_SOURCE_DIR) + "/resources/presets/";

Parameters preset_params(const std::string& preset) {
  Parameters p;
  p.load_json_file(kPresets + preset + ".json");
  return p;
}

// The simulator the device URI "tunnelmap-sim://PRESET?pose=K&frames=N" runs. Tests use short
// frame cycles: the simulated camera renders its whole cycle before the first frame.
TunnelSimulator simulator_for(const std::string& preset, int pose, int frames = 0) {
  SimConfig c = SimConfig::from_preset(preset);
  if (frames > 0) c.frames = frames;
  if (pose >= 0) c.poses = {c.poses[static_cast<std::size_t>(pose)]};
  return TunnelSimulator(c);
}

int sim_index(const DepthFrame& f) { return static_cast<int>(std::lround(f.timestamp_s * 30.0)); }

void expect_same_depth(const DepthFrame& got, const DepthFrame& sim) {
  ASSERT_EQ(got.width, sim.width);
  ASSERT_EQ(got.height, sim.height);
  std::size_t differ = 0;
  for (std::size_t i = 0; i < got.depth.size(); ++i)
    differ += got.depth[i] != static_cast<float>(std::lround(sim.depth[i]));
  EXPECT_EQ(differ, 0u);
}

// Runs tunnelmap-cli with a chosen OpenNI2 (LD_LIBRARY_PATH "" = the system's own stack).
tunnelmap::testing::CliRun run_cli_with(const std::string& ld_path, const std::string& args) {
  const std::string env = ld_path.empty() ? "env -u LD_LIBRARY_PATH " : "env LD_LIBRARY_PATH=" + ld_path + " ";
  tunnelmap::testing::IoTempDir tmp;
  const std::string out = tmp.file("stdout"), err = tmp.file("stderr");
  const int status =
      std::system((env + TUNNELMAP_CLI_PATH + " " + args + " >" + out + " 2>" + err + " </dev/null").c_str());
  tunnelmap::testing::CliRun r;
  r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  r.out = tunnelmap::testing::slurp(out);
  r.err = tunnelmap::testing::slurp(err);
  return r;
}

class OpenNiTest : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    openni2::ensure_initialized();  // each test also runs alone (ctest)
    openni2::register_openni_inputs();
  }
  tunnelmap::testing::IoTempDir tmp_;
};
}  // namespace

TEST_F(OpenNiTest, EnumeratesTheSimulatedCamerasWithTheirModes) {
  const auto devices = openni2::list_devices();
  const openni2::DeviceDescription* lab = nullptr;
  for (const auto& d : devices)
    if (d.uri == "tunnelmap-sim://lab") lab = &d;
  ASSERT_NE(lab, nullptr) << "simulated camera not found: is libTunnelMapSim.so.0 in the OpenNI2 drivers folder?";
  EXPECT_EQ(lab->vendor, "TunnelMap");
  ASSERT_EQ(lab->modes.size(), 2u);
  EXPECT_EQ(lab->modes[0].sensor, "depth");
  EXPECT_EQ(lab->modes[0].pixel_format, "DEPTH_1_MM");
  EXPECT_EQ(lab->modes[0].width, 640);
  EXPECT_EQ(lab->modes[0].height, 480);
  EXPECT_EQ(lab->modes[0].fps, 30);
  EXPECT_EQ(lab->modes[1].sensor, "color");
  EXPECT_EQ(lab->modes[1].pixel_format, "RGB888");
}

TEST_F(OpenNiTest, Streams60LiveFramesEqualToTheSimulatorWithIntrinsicsAndPoses) {
  openni2::LiveDevice device("tunnelmap-sim://lab?frames=10");
  EXPECT_TRUE(device.has_color());
  EXPECT_TRUE(device.registered());
  const Intrinsics K0 = Intrinsics::primesense_vga();
  EXPECT_NEAR(device.intrinsics().fx, K0.fx, 1e-3);  // from the stream's FOV
  EXPECT_NEAR(device.intrinsics().fy, K0.fy, 1e-3);
  EXPECT_NEAR(device.intrinsics().cx, K0.cx, 1e-9);
  const TunnelSimulator sim = simulator_for("lab", -1, 10);
  device.start();
  int previous = -1;
  for (int i = 0; i < 60; ++i) {
    const DepthFrame f = device.read();
    const int k = sim_index(f);
    EXPECT_GT(k, previous) << "frame " << i;  // in order (a slow reader may miss frames: OpenNI keeps the newest)
    previous = k;
    ASSERT_TRUE(f.pose.has_value());
    EXPECT_TRUE(f.pose->isApprox(sim.pose(k % sim.frame_count()), 1e-12));
    EXPECT_TRUE(f.has_rgb());
    if (i % 20 == 0) expect_same_depth(f, sim.render(k % sim.frame_count()).frame);
  }
  EXPECT_EQ(device.frames_read(), 60);
}

// The OpenNI2 end-to-end check: stream, record 30 frames, play back with OpenNI2's OniFile
// driver, detect in every frame with the accuracy of the simulator's own (dataset) frames.
class OpenNiRecordingTest : public OpenNiTest, public ::testing::WithParamInterface<std::string> {};

TEST_P(OpenNiRecordingTest, RecordedFramesPlayBackLosslesslyAndDetectLikeTheDataset) {
  const std::string preset = GetParam();
  const std::string oni = tmp_.file(preset + ".oni");
  // fps=0: paced by the reader, so a loaded machine records the same 30 (or 31) frames.
  const auto rec = openni2::record_oni("tunnelmap-sim://" + preset + "?pose=0&frames=10&fps=0", 30, oni);
  EXPECT_EQ(rec.frames, 30);
  ASSERT_TRUE(fs::exists(oni));
  for (const auto& e : fs::directory_iterator(tmp_.path())) EXPECT_EQ(e.path().string().find(".tmp-"), std::string::npos);

  auto source = open_input(oni, ReadOptions());
  // Frames that arrive while the recorder stops may add one; never fewer than asked for.
  ASSERT_GE(source->size(), 30u);
  ASSERT_LE(source->size(), 31u);
  const TunnelSimulator sim = simulator_for(preset, 0, 10);
  std::vector<SimFrame> truths;  // the cycle repeats three times in 30 frames
  for (int k = 0; k < sim.frame_count(); ++k) truths.push_back(sim.render(k));
  // .oni files have no poses: the camera-frame up vector of the recording's (single) pose.
  const Eigen::Vector3d up = sim.pose(0).linear().transpose() * Eigen::Vector3d::UnitZ();
  Pipeline from_oni(preset_params(preset));
  from_oni.set_camera_up(up);
  const Pipeline from_dataset(preset_params(preset));  // world up +Z through the simulator's poses
  const SimConfig& c = sim.config();
  double oni_err = 0, dataset_err = 0;
  for (std::size_t i = 0; i < source->size(); ++i) {
    const DepthFrame f = source->load(i);
    EXPECT_NEAR(f.intrinsics.fx, Intrinsics::primesense_vga().fx, 1e-3);
    const SimFrame& truth = truths[i % truths.size()];
    if (i == 0 || i + 1 == source->size()) {
      expect_same_depth(f, truth.frame);
      // Colour comes back with its depth frame; recorded as JPEG, so close but not equal.
      ASSERT_TRUE(f.has_rgb()) << "frame " << i;
      ASSERT_EQ(f.rgb.size(), truth.frame.rgb.size());
      double diff = 0;
      for (std::size_t p = 0; p < f.rgb.size(); ++p) diff += std::abs(int(f.rgb[p]) - int(truth.frame.rgb[p]));
      std::printf("[ %s ] frame %zu colour mean abs difference %.2f / 255\n", preset.c_str(), i, diff / f.rgb.size());
      EXPECT_LT(diff / f.rgb.size(), 4.0) << "frame " << i;
    }
    const FrameResult a = from_oni.run(f);
    const FrameResult b = from_dataset.run(truth.frame);
    ASSERT_TRUE(a.map.detected) << preset << " frame " << i << ": " << a.map.reason;
    ASSERT_TRUE(b.map.detected);
    EXPECT_NEAR(a.map.width_m, b.map.width_m, 0.002) << "frame " << i;
    EXPECT_NEAR(a.map.height_m, b.map.height_m, 0.002) << "frame " << i;
    oni_err += std::abs(a.map.width_m - c.width_m) + std::abs(a.map.height_m - c.height_m);
    dataset_err += std::abs(b.map.width_m - c.width_m) + std::abs(b.map.height_m - c.height_m);
  }
  const double n = 2.0 * source->size();
  std::printf("[ %s ] mean abs error: .oni %.2f mm, simulator frames %.2f mm\n", preset.c_str(),
              1000 * oni_err / n, 1000 * dataset_err / n);
  EXPECT_NEAR(oni_err / n, dataset_err / n, 0.001);
  EXPECT_LT(oni_err / n, 0.015);
}

INSTANTIATE_TEST_SUITE_P(Presets, OpenNiRecordingTest, ::testing::Values("lab", "field"));

TEST_F(OpenNiTest, PlaybackSeeksWithoutLooping) {
  const std::string oni = tmp_.file("seek.oni");
  openni2::record_oni("tunnelmap-sim://lab?frames=8", 8, oni);
  auto source = open_input(oni, ReadOptions());
  const std::size_t n = source->size();
  std::vector<double> sequential;
  for (std::size_t i = 0; i < n; ++i) sequential.push_back(source->load(i).timestamp_s);
  for (std::size_t i = 1; i < n; ++i) EXPECT_NEAR(sequential[i] - sequential[i - 1], 1.0 / 30, 1e-3);
  for (std::size_t i : {n - 1, std::size_t{2}, std::size_t{0}, std::size_t{5}})
    EXPECT_DOUBLE_EQ(source->load(i).timestamp_s, sequential[i]) << "seek to " << i;
  EXPECT_THROW(source->load(n), InputError);  // no looping back to frame 0
}

TEST_F(OpenNiTest, LiveProcessingOfTheLatestFrameKeepsUp) {
  openni2::LatestFrameGrabber grabber(std::make_unique<openni2::LiveDevice>("tunnelmap-sim://lab?frames=10"));
  const Pipeline pipeline(preset_params("lab"));
  std::vector<double> latency_ms;
  int detected = 0;
  std::uint64_t last_sequence = 0;
  std::chrono::steady_clock::time_point start;  // the rate counts from the first frame on
  while (latency_ms.size() < 60) {
    // The first frame waits for the camera to start (the simulator renders its frame cycle).
    auto g = grabber.take_latest(latency_ms.empty() ? 30000 : 2000);
    ASSERT_TRUE(g.has_value());
    if (latency_ms.empty()) start = g->arrived;
    EXPECT_GT(g->sequence, last_sequence);  // never an older frame
    last_sequence = g->sequence;
    detected += pipeline.run(g->frame).map.detected;
    latency_ms.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - g->arrived).count());
  }
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const auto stats = grabber.stats();
  std::sort(latency_ms.begin(), latency_ms.end());
  std::printf("[ live ] %zu frames processed in %.2f s = %.1f fps; %llu received, %llu dropped; latency median "
              "%.1f ms, max %.1f ms\n",
              latency_ms.size(), seconds, (latency_ms.size() - 1) / seconds, (unsigned long long)stats.received,
              (unsigned long long)stats.dropped, latency_ms[latency_ms.size() / 2], latency_ms.back());
  EXPECT_EQ(detected, 60);
  EXPECT_EQ(stats.taken, 60u);
  EXPECT_GE(stats.received, stats.taken + stats.dropped);  // every frame taken or counted as dropped
  EXPECT_GE(stats.taken + stats.dropped, last_sequence);  // frames up to the last taken: taken or dropped
}

// A recording finishes with the streams paused (OpenNI2 can deadlock when a frame reaches a
// recorder being destroyed); the live view keeps streaming afterwards, even when finishing fails.
TEST_F(OpenNiTest, RecordingFinishesWithStreamsPausedAndStreamingGoesOn) {
  openni2::LatestFrameGrabber grabber(std::make_unique<openni2::LiveDevice>("tunnelmap-sim://lab?frames=10"));
  ASSERT_TRUE(grabber.take_latest(30000).has_value());
  const std::string oni = tmp_.file("live.oni");
  auto recording = std::make_unique<openni2::OniRecording>(grabber.device(), oni);
  const auto received_before = grabber.stats().received;
  while (grabber.stats().received < received_before + 10) ASSERT_TRUE(grabber.take_latest(2000).has_value());
  grabber.with_streams_paused([&] { recording->finish(); });
  const std::size_t recorded = open_input(oni, ReadOptions())->size();
  EXPECT_GE(recorded, 9u);  // every frame read since, but perhaps the first (in flight at attach)

  auto streams_again = [&] {
    const auto received = grabber.stats().received;
    for (int i = 0; i < 20 && grabber.stats().received < received + 3; ++i) grabber.take_latest(500);
    return grabber.stats().received >= received + 3;
  };
  EXPECT_TRUE(streams_again());
  EXPECT_THROW(grabber.with_streams_paused([] { throw InputError("x.oni", "cannot write"); }), InputError);
  EXPECT_TRUE(streams_again());
}

TEST_F(OpenNiTest, UnpluggingMidRecordingKeepsWhatWasRecorded) {
  const std::string oni = tmp_.file("unplugged.oni");
  try {
    // fps=0: the simulated camera waits for each frame to be read, so a loaded machine reads
    // all 12 (at 30 fps it could skip some; the file would still hold all 12, see below).
    openni2::record_oni("tunnelmap-sim://lab?disconnect_after=12&frames=6&fps=0", 30, oni);
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()).find('\n'), std::string::npos);
    EXPECT_NE(std::string(e.what()).find("disconnected after 12 frames"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("the 12 frames recorded so far"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find(oni), std::string::npos) << e.what();
  }
  auto source = open_input(oni, ReadOptions());
  EXPECT_EQ(source->size(), 12u);
  for (std::size_t i = 0; i < source->size(); ++i) EXPECT_FALSE(source->load(i).empty());
}

TEST_F(OpenNiTest, UnpluggingMidStreamIsAClearError) {
  openni2::DeviceFrameSource source("tunnelmap-sim://lab?disconnect_after=5&frames=5&fps=0", 10, ReadOptions());
  for (std::size_t i = 0; i < 5; ++i) EXPECT_FALSE(source.load(i).empty());
  try {
    source.load(5);
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), "tunnelmap-sim://lab?disconnect_after=5&frames=5&fps=0");
    EXPECT_EQ(e.problem(), "device disconnected after 5 frames");
  }
}

TEST_F(OpenNiTest, RecordingWithoutDepthIsRejected) {
  const std::string oni = tmp_.file("color-only.oni");
  {
    openni::Device device;
    ASSERT_EQ(device.open("tunnelmap-sim://lab?frames=3"), openni::STATUS_OK);
    openni::VideoStream color;
    ASSERT_EQ(color.create(device, openni::SENSOR_COLOR), openni::STATUS_OK);
    openni::Recorder recorder;
    ASSERT_EQ(recorder.create(oni.c_str()), openni::STATUS_OK);
    ASSERT_EQ(recorder.attach(color), openni::STATUS_OK);
    recorder.start();
    color.start();
    openni::VideoFrameRef f;
    for (int i = 0; i < 3; ++i) color.readFrame(&f);
    color.stop();
    recorder.stop();
    recorder.destroy();
    color.destroy();
    device.close();
  }
  try {
    open_input(oni, ReadOptions());
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()), oni + ": recording has no depth stream");
  }
}

TEST_F(OpenNiTest, TruncatedOrBogusRecordingsAreClearErrors) {
  const std::string oni = tmp_.file("full.oni");
  openni2::record_oni("tunnelmap-sim://lab?frames=5", 10, oni);
  const std::string cut = tmp_.file("cut.oni");
  fs::copy_file(oni, cut);
  fs::resize_file(cut, fs::file_size(oni) / 2);
  try {
    auto source = open_input(cut, ReadOptions());
    std::size_t readable = 0;
    for (std::size_t i = 0; i < source->size(); ++i) {
      try {
        source->load(i);
        ++readable;
      } catch (const InputError& e) {
        EXPECT_EQ(e.file(), cut);
      }
    }
    std::printf("[ truncated ] %zu of %zu frames readable\n", readable, source->size());
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), cut);
    EXPECT_EQ(std::string(e.what()).find('\n'), std::string::npos);
  }
  const std::string bogus = tmp_.file("bogus.oni");
  std::ofstream(bogus) << "not a recording at all";
  EXPECT_THROW(open_input(bogus, ReadOptions()), InputError);
}

TEST_F(OpenNiTest, CliListsRecordsAndDetectsLiveAndRecordedWithStockOpenNi) {
  const std::string runtime = TUNNELMAP_OPENNI2_RUNTIME_DIR;
  const auto devices = run_cli_with(runtime, "devices");
  ASSERT_EQ(devices.exit_code, 0) << devices.err;
  EXPECT_NE(devices.out.find("tunnelmap-sim://field\n  name: Simulated tunnel camera\n  vendor: TunnelMap\n"
                             "  depth: 640x480 @ 30 fps DEPTH_1_MM\n  color: 640x480 @ 30 fps RGB888\n"),
            std::string::npos)
      << devices.out;

  const std::string oni = tmp_.file("cli.oni");
  const auto rec = run_cli_with(runtime, "record --device 'tunnelmap-sim://lab?pose=0&frames=5' --frames 10 " + oni);
  ASSERT_EQ(rec.exit_code, 0) << rec.err;
  EXPECT_EQ(rec.out, "recorded 10 frames from tunnelmap-sim://lab?pose=0&frames=5 to " + oni + "\n");

  const auto live = run_cli_with(runtime, "detect --device 'tunnelmap-sim://lab?frames=5' --frames 10 -q --params " + kPresets +
                                              "lab.json");
  ASSERT_EQ(live.exit_code, 0) << live.err;
  EXPECT_NE(live.out.find("summary: 10/10 frames detected"), std::string::npos) << live.out;
  EXPECT_NE(live.out.find("live: 10 frames in"), std::string::npos) << live.out;

  // Playback through the system's own OpenNI2 and its OniFile driver (no project driver).
  const Eigen::Vector3d up =
      simulator_for("lab", 0, 5).pose(0).linear().transpose() * Eigen::Vector3d::UnitZ();
  char up_arg[96];
  std::snprintf(up_arg, sizeof up_arg, "%.6f,%.6f,%.6f", up.x(), up.y(), up.z());
  const auto play = run_cli_with("", "detect " + oni + " -q --params " + kPresets + "lab.json --up " + up_arg);
  ASSERT_EQ(play.exit_code, 0) << play.err;
  EXPECT_NE(play.out.find("frames detected"), std::string::npos) << play.out;
  const auto n = fs::exists(oni) ? open_input(oni, ReadOptions())->size() : 0;
  EXPECT_NE(play.out.find("summary: " + std::to_string(n) + "/" + std::to_string(n) + " frames detected"),
            std::string::npos)
      << play.out;

  // The device sends 3 frames at 30 fps; a slower pipeline skips to the newest, so it may have read
  // fewer than 3 when the device goes away.
  const auto unplugged =
      run_cli_with(runtime, "detect --device 'tunnelmap-sim://lab?disconnect_after=3&frames=3' --frames 10 -q");
  EXPECT_EQ(unplugged.exit_code, 3);
  const std::string prefix = "tunnelmap-cli: tunnelmap-sim://lab?disconnect_after=3&frames=3: device disconnected after ";
  ASSERT_EQ(unplugged.err.rfind(prefix, 0), 0u) << unplugged.err;
  const int read = std::atoi(unplugged.err.c_str() + prefix.size());
  EXPECT_GE(read, 1);
  EXPECT_LE(read, 3);
  EXPECT_EQ(unplugged.err.substr(prefix.size() + std::to_string(read).size()), " frames\n");
}
