#include "core/recordings/recording_dataset.h"

#include <unistd.h>

#include <atomic>
#include <cmath>
#include <nlohmann/json.hpp>
#include <opencv2/imgcodecs.hpp>

#include "core/io/dataset.h"
#include "core/io/dataset_json_writer.h"
#include "core/util/error.h"
#include "core/util/image_file.h"
#include "core/util/temp_registry.h"

namespace tunnelmap::recordings {
namespace fs = std::filesystem;
using nlohmann::json;

namespace {

constexpr double kDatasetDepthScale = 1000.0;  // millimetres, as depth cameras deliver them

// Depth in millimetres; no measurement (0, NaN, negative) stays 0.
cv::Mat depth_mm(const DepthFrame& f, std::size_t& out_of_range) {
  cv::Mat m(f.height, f.width, CV_16UC1);
  const double to_mm = kDatasetDepthScale / f.depth_units_per_m;
  for (int v = 0; v < f.height; ++v)
    for (int u = 0; u < f.width; ++u) {
      const double d = f.depth[static_cast<std::size_t>(v) * f.width + u] * to_mm;
      std::uint16_t q = 0;
      if (std::isfinite(d) && d > 0) {
        const double r = std::round(d);
        if (r > 65535.0) ++out_of_range;
        else q = static_cast<std::uint16_t>(r);
      }
      m.at<std::uint16_t>(v, u) = q;
    }
  return m;
}

void write_png(const fs::path& path, const cv::Mat& m) {
  write_image_file(path.string(), m);
}

cv::Mat bgr_of(const DepthFrame& f) {
  cv::Mat bgr(f.height, f.width, CV_8UC3);
  for (int v = 0; v < f.height; ++v)
    for (int u = 0; u < f.width; ++u) {
      const std::uint8_t* p = &f.rgb[(static_cast<std::size_t>(v) * f.width + u) * 3];
      bgr.at<cv::Vec3b>(v, u) = cv::Vec3b(p[2], p[1], p[0]);
    }
  return bgr;
}

// A temporary dataset folder removed with the source that reads it.
class ExtractedRecordingSource : public FrameSource {
 public:
  ExtractedRecordingSource(fs::path dir, Dataset ds) : dir_(std::move(dir)), ds_(std::move(ds)) {}
  ~ExtractedRecordingSource() override {
    std::error_code ec;
    fs::remove_all(dir_, ec);
    TempRegistry::remove(dir_);
  }
  std::size_t size() const override { return ds_.frames.size(); }
  DepthFrame load(std::size_t i) const override {
    DepthFrame f = ds_.load_frame(i);
    f.source = sources_.at(i);
    return f;
  }
  std::string describe(std::size_t i) const override {
    return "frame " + std::to_string(i) + "/" + std::to_string(ds_.frames.size()) + " (" + sources_.at(i) + ")";
  }
  const Dataset* dataset() const override { return &ds_; }
  std::vector<std::string> sources_;  // "topic t=... s" per frame

