// Temporary names beside an output: the output's name plus a marker, cut to fit 255 bytes.
#include "core/util/sibling_name.h"

#include <gtest/gtest.h>

namespace tunnelmap {
namespace {

TEST(SiblingName, AShortNameKeepsItsStemMarkerAndExtension) {
  EXPECT_EQ(sibling_name("/out/map.ply", "", ".tmp-42", true), "/out/map.tmp-42.ply");
  EXPECT_EQ(sibling_name("/out/tum", ".", ".tmp-42", false), "/out/.tum.tmp-42");
}

TEST(SiblingName, ALongNameIsCutSoTheResultFits255Bytes) {
  const std::string stem(250, 'b');
  const std::string name = sibling_name("/out/" + stem + ".json", "", ".tmp-123456", true).filename().string();
  EXPECT_EQ(name.size(), 255u);
  EXPECT_EQ(name, std::string(255 - 11 - 5, 'b') + ".tmp-123456.json");
}

TEST(SiblingName, TheCutNeverSplitsAUtf8Character) {
  std::string stem;
  for (int i = 0; i < 100; ++i) stem += "\xC3\xA9";  // é, two bytes each
  const std::string name = sibling_name("/out/" + stem, ".", ".old-1234567", false).filename().string();
  // 255 - 1 - 12 = 242 bytes of room: 121 whole characters.
  EXPECT_EQ(name, "." + stem.substr(0, 242) + ".old-1234567");
  const std::string odd = sibling_name("/out/x" + stem, ".", ".old-1234567", false).filename().string();
  EXPECT_EQ(odd, ".x" + stem.substr(0, 240) + ".old-1234567");  // 241 bytes would end inside a character
}

}  // namespace
}  // namespace tunnelmap
