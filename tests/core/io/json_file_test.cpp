// read_json_file: every JSON problem is one InputError line naming the file.
#include <gtest/gtest.h>

#include "core/io/json_file.h"
#include "tests/support/expect_input_error.h"
#include "tests/support/io_temp_dir.h"

namespace tunnelmap {
namespace {

using testing::IoTempDir;
using testing::expect_input_error;

TEST(JsonFile, EveryJsonProblemIsOneInputErrorLine) {
  // Found by fuzzing the presets: nlohmann throws out_of_range, not parse_error, for "1e999".
  IoTempDir tmp;
  testing::write_text_file(tmp.file("overflow.json"), "{\"params\": {\"grow.angle_deg\": 1e999}}");
  expect_input_error([&] { read_json_file(tmp.file("overflow.json")); }, {"overflow.json", "malformed JSON", "overflow"});
  testing::write_text_file(tmp.file("bad_utf8.json"), "{\"a\": \"\xff\"}");
  expect_input_error([&] { read_json_file(tmp.file("bad_utf8.json")); }, {"bad_utf8.json", "malformed JSON"});
  expect_input_error([&] { read_json_file(tmp.file("none.json")); }, {"none.json", "not found"});
  expect_input_error([&] { read_json_file(tmp.path().string()); }, {"folder"});
  testing::write_text_file(tmp.file("ok.json"), "{\"a\": [1, 2.5]}");
  EXPECT_DOUBLE_EQ(read_json_file(tmp.file("ok.json"))["a"][1].get<double>(), 2.5);
}

}  // namespace
}  // namespace tunnelmap
