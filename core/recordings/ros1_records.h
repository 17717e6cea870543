#pragma once
// ROS 1 bag format 2.0 records, as the rosbag specification lays them out: a u32-prefixed
// header of u32-prefixed "name=value" fields (the "op" field gives the record type), then a
// u32-prefixed data block. Parsers throw TruncatedData when a field runs past its record.
#include <cstdint>
#include <map>
#include <string>

#include "core/recordings/byte_cursor.h"

namespace tunnelmap::recordings::ros1 {

inline constexpr char kMagic[] = "#ROSBAG V2.0\n";
inline constexpr std::size_t kMagicSize = 13;

enum Op : std::uint8_t {
  kMessageData = 0x02, kBagHeader = 0x03, kIndexData = 0x04, kChunk = 0x05, kChunkInfo = 0x06,
  kConnection = 0x07,
};

using HeaderFields = std::map<std::string, std::string>;

HeaderFields parse_header_fields(ByteCursor c);
std::uint8_t field_op(const HeaderFields& h);  // TruncatedData when the op field is missing
std::uint32_t field_u32(const HeaderFields& h, const std::string& name);
std::uint64_t field_u64(const HeaderFields& h, const std::string& name);
std::string field_string(const HeaderFields& h, const std::string& name);  // "" when absent
// ROS time (u32 seconds, u32 nanoseconds) in nanoseconds.
std::int64_t field_time_ns(const HeaderFields& h, const std::string& name);
std::int64_t read_time_ns(ByteCursor& c);

struct Record {
  HeaderFields header;
  ByteCursor data;
};

// One whole record at the cursor (the cursor moves past it).
Record read_record(ByteCursor& c);

struct Connection {
  std::uint32_t id = 0;
  std::string topic, type;
};
Connection parse_connection(const Record& r);

}  // namespace tunnelmap::recordings::ros1
