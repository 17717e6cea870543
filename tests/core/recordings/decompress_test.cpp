// Chunk decompression: a chunk decompresses to exactly its recorded size, and a recorded size
// that the compressed bytes could not hold is refused before it is allocated (a corrupt header
// must not become a 4 GB allocation; the MCAP fuzz target found one).
#include <gtest/gtest.h>

#include <stdexcept>
#include <vector>
#include <zstd.h>

#include "core/recordings/decompress.h"

namespace tunnelmap::recordings {
namespace {

std::vector<std::uint8_t> zstd_of(const std::vector<std::uint8_t>& data) {
  std::vector<std::uint8_t> out(ZSTD_compressBound(data.size()));
  out.resize(ZSTD_compress(out.data(), out.size(), data.data(), data.size(), 3));
  return out;
}

TEST(Decompress, AZstdChunkComesBackWhole) {
  std::vector<std::uint8_t> data(100000);
  for (std::size_t i = 0; i < data.size(); ++i) data[i] = static_cast<std::uint8_t>(i * 7 % 251);
  const std::vector<std::uint8_t> packed = zstd_of(data);
  std::vector<std::uint8_t> out;
  decompress_chunk("zstd", packed.data(), packed.size(), data.size(), out);
  EXPECT_EQ(out, data);
}

TEST(Decompress, ASizeTheCompressedBytesCannotHoldIsRefusedUpFront) {
  const std::vector<std::uint8_t> packed = zstd_of(std::vector<std::uint8_t>(1000, 1));
  std::vector<std::uint8_t> out;
  try {
    decompress_chunk("zstd", packed.data(), packed.size(), 4261413036ull, out);
    FAIL() << "no error";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("compressed"), std::string::npos) << e.what();
  }
  EXPECT_LT(out.capacity(), 1u << 20);  // nothing was allocated for the claim
  EXPECT_THROW(decompress_chunk("", packed.data(), packed.size(), packed.size() + 1, out), std::runtime_error);
  EXPECT_THROW(decompress_chunk("zstd", packed.data(), packed.size(), 999, out), std::runtime_error);
}

}  // namespace
}  // namespace tunnelmap::recordings
