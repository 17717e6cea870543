#pragma once
// Chunk decompression for the bag formats: zstd and LZ4 frames (MCAP), bz2 and LZ4 frames
// (ROS 1, whose roslz4 writes the standard LZ4 frame format). The uncompressed size is
// always recorded in the chunk, so each call fills a buffer of exactly that size.
#include <cstdint>
#include <string>
#include <vector>

namespace tunnelmap::recordings {

// `compression`: "" or "none", "zstd", "lz4", "bz2". Throws std::runtime_error with a short
// reason when the data does not decompress to exactly `uncompressed_size` bytes, or the
// compression is unknown. `out` is reused between chunks (no allocation once large enough).
void decompress_chunk(const std::string& compression, const std::uint8_t* data, std::size_t size,
                      std::uint64_t uncompressed_size, std::vector<std::uint8_t>& out);

}  // namespace tunnelmap::recordings
