#include "core/util/sibling_name.h"

namespace tunnelmap {

namespace {
// `s` cut to at most `bytes` bytes, never inside a UTF-8 character.
std::string cut_utf8(const std::string& s, std::size_t bytes) {
  if (s.size() <= bytes) return s;
  std::size_t end = bytes;
  while (end > 0 && (static_cast<unsigned char>(s[end]) & 0xC0) == 0x80) --end;  // a continuation byte
  return s.substr(0, end);
}
}  // namespace

std::filesystem::path sibling_name(const std::filesystem::path& target, const std::string& prefix,
                                   const std::string& marker, bool keep_extension) {
  const std::string extension = keep_extension ? target.extension().string() : std::string();
  const std::string name = keep_extension ? target.stem().string() : target.filename().string();
  const std::size_t fixed = prefix.size() + marker.size() + extension.size();
  const std::size_t room = fixed < kMaxFileNameBytes ? kMaxFileNameBytes - fixed : 0;
  return target.parent_path() / (prefix + cut_utf8(name, room) + marker + extension);
}

}  // namespace tunnelmap
