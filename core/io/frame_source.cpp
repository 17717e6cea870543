#include "core/io/frame_source.h"

#include <algorithm>
#include <cctype>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <mutex>

#include "core/io/depth_png.h"
#include "core/io/organized_pcd.h"
#include "core/io/png_folder.h"
#include "core/io/tum_sequence.h"
#include "core/recordings/recording.h"
#include "core/recordings/recording_dataset.h"
#include "core/util/error.h"

namespace tunnelmap {
namespace fs = std::filesystem;

FrameSource::~FrameSource() = default;

namespace {

enum class InputKind { DepthPng, Pcd, Dataset, Unknown };

std::string lower(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char ch) { return std::tolower(ch); });
  return s;
}

InputKind sniff(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  char head[16] = {};
  in.read(head, sizeof head);
  const std::string s(head, static_cast<std::size_t>(in.gcount()));
  if (s.size() >= 8 && std::memcmp(s.data(), "\x89PNG\r\n\x1a\n", 8) == 0) return InputKind::DepthPng;
  if (s.rfind("# .PCD", 0) == 0 || s.rfind("VERSION", 0) == 0) return InputKind::Pcd;
  const auto first = s.find_first_not_of(" \t\r\n");
  if (first != std::string::npos && s[first] == '{') return InputKind::Dataset;
  return InputKind::Unknown;
}

// A single depth PNG or PCD: one frame, read when asked for.
class SingleFileSource : public FrameSource {
 public:
  SingleFileSource(std::string path, InputKind kind, ReadOptions opt)
      : path_(std::move(path)), kind_(kind), opt_(std::move(opt)) {}
  std::size_t size() const override { return 1; }
  DepthFrame load(std::size_t i) const override {
    if (i != 0) throw InputError(path_, "frame index " + std::to_string(i) + " out of range (1 frame)");
    return kind_ == InputKind::Pcd ? read_organized_pcd(path_, opt_) : read_depth_png(path_, opt_);
  }
  std::string describe(std::size_t) const override { return path_; }

 private:
  std::string path_;
  InputKind kind_;
  ReadOptions opt_;
};

class DatasetSource : public FrameSource {
 public:
  explicit DatasetSource(Dataset d) : d_(std::move(d)) {}
  std::size_t size() const override { return d_.frames.size(); }
  DepthFrame load(std::size_t i) const override { return d_.load_frame(i); }
  std::string describe(std::size_t i) const override {
    std::string s = "frame " + std::to_string(i) + "/" + std::to_string(d_.frames.size());
    if (i < d_.frames.size()) {
      const auto& raw = d_.frames[i].raw;
      if (raw.contains("depth") && raw["depth"].is_string())
        s += " (" + raw["depth"].get<std::string>() + ")";
    }
    return s;
  }
  const Dataset* dataset() const override { return &d_; }

 private:
  Dataset d_;
};

std::mutex& registry_mutex() {
  static std::mutex m;
  return m;
}
std::map<std::string, FrameSourceFactory>& registry() {
  static std::map<std::string, FrameSourceFactory> r;
  return r;
}

}  // namespace

void register_frame_source(const std::string& extension, FrameSourceFactory factory) {
  std::lock_guard<std::mutex> lock(registry_mutex());
  registry()[lower(extension)] = std::move(factory);
}

std::unique_ptr<FrameSource> open_input(const std::string& input, const ReadOptions& opt) {
  std::error_code ec;
  if (input.empty()) throw InputError("", "no input given");
  if (!fs::exists(input, ec)) throw InputError(input, ec ? "cannot access: " + ec.message() : "not found");
  if (recordings::is_recording_path(input)) return recordings::open_recording_input(input, opt);
  if (is_tum_sequence(input)) return std::make_unique<DatasetSource>(read_dataset(input, opt));
  if (fs::is_directory(input, ec)) {
    // A plain folder of depth PNGs is a sequence without poses.
    if (!fs::exists(fs::path(input) / "dataset.json", ec)) return open_png_folder(input, opt);
    return std::make_unique<DatasetSource>(read_dataset(input, opt));
  }
  const std::string ext = lower(fs::path(input).extension().string());
  FrameSourceFactory factory;
  {
    std::lock_guard<std::mutex> lock(registry_mutex());
    const auto it = registry().find(ext);
    if (it != registry().end()) factory = it->second;
  }
  if (factory) return factory(input, opt);
  if (ext == ".oni") throw InputError(input, "OpenNI2 recordings (.oni) need a build with OpenNI2 support");
  InputKind kind = ext == ".png"    ? InputKind::DepthPng
                   : ext == ".pcd"  ? InputKind::Pcd
                   : ext == ".json" ? InputKind::Dataset
                                    : sniff(input);
  switch (kind) {
    case InputKind::Dataset:
      return std::make_unique<DatasetSource>(read_dataset(input, opt));
    case InputKind::DepthPng:
    case InputKind::Pcd:
      return std::make_unique<SingleFileSource>(input, kind, opt);
    case InputKind::Unknown:
      break;
  }
  throw InputError(input, "unknown input type (expected a 16-bit depth PNG, an organised PCD, "
                          "or a dataset folder with dataset.json)");
}

}  // namespace tunnelmap
