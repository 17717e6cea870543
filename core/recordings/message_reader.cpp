#include "core/recordings/message_reader.h"

namespace tunnelmap::recordings {

namespace {
// A sequence cannot hold more elements than bytes remain: checked before any allocation so a
// corrupt length never becomes a huge vector.
void check_count(std::uint64_t count, std::size_t element_size, std::size_t remaining) {
  if (count > remaining / element_size) throw TruncatedData("sequence longer than its message");
}
}  // namespace

MessageReader::MessageReader(const std::uint8_t* data, std::size_t size, MessageEncoding encoding)
    : c_(data, size), encoding_(encoding) {
  if (encoding_ != MessageEncoding::Cdr) return;
  ByteCursor header(data, size);
  header.u8();
  const std::uint8_t kind = header.u8();
  header.u16();  // options
  // 0x01 CDR_LE, 0x03 PL_CDR_LE; 0x00/0x02 are big-endian, which ROS 2 on PCs never writes.
  if (kind != 0x01 && kind != 0x03) throw TruncatedData("CDR payload is not little-endian");
  c_ = ByteCursor(data + 4, size - 4);
}

void MessageReader::align(std::size_t n) {
  if (encoding_ != MessageEncoding::Cdr) return;
  const std::size_t misalign = c_.position() % n;
  if (misalign) c_.skip(n - misalign);
}

std::string MessageReader::string() {
  const std::uint32_t n = u32();
  std::string s = c_.bytes_as_string(n);
  if (encoding_ == MessageEncoding::Cdr && !s.empty() && s.back() == '\0') s.pop_back();
  return s;
}

std::pair<const std::uint8_t*, std::size_t> MessageReader::byte_sequence() {
  const std::uint32_t n = u32();
  const std::uint8_t* p = c_.here();
  c_.skip(n);
  return {p, n};
}

std::vector<double> MessageReader::f64_sequence() {
  const std::uint32_t n = u32();
  check_count(n, 8, c_.remaining());  // each f64() aligns itself (no padding when empty)
  std::vector<double> v(n);
  for (double& x : v) x = f64();
  return v;
}

void MessageReader::f64_array(double* out, std::size_t n) {
  for (std::size_t i = 0; i < n; ++i) out[i] = f64();
}

std::int64_t MessageReader::time_ns() {
  const std::int64_t sec = encoding_ == MessageEncoding::Cdr ? i32() : static_cast<std::int64_t>(u32());
  const std::uint32_t nsec = u32();
  return sec * 1000000000LL + nsec;
}

}  // namespace tunnelmap::recordings
