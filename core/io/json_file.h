#pragma once
// Reads a whole JSON file (dataset.json, presets): every problem, including nlohmann's
// non-parse errors such as a number overflowing a double ("1e999"), becomes one InputError line.
#include <nlohmann/json.hpp>
#include <string>

namespace tunnelmap {

// Largest JSON file accepted.
constexpr std::uintmax_t kMaxJsonFileBytes = 256u << 20;

// InputError(path, problem) for a missing/unreadable/oversized file or malformed JSON.
nlohmann::json read_json_file(const std::string& path);

}  // namespace tunnelmap
