#include "core/recordings/binary_file.h"

#include <sys/stat.h>

#include "core/util/error.h"

namespace tunnelmap::recordings {

BinaryFile::BinaryFile(const std::string& path) : path_(path) {
  struct stat st {};
  if (::stat(path.c_str(), &st) != 0 || !S_ISREG(st.st_mode))
    throw InputError(path, "cannot open the recording (not a readable file)");
  file_ = std::fopen(path.c_str(), "rb");
  if (!file_) throw InputError(path, "cannot open the recording");
  size_ = static_cast<std::uint64_t>(st.st_size);
}

BinaryFile::~BinaryFile() {
  if (file_) std::fclose(file_);
}

bool BinaryFile::read_at(std::uint64_t offset, std::uint64_t n, std::vector<std::uint8_t>& out) const {
  if (offset > size_ || n > size_ - offset) return false;
  out.resize(static_cast<std::size_t>(n));
  if (n == 0) return true;
  if (fseeko(file_, static_cast<off_t>(offset), SEEK_SET) != 0) return false;
  return std::fread(out.data(), 1, out.size(), file_) == out.size();
}

}  // namespace tunnelmap::recordings
