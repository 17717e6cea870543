#pragma once
// Names for the temporary files and folders made beside an output. They add a marker
// (".tmp-123456") to the output's own name, so an output whose name is near the file
// system's 255-byte limit would get a temporary name over it and fail to be written with a
// misleading error. The output's name is cut to make room instead.
#include <filesystem>
#include <string>

namespace tunnelmap {

// Longest file or folder name (one path component) on Linux file systems, in bytes.
constexpr std::size_t kMaxFileNameBytes = 255;

// `prefix + name + marker` beside `target`, where `name` is the target's file name; with
// `keep_extension`, the target's extension stays last (`prefix + stem + marker + extension`:
// OpenCV and VTK choose the format from it). The stem or name is cut, at a UTF-8 character
// boundary, so that the result fits kMaxFileNameBytes.
std::filesystem::path sibling_name(const std::filesystem::path& target, const std::string& prefix,
                                   const std::string& marker, bool keep_extension);

}  // namespace tunnelmap
