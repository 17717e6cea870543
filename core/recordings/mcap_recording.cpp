#include "core/recordings/mcap_recording.h"

#include <algorithm>
#include <cstring>
#include <map>

#include "core/recordings/binary_file.h"
#include "core/recordings/decompress.h"
#include "core/recordings/mcap_records.h"
#include "core/recordings/topic_tally.h"
#include "core/util/error.h"

namespace tunnelmap::recordings {
namespace {

using namespace mcap;
constexpr std::uint64_t kRecordHeader = 9;  // opcode + length
constexpr std::uint64_t kFooterRecord = kRecordHeader + 20;

struct PendingMessage {
  std::uint64_t log_time;
  std::uint16_t channel;
  const std::uint8_t* data;
  std::size_t size;
};

class McapRecording : public Recording {
 public:
  explicit McapRecording(const std::string& path) : file_(path) {
    std::vector<std::uint8_t> magic;
    if (!file_.read_at(0, 8, magic) || std::memcmp(magic.data(), kMagic, 8) != 0)
      throw InputError(path, "not an MCAP file (bad magic)");
    summary_.format = "mcap";
    summary_.files = {path};
    try {
      if (!read_summary_section()) tally_by_scanning();
    } catch (const TruncatedData& e) {
      throw InputError(path, std::string("corrupt MCAP index: ") + e.what());
    } catch (const std::runtime_error& e) {
      if (dynamic_cast<const InputError*>(&e)) throw;
      throw InputError(path, e.what());
    }
    check_encodings();
    summary_.topics = tally_.topics();
  }

  const RecordingSummary& summary() const override { return summary_; }

  void read_messages(const std::set<std::string>& topics,
                     const std::function<bool(const MessageView&)>& visit) const override {
    std::set<std::uint16_t> wanted;
    for (const auto& [id, ch] : channels_)
      if (topics.empty() || topics.count(ch.topic)) wanted.insert(id);
    auto emit = [&](std::uint16_t channel, std::uint64_t t, const std::uint8_t* d, std::size_t n) {
      if (!wanted.count(channel)) return true;
      return visit(MessageView{channels_.at(channel).topic, static_cast<std::int64_t>(t), d, n});
    };
    try {
      if (chunk_indexes_.empty()) {
        scan(emit);
      } else {
        read_indexed_chunks(emit);
      }
    } catch (const TruncatedData& e) {
      throw InputError(file_.path(), std::string("corrupt MCAP record: ") + e.what());
    }
  }

 private:
  using Emit = std::function<bool(std::uint16_t, std::uint64_t, const std::uint8_t*, std::size_t)>;

  // True when the footer points at a summary whose chunk indexes cover every chunk.
  bool read_summary_section() {
    const std::uint64_t size = file_.size();
    if (size < 8 + kFooterRecord + 8) return false;
    std::vector<std::uint8_t> tail;
    const std::uint64_t footer_pos = size - 8 - kFooterRecord;
    if (!file_.read_at(footer_pos, kFooterRecord + 8, tail)) return false;
    if (tail[0] != kFooter || std::memcmp(tail.data() + kFooterRecord, kMagic, 8) != 0) return false;
    ByteCursor fc(tail.data() + kRecordHeader, 20);
    const Footer footer = parse_footer(fc);
    if (footer.summary_start < 8 || footer.summary_start >= footer_pos) return false;
    std::vector<std::uint8_t> summary;
    if (!file_.read_at(footer.summary_start, footer_pos - footer.summary_start, summary)) return false;
    std::vector<ChunkIndex> chunks;
    for_each_record(ByteCursor(summary.data(), summary.size()), [&](std::uint8_t op, ByteCursor c) {
      if (op == kSchema) add_schema(parse_schema(c));
      if (op == kChannel) add_channel(parse_channel(c));
      if (op == kChunkIndex) chunks.push_back(parse_chunk_index(c));
    });
    if (chunks.empty()) return false;  // unchunked messages: only a scan finds them
    std::stable_sort(chunks.begin(), chunks.end(), [](const ChunkIndex& a, const ChunkIndex& b) {
      return a.message_start_time < b.message_start_time;
    });
    for (const ChunkIndex& ci : chunks) tally_chunk(ci);
    chunk_indexes_ = std::move(chunks);
    return true;
  }

