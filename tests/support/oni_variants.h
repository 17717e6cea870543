#pragma once
// The 200 single-byte changes of an .oni recording that the hostile tests play back
// (tests/hostile/oni_recording_test.cpp) and bench/oni_isolation_main.cpp measures: spread over
// the file header, the record headers, the records' fields and their payloads.
#include <cstddef>
#include <string>
#include <vector>

namespace tunnelmap::testing {

// 200 positions: the whole file header, 88 record-header bytes, 40 field bytes, 48 payload bytes.
std::vector<std::size_t> oni_change_positions(const std::string& recording);

// The k-th change at `at`: the high bit flipped, all bits set, the low bit flipped or all bits clear.
std::string oni_changed(std::string recording, std::size_t at, std::size_t k);

}  // namespace tunnelmap::testing
