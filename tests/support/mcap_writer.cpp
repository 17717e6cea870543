#include "tests/support/mcap_writer.h"

#include <lz4frame.h>
#include <zstd.h>

#include <algorithm>
#include <cstring>
#include <fstream>
#include <stdexcept>

namespace tunnelmap::testing {
namespace {

constexpr std::uint8_t kMagic[8] = {0x89, 'M', 'C', 'A', 'P', 0x30, '\r', '\n'};

template <typename T>
void put(std::vector<std::uint8_t>& b, T v) {
  std::uint8_t raw[sizeof(T)];
  std::memcpy(raw, &v, sizeof(T));
  b.insert(b.end(), raw, raw + sizeof(T));
}
void put_string(std::vector<std::uint8_t>& b, const std::string& s) {
  put<std::uint32_t>(b, static_cast<std::uint32_t>(s.size()));
  b.insert(b.end(), s.begin(), s.end());
}
void put_record(std::vector<std::uint8_t>& out, std::uint8_t op, const std::vector<std::uint8_t>& content) {
  out.push_back(op);
  put<std::uint64_t>(out, content.size());
  out.insert(out.end(), content.begin(), content.end());
}

std::vector<std::uint8_t> compress(const std::string& how, const std::vector<std::uint8_t>& in) {
  if (how.empty()) return in;
  std::vector<std::uint8_t> out;
  if (how == "zstd") {
    out.resize(ZSTD_compressBound(in.size()));
    out.resize(ZSTD_compress(out.data(), out.size(), in.data(), in.size(), 3));
  } else if (how == "lz4") {
    out.resize(LZ4F_compressFrameBound(in.size(), nullptr));
    out.resize(LZ4F_compressFrame(out.data(), out.size(), in.data(), in.size(), nullptr));
  } else {
    throw std::invalid_argument("compression " + how);
  }
  return out;
}

std::vector<std::uint8_t> schema_record(const std::string& type, std::uint16_t id) {
  std::vector<std::uint8_t> c;
  put<std::uint16_t>(c, id);
  put_string(c, type);
  put_string(c, "ros2msg");
  put_string(c, "");  // the definition text: not needed to read CDR of known types
  return c;
}

std::vector<std::uint8_t> channel_record(std::uint16_t id, std::uint16_t schema_id, const std::string& topic) {
  std::vector<std::uint8_t> c;
  put<std::uint16_t>(c, id);
  put<std::uint16_t>(c, schema_id);
  put_string(c, topic);
  put_string(c, "cdr");
  put<std::uint32_t>(c, 0);  // empty metadata map
  return c;
}

}  // namespace

McapWriter::McapWriter(std::string path, Options options) : path_(std::move(path)), options_(std::move(options)) {
  file_.assign(kMagic, kMagic + 8);
  std::vector<std::uint8_t> header;
  put_string(header, "ros2");
  put_string(header, "tunnelmap tests");
  put_record(file_, 0x01, header);
}

void McapWriter::write(const std::string& topic, const std::string& type, std::uint64_t log_time_ns,
                       const std::vector<std::uint8_t>& cdr) {
  auto it = channels_.find(topic);
  if (it == channels_.end()) {
    const auto id = static_cast<std::uint16_t>(channels_.size() + 1);
    it = channels_.emplace(topic, Channel{id, id, topic, type}).first;
    put_record(file_, 0x03, schema_record(type, id));
    put_record(file_, 0x04, channel_record(id, id, topic));
  }
  if (chunk_.empty()) chunk_start_ = log_time_ns;
  chunk_start_ = std::min(chunk_start_, log_time_ns);
  chunk_end_ = std::max(chunk_end_, log_time_ns);
  if (message_count_ == 0) first_time_ = log_time_ns;
  first_time_ = std::min(first_time_, log_time_ns);
  last_time_ = std::max(last_time_, log_time_ns);
  chunk_index_entries_[it->second.id].push_back({log_time_ns, chunk_.size()});
  std::vector<std::uint8_t> m;
  put<std::uint16_t>(m, it->second.id);
  put<std::uint32_t>(m, static_cast<std::uint32_t>(message_count_));
  put<std::uint64_t>(m, log_time_ns);
  put<std::uint64_t>(m, log_time_ns);
  m.insert(m.end(), cdr.begin(), cdr.end());
  put_record(chunk_, 0x05, m);
  ++message_count_;
  ++channel_counts_[it->second.id];
  if (chunk_.size() >= options_.chunk_bytes) flush_chunk();
}

void McapWriter::flush_chunk() {
  if (chunk_.empty()) return;
  const std::vector<std::uint8_t> packed = compress(options_.compression, chunk_);
  std::vector<std::uint8_t> c;
  put<std::uint64_t>(c, chunk_start_);
  put<std::uint64_t>(c, chunk_end_);
  put<std::uint64_t>(c, chunk_.size());
  put<std::uint32_t>(c, 0);  // no CRC
  put_string(c, options_.compression);
  put<std::uint64_t>(c, packed.size());
  c.insert(c.end(), packed.begin(), packed.end());
  const std::uint64_t chunk_offset = file_.size();
  put_record(file_, 0x06, c);
  const std::uint64_t chunk_length = file_.size() - chunk_offset;

  std::vector<std::uint8_t> offsets;  // channel -> message index offset, for the chunk index
  const std::uint64_t indexes_start = file_.size();
  for (const auto& [channel, entries] : chunk_index_entries_) {
    put<std::uint16_t>(offsets, channel);
    put<std::uint64_t>(offsets, file_.size());
    std::vector<std::uint8_t> mi;
    put<std::uint16_t>(mi, channel);
    put<std::uint32_t>(mi, static_cast<std::uint32_t>(entries.size() * 16));
    for (const auto& [time, offset] : entries) {
      put<std::uint64_t>(mi, time);
      put<std::uint64_t>(mi, offset);
    }
    put_record(file_, 0x07, mi);
  }
  std::vector<std::uint8_t> ci;
  put<std::uint64_t>(ci, chunk_start_);
  put<std::uint64_t>(ci, chunk_end_);
  put<std::uint64_t>(ci, chunk_offset);
  put<std::uint64_t>(ci, chunk_length);
  put<std::uint32_t>(ci, static_cast<std::uint32_t>(offsets.size()));
  ci.insert(ci.end(), offsets.begin(), offsets.end());
  put<std::uint64_t>(ci, file_.size() - indexes_start);
  put_string(ci, options_.compression);
  put<std::uint64_t>(ci, packed.size());
  put<std::uint64_t>(ci, chunk_.size());
  put_record(summary_chunk_indexes_, 0x08, ci);
  chunk_.clear();
  chunk_index_entries_.clear();
  chunk_start_ = chunk_end_ = 0;
  ++chunk_count_;
}

void McapWriter::close() {
  if (closed_) return;
  closed_ = true;
  flush_chunk();
  put_record(file_, 0x0F, std::vector<std::uint8_t>(4, 0));  // data end, no CRC
  std::uint64_t summary_start = 0;
  if (options_.summary) {
    summary_start = file_.size();
    for (const auto& [topic, ch] : channels_) put_record(file_, 0x03, schema_record(ch.type, ch.schema_id));
    for (const auto& [topic, ch] : channels_) put_record(file_, 0x04, channel_record(ch.id, ch.schema_id, topic));
    std::vector<std::uint8_t> st;
    put<std::uint64_t>(st, message_count_);
    put<std::uint16_t>(st, static_cast<std::uint16_t>(channels_.size()));
    put<std::uint32_t>(st, static_cast<std::uint32_t>(channels_.size()));
    put<std::uint32_t>(st, 0);  // attachments
    put<std::uint32_t>(st, 0);  // metadata
    put<std::uint32_t>(st, chunk_count_);
    put<std::uint64_t>(st, first_time_);
    put<std::uint64_t>(st, last_time_);
    put<std::uint32_t>(st, static_cast<std::uint32_t>(channel_counts_.size() * 10));
    for (const auto& [id, n] : channel_counts_) {
      put<std::uint16_t>(st, id);
      put<std::uint64_t>(st, n);
    }
    put_record(file_, 0x0B, st);
    file_.insert(file_.end(), summary_chunk_indexes_.begin(), summary_chunk_indexes_.end());
  }
  std::vector<std::uint8_t> footer;
  put<std::uint64_t>(footer, summary_start);
  put<std::uint64_t>(footer, 0);  // no summary offset section
  put<std::uint32_t>(footer, 0);  // no CRC
  put_record(file_, 0x02, footer);
  file_.insert(file_.end(), kMagic, kMagic + 8);
  std::ofstream out(path_, std::ios::binary | std::ios::trunc);
  out.write(reinterpret_cast<const char*>(file_.data()), static_cast<std::streamsize>(file_.size()));
  if (!out) throw std::runtime_error("cannot write " + path_);
}

}  // namespace tunnelmap::testing
