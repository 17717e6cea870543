#include "app/cli/error_line.h"

#include <cstdio>

namespace tunnelmap::cli {

std::string error_line(const std::string& message) {
  std::string line;
  for (const char ch : message.substr(0, kMaxErrorChars)) {
    if (static_cast<unsigned char>(ch) < 0x20 || ch == 0x7f) {
      char escaped[8];
      std::snprintf(escaped, sizeof escaped, "\\x%02x", static_cast<unsigned char>(ch));
      line += escaped;
    } else {
      line += ch;
    }
  }
  if (message.size() > kMaxErrorChars)
    line += "... (" + std::to_string(message.size() - kMaxErrorChars) + " more characters)";
  return line;
}

}  // namespace tunnelmap::cli
