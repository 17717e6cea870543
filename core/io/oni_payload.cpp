#include "core/io/oni_payload.h"

#include <cstring>

namespace tunnelmap::oni {

namespace {

std::uint16_t le16(const std::uint8_t* p) { return static_cast<std::uint16_t>(p[0] | (p[1] << 8)); }
std::uint16_t be16(const std::uint8_t* p) { return static_cast<std::uint16_t>((p[0] << 8) | p[1]); }

// Walks a 16z code stream (OpenNI's differential depth code) without writing the pixels:
// counts them, and with a value table checks every value is an index into it. OpenNI's
// decoder stops only when its read position equals the end, so a code that steps over the
// end would make it read on through memory: the walk must land on the end exactly.
class Code16zWalk {
 public:
  Code16zWalk(const std::uint8_t* p, std::size_t size, std::uint64_t pixels, std::uint32_t table_size)
      : p_(p), end_(size), pixels_(pixels), table_size_(table_size) {}

  std::string run(std::size_t start, std::uint16_t first) {
    pos_ = start;
    value_ = first;
    if (!emit(1)) return problem_;
    while (pos_ != end_) {
      const std::uint8_t c = p_[pos_];
      if (c < 0xE0) {
        if (!step(c >> 4)) return problem_;
        const int low = c & 0x0F;
        ++pos_;
        if (low == 0x0F) {
          if (!escape()) return problem_;
        } else if (low != 0x0D && !step(low)) {
          return problem_;
        }
      } else if (c == 0xFF) {
        ++pos_;
        if (!escape()) return problem_;
      } else {
        if (!emit(2u * (c - 0xE0u))) return problem_;  // a run of repeated values
        ++pos_;
      }
    }
    if (count_ != pixels_)
      return "depth code gives " + std::to_string(count_) + " pixels, expected " + std::to_string(pixels_);
    return {};
  }

 private:
  bool fail(const std::string& why) {
    problem_ = why;
    return false;
  }
  bool emit(std::uint64_t n) {
    if (n == 0) return true;
    if (table_size_ && value_ >= table_size_) return fail("depth code refers to value " + std::to_string(value_) +
                                                          " of a table of " + std::to_string(table_size_));
    count_ += n;
    if (count_ > pixels_) return fail("depth code gives more than the frame's " + std::to_string(pixels_) + " pixels");
    return true;
  }
  bool step(int nibble) {
    value_ = static_cast<std::uint16_t>(value_ - (nibble - 6));
    return emit(1);
  }
  // After an escape: one byte of difference (high bit set) or a whole big-endian value.
  bool escape() {
    if (pos_ >= end_) return fail("depth code ends inside a value");
    const std::uint8_t b = p_[pos_];
    if (b & 0x80) {
      value_ = static_cast<std::uint16_t>(value_ - (b - 192));
      ++pos_;
    } else {
      if (pos_ + 1 >= end_) return fail("depth code ends inside a value");
      value_ = be16(p_ + pos_);
      pos_ += 2;
    }
    return emit(1);
  }

