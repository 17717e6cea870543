#include "core/recordings/ros1_recording.h"

#include <algorithm>
#include <cstring>
#include <map>

#include "core/recordings/binary_file.h"
#include "core/recordings/decompress.h"
#include "core/recordings/ros1_records.h"
#include "core/recordings/topic_tally.h"
#include "core/util/error.h"

namespace tunnelmap::recordings {
namespace {

using namespace ros1;

struct ChunkInfo {
  std::uint64_t position = 0;
  std::int64_t start_time_ns = 0;
  std::uint32_t connection_count = 0;
};

struct PendingMessage {
  std::int64_t time_ns;
  std::uint32_t connection;
  const std::uint8_t* data;
  std::size_t size;
};

class Ros1Recording : public Recording {
 public:
  explicit Ros1Recording(const std::string& path) : file_(path) {
    std::vector<std::uint8_t> magic;
    if (!file_.read_at(0, kMagicSize, magic) || std::memcmp(magic.data(), kMagic, kMagicSize) != 0)
      throw InputError(path, "not a ROS 1 bag (expected '#ROSBAG V2.0')");
    summary_.format = "ros1";
    summary_.encoding = MessageEncoding::Ros1;
    summary_.files = {path};
    try {
      if (!read_index_or_forget()) tally_by_scanning();
    } catch (const TruncatedData& e) {
      throw InputError(path, std::string("corrupt bag record: ") + e.what());
    }
    summary_.topics = tally_.topics();
  }

  const RecordingSummary& summary() const override { return summary_; }

  void read_messages(const std::set<std::string>& topics,
                     const std::function<bool(const MessageView&)>& visit) const override {
    auto emit = [&](std::uint32_t conn, std::int64_t t, const std::uint8_t* d, std::size_t n) {
      const auto it = connections_.find(conn);
      if (it == connections_.end()) throw TruncatedData("message on an undeclared connection");
      // A connection declared only inside a chunk, not in the index the summary lists.
      if (!summary_.topic(it->second.topic))
        throw TruncatedData("message on topic '" + it->second.topic + "', which the bag's index does not list");
      if (!topics.empty() && !topics.count(it->second.topic)) return true;
      return visit(MessageView{it->second.topic, t, d, n});
    };
    try {
      if (chunks_.empty()) {
        scan(emit);
      } else {
        for (const ChunkInfo& ci : chunks_) {
          const auto size = record_at(ci.position, record_buffer_);
          if (!size) throw TruncatedData("chunk info points outside the file");
          ByteCursor c(record_buffer_.data(), record_buffer_.size());
          if (!visit_chunk(read_record(c), emit)) return;
        }
      }
    } catch (const TruncatedData& e) {
      throw InputError(file_.path(), std::string("corrupt bag record: ") + e.what());
    }
  }

 private:
  using Emit = std::function<bool(std::uint32_t, std::int64_t, const std::uint8_t*, std::size_t)>;

  // Reads the whole record at `pos` into `out`; its size, or 0 when the file ends first.
  std::uint64_t record_at(std::uint64_t pos, std::vector<std::uint8_t>& out) const {
    std::vector<std::uint8_t> len;
    if (!file_.read_at(pos, 4, len)) return 0;
    std::uint32_t header_len;
    std::memcpy(&header_len, len.data(), 4);
    if (!file_.read_at(pos + 4 + header_len, 4, len)) return 0;
    std::uint32_t data_len;
    std::memcpy(&data_len, len.data(), 4);
    const std::uint64_t total = 8ull + header_len + data_len;
    return file_.read_at(pos, total, out) ? total : 0;
  }

  // A cut or damaged index is no reason to refuse the bag: the chunks are scanned instead.
  bool read_index_or_forget() {
    try {
      return read_index();
    } catch (const TruncatedData&) {
      connections_.clear();
      chunks_.clear();
      tally_ = TopicTally();
      return false;
    }
  }

  // The bag header's index position, then connections, chunk infos and each chunk's index
  // data (one time per message) without decompressing a chunk. False when there is no index.
  bool read_index() {
    std::vector<std::uint8_t> buf;
    if (!record_at(kMagicSize, buf)) return false;
    ByteCursor hc(buf.data(), buf.size());
    const Record bag_header = read_record(hc);
    if (field_op(bag_header.header) != kBagHeader) throw TruncatedData("the bag header is missing");
    const std::uint64_t index_pos = field_u64(bag_header.header, "index_pos");
    if (index_pos < kMagicSize || index_pos >= file_.size()) return false;
    if (!file_.read_at(index_pos, file_.size() - index_pos, buf)) return false;
    ByteCursor c(buf.data(), buf.size());
    while (!c.at_end()) {
      const Record r = read_record(c);
      const std::uint8_t op = field_op(r.header);
      if (op == kConnection) add_connection(parse_connection(r));
      if (op == kChunkInfo) chunks_.push_back(parse_chunk_info(r));
    }
    for (const ChunkInfo& ci : chunks_) tally_chunk_index(ci);
    std::stable_sort(chunks_.begin(), chunks_.end(), [](const ChunkInfo& a, const ChunkInfo& b) {
      return a.start_time_ns < b.start_time_ns;
    });
    return true;
  }

  static ChunkInfo parse_chunk_info(const Record& r) {
    ChunkInfo ci;
    ci.position = field_u64(r.header, "chunk_pos");
    ci.start_time_ns = field_time_ns(r.header, "start_time");
    ci.connection_count = field_u32(r.header, "count");
    return ci;
  }

