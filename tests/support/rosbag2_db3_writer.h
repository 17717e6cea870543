#pragma once
// A rosbag2 sqlite3 storage file written as rosbag2 lays it out (the schema before Iron:
// topics and messages tables), for the tests.
#include <cstdint>
#include <map>
#include <string>
#include <vector>

struct sqlite3;

namespace tunnelmap::testing {

class Rosbag2Db3Writer {
 public:
  explicit Rosbag2Db3Writer(const std::string& path);  // std::runtime_error when it cannot
  ~Rosbag2Db3Writer();
  Rosbag2Db3Writer(const Rosbag2Db3Writer&) = delete;
  Rosbag2Db3Writer& operator=(const Rosbag2Db3Writer&) = delete;

  void write(const std::string& topic, const std::string& type, std::int64_t time_ns,
             const std::vector<std::uint8_t>& cdr);

 private:
  void exec(const std::string& sql);
  sqlite3* db_ = nullptr;
  std::map<std::string, std::int64_t> topic_ids_;
};

}  // namespace tunnelmap::testing
