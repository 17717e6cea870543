#pragma once
// A robot recording read as topics and messages: ROS 2 bags (MCAP or sqlite3, a rosbag2 folder
// with metadata.yaml and split files) and ROS 1 bags. Readers stream: the summary is read
// from the file's index when there is one, and messages are delivered one chunk (or one
// database row) at a time, so a bag is never loaded whole.
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <vector>

namespace tunnelmap::recordings {

enum class MessageEncoding { Cdr, Ros1 };

struct TopicInfo {
  std::string name;
  std::string type;  // as recorded: "pkg/msg/Name" (ROS 2), "pkg/Name" (ROS 1)
  std::uint64_t message_count = 0;
  std::optional<std::int64_t> first_time_ns, last_time_ns;  // unknown for an empty topic

  std::optional<double> rate_hz() const;  // (count-1)/duration; unknown below two messages
};

struct RecordingSummary {
  std::string format;  // "mcap", "sqlite3", "ros1"
  MessageEncoding encoding = MessageEncoding::Cdr;
  std::vector<TopicInfo> topics;  // sorted by name
  std::vector<std::string> files;  // the files read (several for a split bag)
  // Set when the file ends early: messages are read up to the last whole one.
  std::optional<std::string> truncation_note;

  const TopicInfo* topic(const std::string& name) const;
  std::uint64_t message_count() const;
};

struct MessageView {
  const std::string& topic;
  std::int64_t log_time_ns;
  const std::uint8_t* data;
  std::size_t size;
};

class Recording {
 public:
  virtual ~Recording();
  virtual const RecordingSummary& summary() const = 0;
  // Calls `visit` for every message on `topics` (all topics when empty), in storage order
  // (time order within a chunk). `visit` returns false to stop early.
  virtual void read_messages(const std::set<std::string>& topics,
                             const std::function<bool(const MessageView&)>& visit) const = 0;
};

// True when `path` looks like a recording (.mcap, .db3, .bag, or a folder holding
// metadata.yaml, or bag files and no dataset.json or depth.txt).
bool is_recording_path(const std::string& path);

// Opens a recording by extension, folder contents or magic bytes. InputError (one line naming
// the file) for unreadable files and for a channel whose encoding TunnelMap cannot decode.
std::unique_ptr<Recording> open_recording(const std::string& path);

}  // namespace tunnelmap::recordings
