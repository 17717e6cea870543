// libFuzzer target: the JSON file reader's limits (core/io/json_file), on any bytes. A document
// it accepts must nest at most kMaxJsonDepth levels, measured here on the parsed document
// itself (without recursion, so the check cannot overflow the stack the limit protects); any
// refusal must be one line naming the file.
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <utility>
#include <vector>

#include "core/io/json_file.h"
#include "core/util/error.h"
#include "tests/fuzz/fuzz_util.h"

namespace {

int depth_of(const nlohmann::json& doc) {
  int deepest = 0;
  std::vector<std::pair<const nlohmann::json*, int>> todo{{&doc, 0}};
  while (!todo.empty()) {
    const auto [j, depth] = todo.back();
    todo.pop_back();
    if (!j->is_structured()) continue;
    deepest = std::max(deepest, depth + 1);
    for (const auto& child : *j) todo.push_back({&child, depth + 1});
  }
  return deepest;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace tunnelmap;
  const std::string path = (fuzz::scratch_dir("json_depth") / "doc.json").string();
  fuzz::write_bytes(path, data, size);
  try {
    if (depth_of(read_json_file(path)) > kMaxJsonDepth) std::abort();
  } catch (const InputError& e) {
    if (e.file() != path || std::strchr(e.what(), '\n') != nullptr) std::abort();
  }
  return 0;
}
