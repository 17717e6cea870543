#pragma once
// Field-by-field reading of one serialised ROS message, in either wire format:
//  - CDR (ROS 2): a 4-byte encapsulation header (little-endian XCDR1 expected), then fields
//    aligned to their own size relative to the end of that header, strings with a trailing NUL;
//  - ROS 1: packed little-endian fields, strings without NUL, std_msgs/Header with a seq.
// Reading past the end throws TruncatedData; the callers turn it into an error naming the
// topic and time.
#include <cstdint>
#include <string>
#include <vector>

#include "core/recordings/byte_cursor.h"
#include "core/recordings/recording.h"

namespace tunnelmap::recordings {

class MessageReader {
 public:
  MessageReader(const std::uint8_t* data, std::size_t size, MessageEncoding encoding);

  std::uint8_t u8() { return c_.u8(); }
  std::uint32_t u32() { return aligned<std::uint32_t>(); }
  std::int32_t i32() { return aligned<std::int32_t>(); }
  double f64() { return aligned<double>(); }
  std::string string();
  // A uint8[] field: its length, then a view of its bytes (no copy).
  std::pair<const std::uint8_t*, std::size_t> byte_sequence();
  std::vector<double> f64_sequence();
  void f64_array(double* out, std::size_t n);
  std::uint32_t sequence_length() { return u32(); }
  std::int64_t time_ns();  // builtin_interfaces/Time or ROS 1 time (both sec + nsec)

 private:
  template <typename T>
  T aligned() {
    align(sizeof(T));
    return c_.read<T>();
  }
  void align(std::size_t n);

  ByteCursor c_;
  MessageEncoding encoding_;
};

}  // namespace tunnelmap::recordings