  // Counts a chunk's messages from its message indexes, without decompressing it.
  void tally_chunk(const ChunkIndex& ci) {
    if (ci.message_index_offsets.empty()) {
      read_chunk_at(ci, [&](std::uint16_t ch, std::uint64_t t, const std::uint8_t*, std::size_t) {
        tally_message(ch, t);
        return true;
      });
      return;
    }
    std::vector<std::uint8_t> header, record;
    for (const auto& [channel, offset] : ci.message_index_offsets) {
      if (!file_.read_at(offset, kRecordHeader, header) || header[0] != kMessageIndex)
        throw TruncatedData("message index outside the file");
      ByteCursor hc(header.data() + 1, 8);
      if (!file_.read_at(offset + kRecordHeader, hc.u64(), record))
        throw TruncatedData("message index runs past the end of the file");
      std::uint16_t id = 0;
      for (std::uint64_t t : parse_message_index_times(ByteCursor(record.data(), record.size()), id))
        tally_message(id, t);
    }
  }

  void tally_by_scanning() {
    scan([&](std::uint16_t ch, std::uint64_t t, const std::uint8_t*, std::size_t) {
      tally_message(ch, t);
      return true;
    });
  }

  void tally_message(std::uint16_t channel, std::uint64_t t) {
    const auto it = channels_.find(channel);
    if (it == channels_.end()) throw TruncatedData("message on an undeclared channel");
    tally_.add(it->second.topic, static_cast<std::int64_t>(t));
  }

  // Schemas and channels met while scanning are registered even from the const read path.
  // The first definition of an id wins: a later record cannot move messages to another topic.
  void add_schema(const Schema& s) const { schemas_.emplace(s.id, s); }
  void add_channel(const Channel& ch) const {
    if (!channels_.emplace(ch.id, ch).second) return;
    const auto s = schemas_.find(ch.schema_id);
    tally_.declare(ch.topic, s == schemas_.end() ? std::string() : s->second.name);
  }

  void check_encodings() const {
    for (const auto& [id, ch] : channels_)
      if (ch.message_encoding != "cdr" && ch.message_encoding != "ros1")
        throw InputError(file_.path(), "topic " + ch.topic + ": message encoding '" +
                                           ch.message_encoding +
                                           "' cannot be decoded (TunnelMap reads cdr and ros1)");
  }

  // Linear pass over the data section: records one at a time, chunks decompressed one at a
  // time. A record cut by the end of the file ends the pass with a truncation note.
  void scan(const Emit& emit) const {
    std::vector<std::uint8_t> header, content;
    std::uint64_t pos = 8;
    while (pos < file_.size()) {
      if (!file_.read_at(pos, kRecordHeader, header)) return note_truncation(pos);
      ByteCursor hc(header.data(), header.size());
      const std::uint8_t op = hc.u8();
      const std::uint64_t len = hc.u64();
      if (op == kFooter || op == kDataEnd) return;
      if (!file_.read_at(pos + kRecordHeader, len, content)) {
        note_truncation(pos);
        if (op == kChunk) read_cut_chunk(pos + kRecordHeader, emit);
        return;
      }
      if (!handle_data_record(op, ByteCursor(content.data(), content.size()), emit)) return;
      pos += kRecordHeader + len;
    }
  }

  void note_truncation(std::uint64_t pos) const {
    summary_.truncation_note = "the file ends inside the record at byte " + std::to_string(pos) +
                               "; read up to the last whole message";
  }

