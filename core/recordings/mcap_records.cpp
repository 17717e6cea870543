#include "core/recordings/mcap_records.h"

namespace tunnelmap::recordings::mcap {

Schema parse_schema(ByteCursor c) {
  Schema s;
  s.id = c.u16();
  s.name = c.string_u32();
  s.encoding = c.string_u32();
  return s;  // the schema data (the message definition) is not needed
}

Channel parse_channel(ByteCursor c) {
  Channel ch;
  ch.id = c.u16();
  ch.schema_id = c.u16();
  ch.topic = c.string_u32();
  ch.message_encoding = c.string_u32();
  return ch;
}

MessageHeader parse_message_header(ByteCursor& c) {
  MessageHeader m;
  m.channel_id = c.u16();
  c.u32();  // sequence
  m.log_time = c.u64();
  c.u64();  // publish time
  return m;
}

ChunkHeader parse_chunk_header(ByteCursor& c) {
  ChunkHeader h;
  c.u64();  // message start time
  c.u64();  // message end time
  h.uncompressed_size = c.u64();
  c.u32();  // uncompressed crc
  h.compression = c.string_u32();
  h.records_size = c.u64();
  return h;
}

ChunkIndex parse_chunk_index(ByteCursor c) {
  ChunkIndex ci;
  ci.message_start_time = c.u64();
  c.u64();  // message end time
  ci.chunk_start_offset = c.u64();
  ci.chunk_length = c.u64();
  ByteCursor offsets = c.sub(c.u32());
  while (!offsets.at_end()) {
    const std::uint16_t channel = offsets.u16();
    ci.message_index_offsets[channel] = offsets.u64();
  }
  return ci;
}

Footer parse_footer(ByteCursor c) {
  Footer f;
  f.summary_start = c.u64();
  return f;
}

std::vector<std::uint64_t> parse_message_index_times(ByteCursor c, std::uint16_t& channel_id) {
  channel_id = c.u16();
  ByteCursor entries = c.sub(c.u32());
  std::vector<std::uint64_t> times;
  times.reserve(entries.remaining() / 16);
  while (!entries.at_end()) {
    times.push_back(entries.u64());
    entries.u64();  // offset inside the uncompressed chunk
  }
  return times;
}

}  // namespace tunnelmap::recordings::mcap