  // The index data records follow their chunk, one per connection in it.
  void tally_chunk_index(const ChunkInfo& ci) {
    std::vector<std::uint8_t> buf;
    std::uint64_t pos = ci.position;
    const std::uint64_t chunk_size = record_at(pos, buf);
    if (!chunk_size) throw TruncatedData("chunk info points outside the file");
    pos += chunk_size;
    for (std::uint32_t i = 0; i < ci.connection_count; ++i) {
      const std::uint64_t size = record_at(pos, buf);
      if (!size) throw TruncatedData("index data runs past the end of the file");
      ByteCursor c(buf.data(), buf.size());
      Record r = read_record(c);
      if (field_op(r.header) != kIndexData) throw TruncatedData("index data missing after a chunk");
      const std::uint32_t conn = field_u32(r.header, "conn");
      const std::uint32_t count = field_u32(r.header, "count");
      for (std::uint32_t k = 0; k < count; ++k) {
        const std::int64_t t = read_time_ns(r.data);
        r.data.u32();  // offset inside the uncompressed chunk
        tally_.add(topic_of(conn), t);
      }
      pos += size;
    }
  }

  const std::string& topic_of(std::uint32_t conn) const {
    const auto it = connections_.find(conn);
    if (it == connections_.end()) throw TruncatedData("message on an undeclared connection");
    return it->second.topic;
  }

  // The first definition of an id wins: a later record cannot move messages to another topic.
  void add_connection(const Connection& conn) const {
    if (!connections_.emplace(conn.id, conn).second) return;
    tally_.declare(conn.topic, conn.type);
  }

  void tally_by_scanning() {
    scan([&](std::uint32_t conn, std::int64_t t, const std::uint8_t*, std::size_t) {
      tally_.add(topic_of(conn), t);
      return true;
    });
  }

  // Record after record from the bag header on; a record cut by the end of the file ends the
  // pass with a truncation note.
  void scan(const Emit& emit) const {
    std::uint64_t pos = kMagicSize;
    while (pos < file_.size()) {
      const std::uint64_t size = record_at(pos, record_buffer_);
      if (!size) {
        summary_.truncation_note = "the file ends inside the record at byte " + std::to_string(pos) +
                                   "; read up to the last whole message";
        read_cut_chunk(pos, emit);
        return;
      }
      ByteCursor c(record_buffer_.data(), record_buffer_.size());
      const Record r = read_record(c);
      const std::uint8_t op = field_op(r.header);
      if (op == kConnection) add_connection(parse_connection(r));
      if (op == kMessageData && !emit_message(r, emit)) return;
      if (op == kChunk && !visit_chunk(r, emit)) return;
      pos += size;
    }
  }

  // An uncompressed chunk cut by the end of the file still holds whole messages before the
  // cut (a compressed one cannot be decoded in part).
  void read_cut_chunk(std::uint64_t pos, const Emit& emit) const {
    if (!file_.read_at(pos, file_.size() - pos, record_buffer_)) return;
    ByteCursor c(record_buffer_.data(), record_buffer_.size());
    pending_.clear();
    try {
      const HeaderFields header = parse_header_fields(c.sub(c.u32()));
      const std::string compression = field_string(header, "compression");
      if (field_op(header) != kChunk || (compression != "none" && !compression.empty())) return;
      c.u32();  // the data length the writer meant to reach
      collect_chunk_messages(c);
    } catch (const TruncatedData&) {
    }
    emit_sorted(pending_, emit);
  }

  // Records of a decompressed chunk into `pending_`, up to the last whole one when cut
  // (TruncatedData then propagates after the whole records were kept).
  void collect_chunk_messages(ByteCursor& c) const {
    pending_.clear();
    while (!c.at_end()) {
      const Record r = read_record(c);
      const std::uint8_t op = field_op(r.header);
      if (op == kConnection) add_connection(parse_connection(r));
      if (op == kMessageData)
        pending_.push_back({field_time_ns(r.header, "time"), field_u32(r.header, "conn"),
                            r.data.here(), r.data.remaining()});
    }
  }

  bool emit_sorted(std::vector<PendingMessage>& messages, const Emit& emit) const {
    std::stable_sort(messages.begin(), messages.end(),
                     [](const PendingMessage& a, const PendingMessage& b) { return a.time_ns < b.time_ns; });
    for (const PendingMessage& m : messages)
      if (!emit(m.connection, m.time_ns, m.data, m.size)) return false;
    return true;
  }

  bool emit_message(const Record& r, const Emit& emit) const {
    return emit(field_u32(r.header, "conn"), field_time_ns(r.header, "time"), r.data.here(),
                r.data.remaining());
  }

  // Decompresses one chunk and emits its messages in time order.
  bool visit_chunk(const Record& chunk, const Emit& emit) const {
    const std::string compression = field_string(chunk.header, "compression");
    try {
      decompress_chunk(compression, chunk.data.here(), chunk.data.remaining(),
                       field_u32(chunk.header, "size"), chunk_buffer_);
    } catch (const std::runtime_error& e) {
      if (dynamic_cast<const TruncatedData*>(&e)) throw;
      throw InputError(file_.path(), std::string("bag chunk: ") + e.what());
    }
    ByteCursor c(chunk_buffer_.data(), chunk_buffer_.size());
    collect_chunk_messages(c);
    return emit_sorted(pending_, emit);
  }

  BinaryFile file_;
  mutable RecordingSummary summary_;
  mutable TopicTally tally_;
  mutable std::map<std::uint32_t, Connection> connections_;
  std::vector<ChunkInfo> chunks_;
  mutable std::vector<std::uint8_t> chunk_buffer_, record_buffer_;  // reused between chunks
  mutable std::vector<PendingMessage> pending_;                       // one chunk's messages
};

}  // namespace

std::unique_ptr<Recording> open_ros1_bag(const std::string& path) {
  return std::make_unique<Ros1Recording>(path);
}

}  // namespace tunnelmap::recordings
