#pragma once
// Reads a whole JSON file (dataset.json, presets): every problem, including nlohmann's
// non-parse errors such as a number overflowing a double ("1e999"), becomes one InputError line.
#include <nlohmann/json.hpp>
#include <string>

namespace tunnelmap {

// Largest JSON file accepted.
constexpr std::uintmax_t kMaxJsonFileBytes = 256u << 20;
// Deepest nesting accepted: our files nest 6 levels; 100,000 '[' would exhaust the stack or
// the memory of the code that walks the document.
constexpr int kMaxJsonDepth = 64;

// InputError(path, problem) for a missing/unreadable/oversized file or malformed JSON.
nlohmann::json read_json_file(const std::string& path);

}  // namespace tunnelmap
