// Cross-field rules of the parameter table (cloud range, template window, odd neighbourhood):
// enforced alike by Parameters::set (the GUI's path), presets (apply_json / load_json_file) and
// --set, with one clear line; a preset or a --set list is checked once it is whole.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "core/params/parameters.h"
#include "core/util/build_paths.h"
#include "core/util/error.h"
#include "tests/support/cli_runner.h"
#include "tests/support/expect_input_error.h"

using namespace tunnelmap;
using namespace tunnelmap::testing;

namespace {

const std::string kSample = std::string(TUNNELMAP_SOURCE_DIR) + "/resources/sample/lab";

// The one-line ParameterError `f` throws.
std::string parameter_error(const std::function<void()>& f) {
  try {
    f();
  } catch (const ParameterError& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST(ParameterRules, TheTableDeclaresThem) {
  int less = 0, odd = 0;
  for (const ParameterRule& r : parameter_rules()) {
    EXPECT_NE(find_parameter(r.a), nullptr) << r.a;
    if (r.kind == ParameterRule::Kind::Less) {
      EXPECT_NE(find_parameter(r.b), nullptr) << r.b;
      ++less;
    } else {
      ++odd;
    }
  }
  EXPECT_EQ(less, 3);  // cloud range, template width, template height
  EXPECT_EQ(odd, 1);   // grow.neighbourhood_n
}

TEST(ParameterRules, SetChecksAgainstTheCurrentOtherValue) {
  Parameters p;
  // Each pair's minimum must stay below its maximum, in both directions of the edit.
  // {min key, max key, a valid max, a valid min, a min at or above that max, a max at or below
  // that min}
  const std::vector<std::tuple<std::string, std::string, double, double, double, double>> pairs = {
      {"cloud.min_range_m", "cloud.max_range_m", 1.0, 0.8, 1.0, 0.7},
      {"tunnel.width_min_m", "tunnel.width_max_m", 3.0, 0.3, 3.5, 0.2},
      {"tunnel.height_min_m", "tunnel.height_max_m", 3.0, 0.3, 3.0, 0.3}};
  for (const auto& pair : pairs) {
    // Named copies, not structured bindings: lambdas may not capture those in C++17 (clang).
    const std::string min_key = std::get<0>(pair), max_key = std::get<1>(pair);
    const double max = std::get<2>(pair), min = std::get<3>(pair), bad_min = std::get<4>(pair),
                 bad_max = std::get<5>(pair);
    p.set(max_key, max);
    p.set(min_key, min);
    const Parameters before = p;
    const std::string raised = parameter_error([&] { p.set(min_key, bad_min); });
    EXPECT_NE(raised.find("parameter '" + min_key + "'"), std::string::npos) << raised;
    EXPECT_NE(raised.find("must be less than '" + max_key + "'"), std::string::npos) << raised;
    EXPECT_EQ(raised.find('\n'), std::string::npos) << raised;
    const std::string lowered = parameter_error([&] { p.set(max_key, bad_max); });
    EXPECT_NE(lowered.find("must be less than '" + max_key + "'"), std::string::npos) << lowered;
    EXPECT_TRUE(p == before) << min_key << ": a refused value changed the parameters";
  }
  EXPECT_EQ(parameter_error([&] { p.set("grow.neighbourhood_n", 4); }),
            "parameter 'grow.neighbourhood_n' must be odd, got 4");
  // Valid edits one after the other: raise the maximum first, then the minimum.
  p.set("tunnel.width_max_m", 5.0);
  p.set("tunnel.width_min_m", 3.5);
  p.set("grow.neighbourhood_n", 7);
  EXPECT_DOUBLE_EQ(p.get("tunnel.width_min_m"), 3.5);
  EXPECT_EQ(p.get_int("grow.neighbourhood_n"), 7);
}

TEST(ParameterRules, APresetIsCheckedWhenWhole) {
  Parameters p;
  // JSON objects apply in key order: width_max (0.2, below the current min 0.3) comes first.
  p.apply_json({{"params", {{"tunnel.width_max_m", 0.2}, {"tunnel.width_min_m", 0.1}}}}, "narrow.json");
  EXPECT_DOUBLE_EQ(p.get("tunnel.width_min_m"), 0.1);
  EXPECT_DOUBLE_EQ(p.get("tunnel.width_max_m"), 0.2);

  const Parameters before = p;
  expect_input_error([&] {
    p.apply_json({{"params", {{"tunnel.height_min_m", 2.0}, {"tunnel.height_max_m", 1.0}, {"grow.angle_deg", 6.0}}}},
                 "inverted.json");
  }, {"inverted.json", "tunnel.height_min_m", "must be less than", "tunnel.height_max_m"});
  expect_input_error([&] { p.apply_json({{"params", {{"cloud.min_range_m", 0.6}, {"cloud.max_range_m", 0.5}}}}, "range.json"); },
                     {"range.json", "cloud.min_range_m", "cloud.max_range_m"});
  expect_input_error([&] { p.apply_json({{"params", {{"grow.neighbourhood_n", 6}}}}, "even.json"); },
                     {"even.json", "grow.neighbourhood_n", "must be odd"});
  EXPECT_TRUE(p == before) << "a refused preset applied some of its values";

  IoTempDir tmp;
  write_text_file(tmp.file("preset.json"), R"({"params": {"tunnel.width_min_m": 2.5, "tunnel.width_max_m": 2.0}})");
  expect_input_error([&] { p.load_json_file(tmp.file("preset.json")); },
                     {tmp.file("preset.json"), "tunnel.width_min_m", "must be less than"});
}

TEST(ParameterRules, ASetListIsCheckedWhenWhole) {
  Parameters p;
  // Sequential sets would refuse the first (3.5 > the current max 3); the list as a whole holds.
  p.set_from_strings({"tunnel.width_min_m=3.5", "tunnel.width_max_m=5"});
  EXPECT_DOUBLE_EQ(p.get("tunnel.width_min_m"), 3.5);
  const Parameters before = p;
  EXPECT_NE(parameter_error([&] { p.set_from_strings({"grow.angle_deg=6", "cloud.min_range_m=1", "cloud.max_range_m=0.8"}); })
                .find("must be less than 'cloud.max_range_m'"),
            std::string::npos);
  EXPECT_TRUE(p == before);
}

TEST(ParameterRules, CliSetAndPresetsEnforceThem) {
  // --set: exit 2 with one line; a preset: exit 3 naming the file.
  for (const char* set :
       {"--set cloud.min_range_m=1 --set cloud.max_range_m=0.8", "--set tunnel.width_min_m=3.5",
        "--set tunnel.height_max_m=0.2", "--set grow.neighbourhood_n=4"}) {
    const auto r = run_cli("detect " + kSample + " -q " + set);
    EXPECT_EQ(r.exit_code, 2) << set << "\n" << r.err;
    EXPECT_EQ(count_lines(r.err), 1) << set << "\n" << r.err;
    EXPECT_TRUE(r.err.find("must be less than") != std::string::npos || r.err.find("must be odd") != std::string::npos)
        << r.err;
  }
  IoTempDir tmp;
  write_text_file(tmp.file("inverted.json"), R"({"params": {"tunnel.height_min_m": 2, "tunnel.height_max_m": 1}})");
  const auto r = run_cli("params --params " + tmp.file("inverted.json"));
  EXPECT_EQ(r.exit_code, 3) << r.err;
  EXPECT_EQ(count_lines(r.err), 1) << r.err;
  EXPECT_NE(r.err.find("inverted.json"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("tunnel.height_min_m"), std::string::npos) << r.err;
  // Order does not matter in a --set list: the minimum raised above the old maximum first.
  const auto ok = run_cli("detect " + kSample + " -q --set tunnel.width_min_m=0.5 --set tunnel.width_max_m=3.5 "
                          "--set tunnel.width_min_m=3.2 --set tunnel.width_max_m=4");
  EXPECT_EQ(ok.exit_code, 0) << ok.err;
}
