#include "core/recordings/recording.h"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "core/recordings/mcap_recording.h"
#include "core/recordings/ros1_recording.h"
#include "core/recordings/rosbag2_metadata.h"
#include "core/recordings/sqlite_recording.h"
#include "core/recordings/topic_tally.h"
#include "core/util/error.h"

namespace tunnelmap::recordings {
namespace fs = std::filesystem;

Recording::~Recording() = default;

std::optional<double> TopicInfo::rate_hz() const {
  if (message_count < 2 || !first_time_ns || !last_time_ns || *last_time_ns <= *first_time_ns)
    return std::nullopt;
  return static_cast<double>(message_count - 1) / (1e-9 * static_cast<double>(*last_time_ns - *first_time_ns));
}

const TopicInfo* RecordingSummary::topic(const std::string& name) const {
  for (const TopicInfo& t : topics)
    if (t.name == name) return &t;
  return nullptr;
}

std::uint64_t RecordingSummary::message_count() const {
  std::uint64_t n = 0;
  for (const TopicInfo& t : topics) n += t.message_count;
  return n;
}

namespace {

std::string lower_extension(const fs::path& p) {
  std::string e = p.extension().string();
  std::transform(e.begin(), e.end(), e.begin(), [](unsigned char c) { return std::tolower(c); });
  return e;
}

bool is_storage_file(const fs::path& p) {
  const std::string e = lower_extension(p);
  return e == ".mcap" || e == ".db3" || e == ".bag";
}

std::string first_bytes(const std::string& path, std::size_t n) {
  std::ifstream in(path, std::ios::binary);
  std::string s(n, '\0');
  in.read(&s[0], static_cast<std::streamsize>(n));
  s.resize(static_cast<std::size_t>(in.gcount()));
  return s;
}

std::unique_ptr<Recording> open_storage_file(const std::string& path) {
  const std::string ext = lower_extension(path);
  const std::string head = first_bytes(path, 16);
  if (ext == ".mcap" || head.rfind("\x89MCAP", 0) == 0) return open_mcap(path);
  if (ext == ".bag" || head.rfind("#ROSBAG", 0) == 0) return open_ros1_bag(path);
  if (ext == ".db3" || head.rfind("SQLite format 3", 0) == 0) return open_rosbag2_sqlite(path);
  throw InputError(path, "not a recording (expected an MCAP, sqlite3 or ROS 1 bag file)");
}

// Several storage files read as one recording, in order (a split rosbag2 bag).
class SplitRecording : public Recording {
 public:
  explicit SplitRecording(std::vector<std::unique_ptr<Recording>> parts) : parts_(std::move(parts)) {
    TopicTally tally;
    for (const auto& part : parts_) {
      const RecordingSummary& s = part->summary();
      summary_.format = s.format;
      summary_.encoding = s.encoding;
      summary_.files.insert(summary_.files.end(), s.files.begin(), s.files.end());
      for (const TopicInfo& t : s.topics) tally.merge(t);
      if (s.truncation_note) summary_.truncation_note = s.files.front() + ": " + *s.truncation_note;
    }
    summary_.topics = tally.topics();
  }
  const RecordingSummary& summary() const override { return summary_; }
  void read_messages(const std::set<std::string>& topics,
                     const std::function<bool(const MessageView&)>& visit) const override {
    bool stopped = false;
    for (const auto& part : parts_) {
      if (stopped) return;
      part->read_messages(topics, [&](const MessageView& m) { return !(stopped = !visit(m)); });
    }
  }

 private:
  std::vector<std::unique_ptr<Recording>> parts_;
  RecordingSummary summary_;
};

std::string read_text(const fs::path& p) {
  std::ifstream in(p);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

std::vector<fs::path> storage_files_in(const fs::path& dir, const Rosbag2Metadata& meta) {
  std::vector<fs::path> files;
  for (const std::string& rel : meta.relative_file_paths) files.push_back(dir / rel);
  if (!files.empty()) return files;
  for (const auto& e : fs::directory_iterator(dir))
    if (e.is_regular_file() && is_storage_file(e.path())) files.push_back(e.path());
  std::sort(files.begin(), files.end());
  return files;
}

std::unique_ptr<Recording> open_folder(const fs::path& dir) {
  Rosbag2Metadata meta;
  const fs::path yaml = dir / "metadata.yaml";
  if (fs::exists(yaml)) meta = parse_rosbag2_metadata(read_text(yaml));
  for (const auto& [topic, format] : meta.serialization_formats)
    if (format != "cdr" && format != "ros1")
      throw InputError(yaml.string(), "topic " + topic + ": serialization format '" + format +
                                          "' cannot be decoded (TunnelMap reads cdr)");
  const std::vector<fs::path> files = storage_files_in(dir, meta);
  if (files.empty()) throw InputError(dir.string(), "folder holds no bag file (.mcap, .db3 or .bag)");
  std::vector<std::unique_ptr<Recording>> parts;
  for (const fs::path& f : files) {
    if (!fs::exists(f)) throw InputError(f.string(), "listed in metadata.yaml but missing");
    parts.push_back(open_storage_file(f.string()));
  }
  if (parts.size() == 1) return std::move(parts.front());
  return std::make_unique<SplitRecording>(std::move(parts));
}

}  // namespace

bool is_recording_path(const std::string& path) {
  std::error_code ec;
  if (fs::is_directory(path, ec)) {
    if (fs::exists(fs::path(path) / "metadata.yaml", ec)) return true;
    // A dataset or TUM sequence folder stays one even with a bag file lying beside it.
    if (fs::exists(fs::path(path) / "dataset.json", ec) || fs::exists(fs::path(path) / "depth.txt", ec)) return false;
    for (const auto& e : fs::directory_iterator(path, ec))
      if (e.is_regular_file() && is_storage_file(e.path())) return true;
    return false;
  }
  return is_storage_file(path);
}

std::unique_ptr<Recording> open_recording(const std::string& path) {
  std::error_code ec;
  if (fs::is_directory(path, ec)) return open_folder(path);
  if (!fs::exists(path, ec)) throw InputError(path, "no such file or folder");
  return open_storage_file(path);
}

}  // namespace tunnelmap::recordings
