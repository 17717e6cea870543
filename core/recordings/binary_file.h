#pragma once
// Random-access reads of a file that may be far larger than memory: a bag is read record by
// record at known offsets, never loaded whole.
#include <cstdint>
#include <cstdio>
#include <string>
#include <vector>

namespace tunnelmap::recordings {

class BinaryFile {
 public:
  explicit BinaryFile(const std::string& path);  // InputError when it cannot be opened
  ~BinaryFile();
  BinaryFile(const BinaryFile&) = delete;
  BinaryFile& operator=(const BinaryFile&) = delete;

  const std::string& path() const { return path_; }
  std::uint64_t size() const { return size_; }
  // Reads [offset, offset+n) into `out` (resized to n). False when the file ends before.
  bool read_at(std::uint64_t offset, std::uint64_t n, std::vector<std::uint8_t>& out) const;

 private:
  std::string path_;
  std::FILE* file_ = nullptr;
  std::uint64_t size_ = 0;
};

}  // namespace tunnelmap::recordings
