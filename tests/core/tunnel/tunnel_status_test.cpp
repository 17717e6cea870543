// TunnelStatus names are a contract (JSON, CSV, PLY comments, printed lines): every value has
// its name, and the name reads back as the same value.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <set>
#include <sstream>
#include <string>

#include "core/tunnel/tunnel_status.h"

using namespace tunnelmap;

TEST(TunnelStatus, EveryValueRoundTripsThroughItsName) {
  std::set<std::string> names;
  for (int i = 0; i < kTunnelStatusCount; ++i) {
    const auto s = static_cast<TunnelStatus>(i);
    const std::string name = status_name(s);
    EXPECT_TRUE(names.insert(name).second) << "duplicate name " << name;
    const std::optional<TunnelStatus> back = parse_tunnel_status(name);
    ASSERT_TRUE(back.has_value()) << name;
    EXPECT_EQ(*back, s) << name;
    EXPECT_EQ(nlohmann::json(s), name);
    EXPECT_EQ(nlohmann::json(name).get<TunnelStatus>(), s) << name;
    std::ostringstream printed;
    printed << s;
    EXPECT_EQ(printed.str(), name);
  }
  EXPECT_EQ(names.size(), 12u);
}

TEST(TunnelStatus, NamesAreTheReleasedStrings) {
  // Users' scripts match these exact strings: changing one is a breaking change.
  EXPECT_STREQ(status_name(TunnelStatus::NotRun), "not_run");
  EXPECT_STREQ(status_name(TunnelStatus::Ok), "ok");
  EXPECT_STREQ(status_name(TunnelStatus::Partial), "partial");
  EXPECT_STREQ(status_name(TunnelStatus::TooFewPlanes), "too_few_planes");
  EXPECT_STREQ(status_name(TunnelStatus::MissingWall), "missing_wall");
  EXPECT_STREQ(status_name(TunnelStatus::NoParallelPair), "no_parallel_pair");
  EXPECT_STREQ(status_name(TunnelStatus::NotRectangular), "not_rectangular");
  EXPECT_STREQ(status_name(TunnelStatus::OutOfTemplate), "out_of_template");
  EXPECT_STREQ(status_name(TunnelStatus::InconsistentWithContext), "inconsistent_with_context");
  EXPECT_STREQ(status_name(TunnelStatus::TooFewPoints), "too_few_points");
  EXPECT_STREQ(status_name(TunnelStatus::DegenerateHull), "degenerate_hull");
  EXPECT_STREQ(status_name(TunnelStatus::NoDetection), "no_detection");
}

TEST(TunnelStatus, UnknownNamesAreRejected) {
  for (const char* bad : {"", "OK", "Ok", "ok ", "partial\n", "error", "missing-wall"})
    EXPECT_FALSE(parse_tunnel_status(bad).has_value()) << '"' << bad << '"';
  EXPECT_THROW(nlohmann::json("error").get<TunnelStatus>(), nlohmann::json::other_error);
  EXPECT_THROW(nlohmann::json(3).get<TunnelStatus>(), nlohmann::json::type_error);
  EXPECT_STREQ(status_name(static_cast<TunnelStatus>(kTunnelStatusCount)), "unknown");
}