 private:
  fs::path dir_;
  Dataset ds_;
};

// A new folder (never an existing one), registered as it is made: removed on SIGINT/SIGTERM too.
fs::path make_temp_folder() {
  static std::atomic<unsigned> made{0};
  const fs::path dir = fs::temp_directory_path() /
                       ("tunnelmap-recording-" + std::to_string(::getpid()) + "-" + std::to_string(made++));
  try {
    TempRegistry::create(dir, [&] {
      std::error_code ec;
      if (!fs::create_directory(dir, ec) || ec) throw InputError(dir.string(), "cannot create a temporary folder");
    });
  } catch (...) {
    TempRegistry::remove(dir);
    throw;
  }
  return dir;
}

// How many frames the IMU gave gravity, or why it was not read.
void note_gravity(const TopicChoice& topics, const RecordingExport& ex, const std::string& path,
                  const std::function<void(const std::string&)>& note) {
  if (!topics.imu_not_read_because.empty()) note(path + ": " + topics.imu_not_read_because);
  if (topics.imu.empty()) return;
  std::string text = path + ": gravity from " + topics.imu + " for " + std::to_string(ex.with_gravity) + " of " +
                     std::to_string(ex.frames) + " frames";
  if (ex.with_gravity < ex.frames)
    text += " (the others: no accelerometer sample near them, the robot not still, or no TF from the IMU to the camera)";
  note(text);
}

}  // namespace

RecordingExport write_recording_dataset(const RecordingFrames& frames, const std::string& recording_path,
                                        const fs::path& dir, const Eigen::Vector3d& up,
                                        const std::function<void(std::size_t)>& progress) {
  fs::create_directories(dir / "depth");
  RecordingExport ex;
  json list = json::array();
  Intrinsics K;
  frames.for_each_frame([&](DepthFrame& f) {
    const std::string name = dataset_frame_file(ex.frames, ".png");
    write_png(dir / "depth" / name, depth_mm(f, ex.depth_out_of_range));
    json fj = {{"depth", "depth/" + name}, {"timestamp", f.timestamp_s}, {"source", f.source}};
    if (f.has_rgb()) {
      fs::create_directories(dir / "rgb");
      write_png(dir / "rgb" / name, bgr_of(f));
      fj["rgb"] = "rgb/" + name;
      ++ex.coloured;
    }
    if (f.pose) {
      fj["pose"] = dataset_pose_json(*f.pose);
      ++ex.posed;
    }
    if (f.gravity) {
      fj["gravity"] = dataset_vector_json(*f.gravity);
      ++ex.with_gravity;
    }
    list.push_back(fj);
    if (ex.frames == 0) K = f.intrinsics;
    ++ex.frames;
    if (progress) progress(ex.frames);
    return true;
  });
  if (ex.frames == 0)
    throw InputError(recording_path, "no depth frame on " + frames.topics().depth + " in the chosen time window");
  json dataset = dataset_document(K, kDatasetDepthScale, up, std::move(list));
  dataset["recording"] = {{"path", recording_path},
                          {"depth_topic", frames.topics().depth},
                          {"color_topic", frames.topics().color},
                          {"camera_info_topic", frames.topics().camera_info},
                          {"pose_topic", frames.topics().pose},
                          {"imu_topic", frames.topics().imu},
                          {"world_frame", frames.world_frame()}};
  write_dataset_json(dir, dataset);
  return ex;
}

std::unique_ptr<FrameSource> open_recording_input(const std::string& path, const ReadOptions& opt) {
  const std::unique_ptr<Recording> rec = open_recording(path);
  return extract_recording(*rec, path, opt);
}

std::unique_ptr<FrameSource> extract_recording(const Recording& rec, const std::string& path, const ReadOptions& opt,
                                               const std::function<void(std::size_t)>& progress) {
  const RecordingFrames frames(rec, opt.recording, opt);
  const fs::path dir = make_temp_folder();
  try {
    const Eigen::Vector3d up = opt.world_up ? opt.world_up->normalized() : Eigen::Vector3d::UnitZ();
    const RecordingExport ex = write_recording_dataset(frames, path, dir, up, progress);
    if (opt.note && ex.depth_out_of_range)
      opt.note(path + ": " + std::to_string(ex.depth_out_of_range) + " depth pixels beyond 65.535 m read as no measurement");
    if (opt.note) note_gravity(frames.topics(), ex, path, opt.note);
    Dataset ds = read_dataset(dir.string());
    ds.max_image_pixels = opt.max_image_pixels;
    auto source = std::make_unique<ExtractedRecordingSource>(dir, std::move(ds));
    for (const auto& f : source->dataset()->frames) source->sources_.push_back(f.raw.value("source", path));
    return source;
  } catch (...) {
    std::error_code ec;
    fs::remove_all(dir, ec);
    TempRegistry::remove(dir);
    throw;
  }
}

}  // namespace tunnelmap::recordings
