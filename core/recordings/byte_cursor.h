#pragma once
// Bounds-checked little-endian reading of a byte span: the record formats of MCAP, ROS 1 bags
// and CDR are all little-endian with length-prefixed strings. Reading past the end throws
// TruncatedData, so a malformed length can never read outside the buffer.
#include <cstdint>
#include <cstring>
#include <stdexcept>
#include <string>

namespace tunnelmap::recordings {

class TruncatedData : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

class ByteCursor {
 public:
  ByteCursor(const std::uint8_t* data, std::size_t size) : data_(data), size_(size) {}

  std::size_t position() const { return pos_; }
  std::size_t remaining() const { return size_ - pos_; }
  bool at_end() const { return pos_ == size_; }
  const std::uint8_t* here() const { return data_ + pos_; }

  void skip(std::uint64_t n) {
    need(n);
    pos_ += static_cast<std::size_t>(n);
  }
  void seek(std::size_t pos) {
    if (pos > size_) throw TruncatedData("offset beyond the end of the data");
    pos_ = pos;
  }
  template <typename T>
  T read() {
    need(sizeof(T));
    T v;
    std::memcpy(&v, data_ + pos_, sizeof(T));
    pos_ += sizeof(T);
    return v;
  }
  std::uint8_t u8() { return read<std::uint8_t>(); }
  std::uint16_t u16() { return read<std::uint16_t>(); }
  std::uint32_t u32() { return read<std::uint32_t>(); }
  std::uint64_t u64() { return read<std::uint64_t>(); }
  std::string bytes_as_string(std::uint64_t n) {
    need(n);
    std::string s(reinterpret_cast<const char*>(data_ + pos_), static_cast<std::size_t>(n));
    pos_ += static_cast<std::size_t>(n);
    return s;
  }
  std::string string_u32() { return bytes_as_string(u32()); }  // uint32 length + bytes
  // A sub-cursor over the next n bytes (the cursor moves past them).
  ByteCursor sub(std::uint64_t n) {
    need(n);
    ByteCursor c(data_ + pos_, static_cast<std::size_t>(n));
    pos_ += static_cast<std::size_t>(n);
    return c;
  }

 private:
  void need(std::uint64_t n) const {
    if (n > size_ - pos_) throw TruncatedData("record runs past the end of its data");
  }
  const std::uint8_t* data_;
  std::size_t size_;
  std::size_t pos_ = 0;
};

}  // namespace tunnelmap::recordings
