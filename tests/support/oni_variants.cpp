#include "tests/support/oni_variants.h"

#include <cstdint>
#include <cstring>

namespace tunnelmap::testing {

namespace {

constexpr std::size_t kFileHeaderBytes = 24, kRecordHeaderBytes = 28;

std::uint32_t u32_at(const std::string& b, std::size_t at) {
  std::uint32_t v;
  std::memcpy(&v, b.data() + at, 4);
  return v;
}

// Every byte of the recording by its part: the file header, the record headers, the records'
// fields and their payloads (frames and seek tables), following the record chain to its end.
struct Parts {
  std::vector<std::size_t> header, record_headers, fields, payloads;
};

Parts parts_of(const std::string& b) {
  Parts p;
  for (std::size_t i = 0; i < kFileHeaderBytes; ++i) p.header.push_back(i);
  for (std::size_t pos = kFileHeaderBytes; pos + kRecordHeaderBytes <= b.size();) {
    const std::uint32_t type = u32_at(b, pos + 4), fields = u32_at(b, pos + 12), payload = u32_at(b, pos + 16);
    for (std::size_t i = 0; i < kRecordHeaderBytes; ++i) p.record_headers.push_back(pos + i);
    for (std::size_t i = kRecordHeaderBytes; i < fields; ++i) p.fields.push_back(pos + i);
    for (std::size_t i = 0; i < payload; ++i) p.payloads.push_back(pos + fields + i);
    pos += fields + payload;
    if (type == 11) break;  // the end record
  }
  return p;
}

// `n` positions spread evenly over `from`.
void take_spread(const std::vector<std::size_t>& from, std::size_t n, std::vector<std::size_t>& to) {
  for (std::size_t k = 0; k < n && !from.empty(); ++k) to.push_back(from[k * from.size() / n]);
}

}  // namespace

// 200 positions: the whole file header, 88 record-header bytes, 40 field bytes, 48 payload bytes.
std::vector<std::size_t> oni_change_positions(const std::string& b) {
  const Parts p = parts_of(b);
  std::vector<std::size_t> at = p.header;
  take_spread(p.record_headers, 88, at);
  take_spread(p.fields, 40, at);
  take_spread(p.payloads, 48, at);
  return at;
}

// The k-th change: the high bit flipped, all bits set, the low bit flipped or all bits clear.
std::string oni_changed(std::string b, std::size_t at, std::size_t k) {
  const auto old = static_cast<unsigned char>(b[at]);
  static const int kinds[] = {0x80, -1, 0x01, -2};
  const int kind = kinds[k % 4];
  unsigned char now = kind == -1 ? 0xFF : kind == -2 ? 0x00 : static_cast<unsigned char>(old ^ kind);
  if (now == old) now = static_cast<unsigned char>(old ^ 0x55);
  b[at] = static_cast<char>(now);
  return b;
}

}  // namespace tunnelmap::testing
