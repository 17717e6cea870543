#pragma once
// Expects `f` to throw InputError with a one-line message containing every string in `parts`.
#include <gtest/gtest.h>

#include <functional>
#include <string>
#include <vector>

#include "core/util/error.h"

namespace tunnelmap::testing {

inline void expect_input_error(const std::function<void()>& f, const std::vector<std::string>& parts) {
  try {
    f();
    ADD_FAILURE() << "expected InputError containing '" << parts.front() << "'";
  } catch (const InputError& e) {
    const std::string msg = e.what();
    EXPECT_EQ(msg.find('\n'), std::string::npos) << "message is not one line: " << msg;
    for (const auto& p : parts) EXPECT_NE(msg.find(p), std::string::npos) << "'" << p << "' not in: " << msg;
  }
}

}  // namespace tunnelmap::testing
