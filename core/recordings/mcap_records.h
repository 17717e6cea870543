#pragma once
// The MCAP records TunnelMap reads, parsed from their bytes as the MCAP specification lays
// them out (opcode u8, length u64, fields little-endian, strings u32-prefixed). Every
// parser throws TruncatedData when a field runs past its record.
#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "core/recordings/byte_cursor.h"

namespace tunnelmap::recordings::mcap {

inline constexpr std::uint8_t kMagic[8] = {0x89, 'M', 'C', 'A', 'P', 0x30, '\r', '\n'};

enum Opcode : std::uint8_t {
  kHeader = 0x01, kFooter = 0x02, kSchema = 0x03, kChannel = 0x04, kMessage = 0x05,
  kChunk = 0x06, kMessageIndex = 0x07, kChunkIndex = 0x08, kStatistics = 0x0B, kDataEnd = 0x0F,
};

struct Schema {
  std::uint16_t id = 0;
  std::string name, encoding;
};
struct Channel {
  std::uint16_t id = 0, schema_id = 0;
  std::string topic, message_encoding;
};
struct MessageHeader {  // the data follows in the record
  std::uint16_t channel_id = 0;
  std::uint64_t log_time = 0;
};
struct ChunkHeader {  // the (compressed) records follow in the record
  std::uint64_t uncompressed_size = 0;
  std::string compression;
  std::uint64_t records_size = 0;
};
struct ChunkIndex {
  std::uint64_t message_start_time = 0, chunk_start_offset = 0, chunk_length = 0;
  std::map<std::uint16_t, std::uint64_t> message_index_offsets;
};
struct Footer {
  std::uint64_t summary_start = 0;
};

Schema parse_schema(ByteCursor c);
Channel parse_channel(ByteCursor c);
MessageHeader parse_message_header(ByteCursor& c);  // leaves `c` at the message data
ChunkHeader parse_chunk_header(ByteCursor& c);      // leaves `c` at the records
ChunkIndex parse_chunk_index(ByteCursor c);
Footer parse_footer(ByteCursor c);
// A MessageIndex record's log times (one per message of its channel in the chunk).
std::vector<std::uint64_t> parse_message_index_times(ByteCursor c, std::uint16_t& channel_id);

// Calls visit(opcode, content) for each whole record in `c`; throws TruncatedData when the
// last record is cut.
template <typename Visit>
void for_each_record(ByteCursor c, Visit&& visit) {
  while (!c.at_end()) {
    const std::uint8_t op = c.u8();
    const std::uint64_t len = c.u64();
    visit(op, c.sub(len));
  }
}

}  // namespace tunnelmap::recordings::mcap
