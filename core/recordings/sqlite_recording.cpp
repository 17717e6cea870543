#include "core/recordings/sqlite_recording.h"

#include <sqlite3.h>
#include <sys/stat.h>

#include <map>

#include "core/recordings/topic_tally.h"
#include "core/util/error.h"

namespace tunnelmap::recordings {
namespace {

struct Topic {
  std::string name, type, serialization_format;
};

class Statement {
 public:
  Statement(sqlite3* db, const std::string& sql, const std::string& path) {
    if (sqlite3_prepare_v2(db, sql.c_str(), -1, &stmt_, nullptr) != SQLITE_OK)
      throw InputError(path, std::string("not a rosbag2 database: ") + sqlite3_errmsg(db));
  }
  ~Statement() { sqlite3_finalize(stmt_); }
  Statement(const Statement&) = delete;
  Statement& operator=(const Statement&) = delete;
  sqlite3_stmt* get() const { return stmt_; }

 private:
  sqlite3_stmt* stmt_ = nullptr;
};

std::string column_text(sqlite3_stmt* s, int i) {
  const unsigned char* t = sqlite3_column_text(s, i);
  return t ? reinterpret_cast<const char*>(t) : "";
}

class SqliteRecording : public Recording {
 public:
  explicit SqliteRecording(const std::string& path) : path_(path) {
    struct stat st {};
    if (::stat(path.c_str(), &st) != 0 || !S_ISREG(st.st_mode))
      throw InputError(path, "cannot open the recording (not a readable file)");
    // immutable=1: no locks, no journal recovery, nothing written next to the bag.
    const std::string uri = "file:" + path + "?immutable=1";
    if (sqlite3_open_v2(uri.c_str(), &db_, SQLITE_OPEN_READONLY | SQLITE_OPEN_URI, nullptr) != SQLITE_OK) {
      const std::string why = db_ ? sqlite3_errmsg(db_) : "out of memory";
      sqlite3_close(db_);
      throw InputError(path, "cannot open the sqlite3 bag: " + why);
    }
    try {
      read_topics();
      count_messages();
    } catch (...) {
      sqlite3_close(db_);
      throw;
    }
    summary_.format = "sqlite3";
    summary_.files = {path};
    summary_.topics = tally_.topics();
  }
  ~SqliteRecording() override { sqlite3_close(db_); }

  const RecordingSummary& summary() const override { return summary_; }

  void read_messages(const std::set<std::string>& topics,
                     const std::function<bool(const MessageView&)>& visit) const override {
    Statement s(db_, "SELECT topic_id, timestamp, data FROM messages ORDER BY timestamp, id", path_);
    int rc;
    while ((rc = sqlite3_step(s.get())) == SQLITE_ROW) {
      const auto it = topics_.find(sqlite3_column_int64(s.get(), 0));
      if (it == topics_.end()) continue;  // a message of a topic the table does not declare
      if (!topics.empty() && !topics.count(it->second.name)) continue;
      const auto* data = static_cast<const std::uint8_t*>(sqlite3_column_blob(s.get(), 2));
      const auto size = static_cast<std::size_t>(sqlite3_column_bytes(s.get(), 2));
      if (!visit(MessageView{it->second.name, sqlite3_column_int64(s.get(), 1), data, size})) return;
    }
    if (rc != SQLITE_DONE) throw InputError(path_, std::string("reading messages: ") + sqlite3_errmsg(db_));
  }

 private:
  // Serialization formats other than CDR cannot be decoded: such a bag is refused whole.
  void read_topics() {
    Statement s(db_, "SELECT id, name, type, serialization_format FROM topics", path_);
    while (sqlite3_step(s.get()) == SQLITE_ROW) {
      Topic t{column_text(s.get(), 1), column_text(s.get(), 2), column_text(s.get(), 3)};
      if (t.serialization_format != "cdr")
        throw InputError(path_, "topic " + t.name + ": serialization format '" +
                                    t.serialization_format + "' cannot be decoded (TunnelMap reads cdr)");
      tally_.declare(t.name, t.type);
      topics_[sqlite3_column_int64(s.get(), 0)] = t;
    }
  }

  // One aggregate query: counts and time range per topic without reading a message blob.
  void count_messages() {
    Statement s(db_,
                "SELECT topic_id, COUNT(*), MIN(timestamp), MAX(timestamp) FROM messages GROUP BY topic_id",
                path_);
    while (sqlite3_step(s.get()) == SQLITE_ROW) {
      const auto it = topics_.find(sqlite3_column_int64(s.get(), 0));
      if (it == topics_.end()) continue;
      TopicInfo info;
      info.name = it->second.name;
      info.type = it->second.type;
      info.message_count = static_cast<std::uint64_t>(sqlite3_column_int64(s.get(), 1));
      info.first_time_ns = sqlite3_column_int64(s.get(), 2);
      info.last_time_ns = sqlite3_column_int64(s.get(), 3);
      tally_.merge(info);
    }
  }

  std::string path_;
  sqlite3* db_ = nullptr;
  std::map<std::int64_t, Topic> topics_;
  TopicTally tally_;
  RecordingSummary summary_;
};

}  // namespace

std::unique_ptr<Recording> open_rosbag2_sqlite(const std::string& path) {
  return std::make_unique<SqliteRecording>(path);
}

}  // namespace tunnelmap::recordings
