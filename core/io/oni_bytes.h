#pragma once
// Random access to the bytes of an OpenNI recording for its structural check
// (core/io/oni_container.h): a file, streamed and never held whole (recordings run to
// gigabytes), or a buffer in memory (the fuzz target); and the little-endian fields in them.
#include <cstdint>
#include <cstring>
#include <fstream>
#include <string>
#include <vector>

namespace tunnelmap::oni {

class Bytes {
 public:
  virtual ~Bytes() = default;
  virtual std::uint64_t size() const = 0;
  // Exactly n bytes at `offset` (inside size(), checked by the caller); InputError if unreadable.
  virtual void read(std::uint64_t offset, std::size_t n, std::vector<std::uint8_t>& out) const = 0;
};

class MemoryBytes : public Bytes {
 public:
  MemoryBytes(const std::uint8_t* data, std::size_t size) : data_(data), size_(size) {}
  std::uint64_t size() const override { return size_; }
  void read(std::uint64_t offset, std::size_t n, std::vector<std::uint8_t>& out) const override;

 private:
  const std::uint8_t* data_;
  std::size_t size_;
};

class FileBytes : public Bytes {
 public:
  explicit FileBytes(const std::string& path);  // InputError if it cannot be opened
  std::uint64_t size() const override { return size_; }
  void read(std::uint64_t offset, std::size_t n, std::vector<std::uint8_t>& out) const override;

 private:
  std::string path_;
  mutable std::ifstream in_;
  std::uint64_t size_ = 0;
};

// The format is little-endian, as every machine OpenNI2 runs on.
inline std::uint32_t u32_at(const std::uint8_t* p) {
  std::uint32_t v;
  std::memcpy(&v, p, 4);
  return v;
}
inline std::uint64_t u64_at(const std::uint8_t* p) {
  std::uint64_t v;
  std::memcpy(&v, p, 8);
  return v;
}

}  // namespace tunnelmap::oni
