#include "tests/support/rosbag2_db3_writer.h"

#include <sqlite3.h>

#include <stdexcept>

namespace tunnelmap::testing {

Rosbag2Db3Writer::Rosbag2Db3Writer(const std::string& path) {
  if (sqlite3_open(path.c_str(), &db_) != SQLITE_OK) throw std::runtime_error("cannot create " + path);
  exec("CREATE TABLE topics(id INTEGER PRIMARY KEY, name TEXT NOT NULL, type TEXT NOT NULL, "
       "serialization_format TEXT NOT NULL, offered_qos_profiles TEXT NOT NULL)");
  exec("CREATE TABLE messages(id INTEGER PRIMARY KEY, topic_id INTEGER NOT NULL, timestamp INTEGER NOT NULL, "
       "data BLOB NOT NULL)");
  exec("CREATE INDEX timestamp_idx ON messages (timestamp ASC)");
  exec("BEGIN");
}

Rosbag2Db3Writer::~Rosbag2Db3Writer() {
  exec("COMMIT");
  sqlite3_close(db_);
}

void Rosbag2Db3Writer::exec(const std::string& sql) {
  char* err = nullptr;
  if (sqlite3_exec(db_, sql.c_str(), nullptr, nullptr, &err) != SQLITE_OK) {
    const std::string why = err ? err : "?";
    sqlite3_free(err);
    throw std::runtime_error("sqlite: " + why);
  }
}

void Rosbag2Db3Writer::write(const std::string& topic, const std::string& type, std::int64_t time_ns,
                             const std::vector<std::uint8_t>& cdr) {
  auto it = topic_ids_.find(topic);
  if (it == topic_ids_.end()) {
    const std::int64_t id = static_cast<std::int64_t>(topic_ids_.size()) + 1;
    exec("INSERT INTO topics VALUES(" + std::to_string(id) + ", '" + topic + "', '" + type + "', 'cdr', '')");
    it = topic_ids_.emplace(topic, id).first;
  }
  sqlite3_stmt* s = nullptr;
  sqlite3_prepare_v2(db_, "INSERT INTO messages(topic_id, timestamp, data) VALUES(?, ?, ?)", -1, &s, nullptr);
  sqlite3_bind_int64(s, 1, it->second);
  sqlite3_bind_int64(s, 2, time_ns);
  sqlite3_bind_blob(s, 3, cdr.data(), static_cast<int>(cdr.size()), SQLITE_STATIC);
  const int rc = sqlite3_step(s);
  sqlite3_finalize(s);
  if (rc != SQLITE_DONE) throw std::runtime_error("sqlite: cannot insert a message");
}

}  // namespace tunnelmap::testing
