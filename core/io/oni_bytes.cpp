#include "core/io/oni_bytes.h"

#include "core/util/error.h"

namespace tunnelmap::oni {

void MemoryBytes::read(std::uint64_t offset, std::size_t n, std::vector<std::uint8_t>& out) const {
  out.assign(data_ + offset, data_ + offset + n);
}

FileBytes::FileBytes(const std::string& path) : path_(path), in_(path, std::ios::binary) {
  if (!in_) throw InputError(path, "cannot open");
  in_.seekg(0, std::ios::end);
  size_ = static_cast<std::uint64_t>(in_.tellg());
}

void FileBytes::read(std::uint64_t offset, std::size_t n, std::vector<std::uint8_t>& out) const {
  out.resize(n);
  in_.seekg(static_cast<std::streamoff>(offset));
  if (!in_.read(reinterpret_cast<char*>(out.data()), static_cast<std::streamsize>(n)))
    throw InputError(path_, "cannot read " + std::to_string(n) + " bytes at byte " + std::to_string(offset));
}

}  // namespace tunnelmap::oni
