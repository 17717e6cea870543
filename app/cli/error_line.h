#pragma once
// The one stderr line of a failed run. A message may echo a hostile field (a 100 KB frame path,
// a line break, a NUL): it is cut and its control characters shown as escapes, so that the
// error stays one readable line.
#include <string>

namespace tunnelmap::cli {

// Longest part of a message kept (a file name plus an echoed field fit well within it).
constexpr std::size_t kMaxErrorChars = 400;

std::string error_line(const std::string& message);

}  // namespace tunnelmap::cli
