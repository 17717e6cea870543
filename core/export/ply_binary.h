#pragma once
// Little helpers for binary little-endian PLY bodies (byte order fixed, whatever the host).
#include <cstdint>
#include <cstring>
#include <ostream>

namespace tunnelmap::ply {

inline void put_u8(std::ostream& out, std::uint8_t v) { out.put(static_cast<char>(v)); }

inline void put_u32(std::ostream& out, std::uint32_t v) {
  const char b[4] = {char(v & 0xff), char((v >> 8) & 0xff), char((v >> 16) & 0xff),
                     char((v >> 24) & 0xff)};
  out.write(b, 4);
}

inline void put_i32(std::ostream& out, std::int32_t v) { put_u32(out, static_cast<std::uint32_t>(v)); }

inline void put_f32(std::ostream& out, float v) {
  std::uint32_t bits;
  std::memcpy(&bits, &v, 4);
  put_u32(out, bits);
}

struct Rgb {
  std::uint8_t r, g, b;
};

}  // namespace tunnelmap::ply
