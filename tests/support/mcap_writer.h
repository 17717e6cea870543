#pragma once
// A minimal MCAP writer following the specification (mcap.dev/spec), for the tests: profile
// "ros2", CDR channels, messages in chunks (none, zstd or lz4) each followed by its message
// indexes, and a summary section with schemas, channels, chunk indexes and statistics
// (or none, to exercise the reader's scan).
#include <cstdint>
#include <map>
#include <string>
#include <vector>

namespace tunnelmap::testing {

class McapWriter {
 public:
  struct Options {
    std::string compression = "zstd";  // "", "zstd" or "lz4"
    bool summary = true;
    std::size_t chunk_bytes = 1 << 20;  // a chunk closes once its records pass this size
  };
  McapWriter(std::string path, Options options);
  // Registers the topic on first use.
  void write(const std::string& topic, const std::string& type, std::uint64_t log_time_ns,
             const std::vector<std::uint8_t>& cdr);
  void close();  // writes the last chunk, the summary and the footer to the file

 private:
  struct Channel {
    std::uint16_t id, schema_id;
    std::string topic, type;
  };
  void flush_chunk();

  std::string path_;
  Options options_;
  std::vector<std::uint8_t> file_, chunk_, summary_chunk_indexes_;
  std::map<std::string, Channel> channels_;
  std::map<std::uint16_t, std::vector<std::pair<std::uint64_t, std::uint64_t>>> chunk_index_entries_;
  std::map<std::uint16_t, std::uint64_t> channel_counts_;
  std::uint64_t chunk_start_ = 0, chunk_end_ = 0, message_count_ = 0, first_time_ = 0, last_time_ = 0;
  std::uint32_t chunk_count_ = 0;
  bool closed_ = false;
};

}  // namespace tunnelmap::testing