  // Returns false when `emit` asked to stop.
  bool handle_data_record(std::uint8_t op, ByteCursor c, const Emit& emit) const {
    if (op == kSchema) add_schema(parse_schema(c));
    if (op == kChannel) add_channel(parse_channel(c));
    if (op == kMessage) {
      const MessageHeader m = parse_message_header(c);
      return emit(m.channel_id, m.log_time, c.here(), c.remaining());
    }
    if (op == kChunk) return visit_chunk(c, emit);
    return true;
  }

  // An uncompressed chunk cut by the end of the file still holds whole messages before the
  // cut (a compressed one cannot be decoded in part).
  void read_cut_chunk(std::uint64_t content_pos, const Emit& emit) const {
    if (!file_.read_at(content_pos, file_.size() - content_pos, record_buffer_)) return;
    ByteCursor c(record_buffer_.data(), record_buffer_.size());
    std::vector<PendingMessage> messages;
    try {
      const ChunkHeader h = parse_chunk_header(c);
      if (!h.compression.empty()) return;
      collect_chunk_messages(c, messages);
    } catch (const TruncatedData&) {
    }
    emit_sorted(messages, emit);
  }

  // The chunk's records into `messages`, up to the last whole one when cut (TruncatedData
  // then propagates after the whole records were kept).
  void collect_chunk_messages(ByteCursor c, std::vector<PendingMessage>& messages) const {
    for_each_record(c, [&](std::uint8_t op, ByteCursor r) {
      if (op == kSchema) add_schema(parse_schema(r));
      if (op == kChannel) add_channel(parse_channel(r));
      if (op != kMessage) return;
      const MessageHeader m = parse_message_header(r);
      messages.push_back({m.log_time, m.channel_id, r.here(), r.remaining()});
    });
  }

  bool visit_chunk(ByteCursor c, const Emit& emit) const {
    const ChunkHeader h = parse_chunk_header(c);
    ByteCursor compressed = c.sub(h.records_size);
    try {
      decompress_chunk(h.compression, compressed.here(), compressed.remaining(), h.uncompressed_size,
                       chunk_buffer_);
    } catch (const std::runtime_error& e) {
      throw InputError(file_.path(), std::string("MCAP chunk: ") + e.what());
    }
    std::vector<PendingMessage> messages;
    collect_chunk_messages(ByteCursor(chunk_buffer_.data(), chunk_buffer_.size()), messages);
    return emit_sorted(messages, emit);
  }

  bool emit_sorted(std::vector<PendingMessage>& messages, const Emit& emit) const {
    std::stable_sort(messages.begin(), messages.end(),
                     [](const PendingMessage& a, const PendingMessage& b) { return a.log_time < b.log_time; });
    for (const PendingMessage& m : messages)
      if (!emit(m.channel, m.log_time, m.data, m.size)) return false;
    return true;
  }

  bool read_chunk_at(const ChunkIndex& ci, const Emit& emit) const {
    if (!file_.read_at(ci.chunk_start_offset, ci.chunk_length, record_buffer_) ||
        ci.chunk_length < kRecordHeader || record_buffer_[0] != kChunk)
      throw InputError(file_.path(), "chunk index points outside the file or at no chunk");
    ByteCursor c(record_buffer_.data() + kRecordHeader, record_buffer_.size() - kRecordHeader);
    return visit_chunk(c, emit);
  }

  void read_indexed_chunks(const Emit& emit) const {
    for (const ChunkIndex& ci : chunk_indexes_)
      if (!read_chunk_at(ci, emit)) return;
  }

  BinaryFile file_;
  mutable RecordingSummary summary_;
  mutable TopicTally tally_;
  mutable std::map<std::uint16_t, Schema> schemas_;
  mutable std::map<std::uint16_t, Channel> channels_;
  std::vector<ChunkIndex> chunk_indexes_;
  mutable std::vector<std::uint8_t> chunk_buffer_, record_buffer_;  // reused between chunks
};

}  // namespace

std::unique_ptr<Recording> open_mcap(const std::string& path) {
  return std::make_unique<McapRecording>(path);
}

}  // namespace tunnelmap::recordings