  const std::uint8_t* p_;
  std::size_t end_, pos_ = 0;
  std::uint64_t pixels_, count_ = 0;
  std::uint32_t table_size_;
  std::uint16_t value_ = 0;
  std::string problem_;
};

std::string check_16z(const std::uint8_t* p, std::size_t size, std::uint64_t pixels) {
  if (size < 2) return "depth code shorter than its first value";
  return Code16zWalk(p, size, pixels, 0).run(2, le16(p));
}

std::string check_16z_table(const std::uint8_t* p, std::size_t size, std::uint64_t pixels) {
  if (size < 2) return "depth code has no value table";
  const std::uint32_t entries = le16(p);
  const std::size_t start = 2 + 2 * static_cast<std::size_t>(entries);
  if (entries == 0) return "depth code has an empty value table";
  if (start + 2 > size) return "depth value table of " + std::to_string(entries) + " entries runs past the frame";
  return Code16zWalk(p, size, pixels, entries).run(start + 2, le16(p + start));
}

bool is_frame_header(std::uint8_t m) { return m >= 0xC0 && m <= 0xCF && m != 0xC4 && m != 0xC8 && m != 0xCC; }

// Only the single-scan JPEG OpenNI's recorder writes: segments with lengths inside the frame up
// to one start-of-scan, then entropy-coded bytes holding no marker but restarts, then the end
// marker as the frame's last two bytes. OpenNI's JPEG source skips segments by their declared
// length without a bound and has no more data to give, so any other layout could make it read
// past the frame or wait for bytes that never come.
std::string check_jpeg(const std::uint8_t* p, std::size_t size, const FrameShape& shape) {
  if (shape.bytes_per_pixel != 3) return "JPEG frames in a stream of " + std::to_string(shape.bytes_per_pixel) + " bytes per pixel";
  if (size < 4 || p[0] != 0xFF || p[1] != 0xD8) return "JPEG frame does not start with its start-of-image marker";
  if (p[size - 2] != 0xFF || p[size - 1] != 0xD9) return "JPEG frame does not end with its end-of-image marker";
  std::size_t pos = 2;
  bool sized = false;
  for (;;) {
    if (pos + 4 > size - 2 || p[pos] != 0xFF) return "JPEG frame has a damaged segment at byte " + std::to_string(pos);
    const std::uint8_t marker = p[pos + 1];
    const std::size_t length = be16(p + pos + 2);
    if (length < 2 || pos + 2 + length > size - 2) return "JPEG segment at byte " + std::to_string(pos) + " runs past the frame";
    if (is_frame_header(marker)) {
      if (length < 8) return "JPEG frame header is too short";
      const std::uint32_t h = be16(p + pos + 5), w = be16(p + pos + 7), components = p[pos + 9];
      if (w != shape.width || h != shape.height || components != 3)
        return "JPEG frame is " + std::to_string(w) + "x" + std::to_string(h) + " with " + std::to_string(components) +
               " components, the stream " + std::to_string(shape.width) + "x" + std::to_string(shape.height) + " RGB";
      sized = true;
    }
    pos += 2 + length;
    if (marker == 0xDA) break;
    if (marker == 0xD9 || marker == 0xD8 || (marker >= 0xD0 && marker <= 0xD7) || marker == 0x01 || marker == 0xFF || marker == 0x00)
      return "JPEG frame has an unexpected marker at byte " + std::to_string(pos - 2 - length);
  }
  if (!sized) return "JPEG frame has no frame header before its scan";
  for (std::size_t i = pos; i + 2 < size; ++i)
    if (p[i] == 0xFF && p[i + 1] != 0x00 && !(p[i + 1] >= 0xD0 && p[i + 1] <= 0xD7))
      return "JPEG scan holds a marker at byte " + std::to_string(i);
  return {};
}

}  // namespace

bool codec_from_fourcc(const char fourcc[4], Codec& codec) {
  static const struct {
    const char* name;
    Codec codec;
  } known[] = {{"NONE", Codec::Uncompressed}, {"16zP", Codec::Depth16z}, {"16zT", Codec::Depth16zTable}, {"JPEG", Codec::Jpeg}};
  for (const auto& k : known)
    if (std::memcmp(fourcc, k.name, 4) == 0) {
      codec = k.codec;
      return true;
    }
  return false;
}

std::string payload_problem(Codec codec, const std::uint8_t* payload, std::size_t size, const FrameShape& shape) {
  const std::uint64_t pixels = static_cast<std::uint64_t>(shape.width) * shape.height;
  const std::uint64_t bytes = pixels * shape.bytes_per_pixel;
  if (size == 0) return "empty frame";
  switch (codec) {
    case Codec::Uncompressed:
      return size == bytes ? std::string() : std::to_string(size) + " bytes for a frame of " + std::to_string(bytes);
    case Codec::Depth16z:
    case Codec::Depth16zTable:
      if (shape.bytes_per_pixel != 2) return "depth code in a stream of " + std::to_string(shape.bytes_per_pixel) + " bytes per pixel";
      return codec == Codec::Depth16z ? check_16z(payload, size, pixels) : check_16z_table(payload, size, pixels);
    case Codec::Jpeg:
      return check_jpeg(payload, size, shape);
  }
  return "unknown codec";
}

}  // namespace tunnelmap::oni
