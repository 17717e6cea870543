#include "core/recordings/ros1_records.h"

#include <cstring>

namespace tunnelmap::recordings::ros1 {

HeaderFields parse_header_fields(ByteCursor c) {
  HeaderFields fields;
  while (!c.at_end()) {
    const std::string field = c.string_u32();
    const std::size_t eq = field.find('=');
    if (eq == std::string::npos) throw TruncatedData("header field without '='");
    fields[field.substr(0, eq)] = field.substr(eq + 1);
  }
  return fields;
}

namespace {
const std::string& field_bytes(const HeaderFields& h, const std::string& name, std::size_t size) {
  const auto it = h.find(name);
  if (it == h.end() || it->second.size() != size)
    throw TruncatedData("record header lacks the field '" + name + "'");
  return it->second;
}
}  // namespace

std::uint8_t field_op(const HeaderFields& h) {
  return static_cast<std::uint8_t>(field_bytes(h, "op", 1)[0]);
}

std::uint32_t field_u32(const HeaderFields& h, const std::string& name) {
  std::uint32_t v;
  std::memcpy(&v, field_bytes(h, name, 4).data(), 4);
  return v;
}

std::uint64_t field_u64(const HeaderFields& h, const std::string& name) {
  std::uint64_t v;
  std::memcpy(&v, field_bytes(h, name, 8).data(), 8);
  return v;
}

std::string field_string(const HeaderFields& h, const std::string& name) {
  const auto it = h.find(name);
  return it == h.end() ? std::string() : it->second;
}

std::int64_t read_time_ns(ByteCursor& c) {
  const std::uint32_t sec = c.u32();
  const std::uint32_t nsec = c.u32();
  return static_cast<std::int64_t>(sec) * 1000000000LL + nsec;
}

std::int64_t field_time_ns(const HeaderFields& h, const std::string& name) {
  const std::string& bytes = field_bytes(h, name, 8);
  ByteCursor c(reinterpret_cast<const std::uint8_t*>(bytes.data()), 8);
  return read_time_ns(c);
}

Record read_record(ByteCursor& c) {
  ByteCursor header = c.sub(c.u32());
  ByteCursor data = c.sub(c.u32());
  return Record{parse_header_fields(header), data};
}

Connection parse_connection(const Record& r) {
  Connection conn;
  conn.id = field_u32(r.header, "conn");
  conn.topic = field_string(r.header, "topic");
  const HeaderFields details = parse_header_fields(r.data);
  conn.type = field_string(details, "type");
  return conn;
}

}  // namespace tunnelmap::recordings::ros1
