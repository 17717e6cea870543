#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "core/params/parameters.h"
#include "core/util/error.h"

using namespace tunnelmap;

TEST(Parameters, DefaultsAreThePapersValues) {
  Parameters p;
  EXPECT_DOUBLE_EQ(p.get("grow.angle_deg"), 4.0);
  EXPECT_DOUBLE_EQ(p.get("grow.distance_mm"), 15.0);
  EXPECT_DOUBLE_EQ(p.get("grow.candidate_distance_mm"), 40.0);
  EXPECT_EQ(p.get_int("grow.min_points"), 40);
  EXPECT_DOUBLE_EQ(p.get("grow.min_area_m2"), 0.004);
  EXPECT_DOUBLE_EQ(p.get("cloud.max_range_m"), 5.0);
  EXPECT_EQ(p.get_int("grow.neighbourhood_n"), 5);
  EXPECT_DOUBLE_EQ(p.get("tunnel.zone_cluster_mm"), 10.0);
  EXPECT_DOUBLE_EQ(p.get("tunnel.context_tolerance_mm"), 40.0);
}

TEST(Parameters, EveryDefaultLiesInItsRange) {
  for (const auto& spec : parameter_table()) {
    EXPECT_GE(spec.default_value, spec.min) << spec.key;
    EXPECT_LE(spec.default_value, spec.max) << spec.key;
    EXPECT_GT(spec.step, 0) << spec.key;
    EXPECT_FALSE(spec.description.empty()) << spec.key;
  }
}

TEST(Parameters, RejectsUnknownKeysAndAbsurdValues) {
  Parameters p;
  EXPECT_THROW(p.set("grow.nope", 1), ParameterError);
  EXPECT_THROW(p.set("grow.angle_deg", -3), ParameterError);
  EXPECT_THROW(p.set("grow.angle_deg", std::nan("")), ParameterError);
  EXPECT_THROW(p.set("grow.min_points", 40.5), ParameterError);
  EXPECT_THROW(p.set("grow.neighbourhood_n", 4), ParameterError);
  EXPECT_THROW(p.set_from_string("grow.angle_deg=abc"), ParameterError);
  EXPECT_THROW(p.set_from_string("grow.angle_deg"), ParameterError);
  EXPECT_DOUBLE_EQ(p.get("grow.angle_deg"), 4.0);  // untouched after failures
  p.set_from_string("grow.angle_deg=6.5");
  EXPECT_DOUBLE_EQ(p.get("grow.angle_deg"), 6.5);
}

TEST(Parameters, PresetJsonIsAllOrNothing) {
  Parameters p;
  nlohmann::json bad = {{"params", {{"grow.angle_deg", 7.0}, {"grow.unknown", 1}}}};
  try {
    p.apply_json(bad, "preset.json");
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("preset.json"), std::string::npos);
    EXPECT_NE(std::string(e.what()).find("grow.unknown"), std::string::npos);
  }
  EXPECT_DOUBLE_EQ(p.get("grow.angle_deg"), 4.0);
  p.apply_json({{"name", "x"}, {"params", {{"grow.angle_deg", 7.0}}}}, "ok.json");
  EXPECT_DOUBLE_EQ(p.get("grow.angle_deg"), 7.0);
}

TEST(Parameters, JsonRoundTrip) {
  Parameters p;
  p.set("grow.angle_deg", 5.5);
  p.set("grow.min_points", 80);
  Parameters q;
  q.apply_json({{"params", p.to_json()}}, "mem");
  EXPECT_TRUE(p == q);
}
