#include "core/recordings/decompress.h"

#include <bzlib.h>
#include <lz4frame.h>
#include <zstd.h>

#include <cstring>
#include <algorithm>
#include <memory>
#include <stdexcept>

namespace tunnelmap::recordings {
namespace {

// Chunks are at most a few hundred MB; a larger claim is a corrupt header, not a real chunk,
// and must not become a giant allocation.
constexpr std::uint64_t kMaxChunkBytes = 1ull << 32;
// Nor may a claim exceed what the compressed bytes could hold: real chunks of depth images
// compress a few fold, all-zero frames a few thousand fold. Up to 256 MiB any claim is taken.
constexpr std::uint64_t kAlwaysPlausibleBytes = 256ull << 20;
constexpr std::uint64_t kMaxCompressionRatio = 4096;

// Checked before anything is allocated.
void check_claim(const std::string& compression, std::size_t size, std::uint64_t uncompressed_size) {
  if (uncompressed_size > kMaxChunkBytes)
    throw std::runtime_error("chunk claims " + std::to_string(uncompressed_size) + " bytes");
  if (compression.empty() || compression == "none") {
    if (size != uncompressed_size) throw std::runtime_error("uncompressed chunk size mismatch");
    return;
  }
  if (uncompressed_size > kAlwaysPlausibleBytes && uncompressed_size / std::max<std::size_t>(size, 1) > kMaxCompressionRatio)
    throw std::runtime_error("chunk claims " + std::to_string(uncompressed_size) + " bytes from " +
                             std::to_string(size) + " compressed");
}

void zstd_decompress(const std::uint8_t* data, std::size_t size, std::vector<std::uint8_t>& out) {
  const std::size_t n = ZSTD_decompress(out.data(), out.size(), data, size);
  if (ZSTD_isError(n)) throw std::runtime_error(std::string("zstd: ") + ZSTD_getErrorName(n));
  if (n != out.size()) throw std::runtime_error("zstd chunk is shorter than its recorded size");
}

void lz4_decompress(const std::uint8_t* data, std::size_t size, std::vector<std::uint8_t>& out) {
  LZ4F_dctx* raw = nullptr;
  if (LZ4F_isError(LZ4F_createDecompressionContext(&raw, LZ4F_VERSION)))
    throw std::runtime_error("lz4: cannot create a decompression context");
  std::unique_ptr<LZ4F_dctx, decltype(&LZ4F_freeDecompressionContext)> ctx(
      raw, LZ4F_freeDecompressionContext);
  std::size_t in_done = 0, out_done = 0;
  while (in_done < size && out_done < out.size()) {
    std::size_t in_n = size - in_done, out_n = out.size() - out_done;
    const std::size_t r = LZ4F_decompress(ctx.get(), out.data() + out_done, &out_n,
                                          data + in_done, &in_n, nullptr);
    if (LZ4F_isError(r)) throw std::runtime_error(std::string("lz4: ") + LZ4F_getErrorName(r));
    in_done += in_n;
    out_done += out_n;
    if (in_n == 0 && out_n == 0) break;
  }
  if (out_done != out.size()) throw std::runtime_error("lz4 chunk is shorter than its recorded size");
}

void bz2_decompress(const std::uint8_t* data, std::size_t size, std::vector<std::uint8_t>& out) {
  unsigned int out_n = static_cast<unsigned int>(out.size());
  const int r = BZ2_bzBuffToBuffDecompress(reinterpret_cast<char*>(out.data()), &out_n,
                                           const_cast<char*>(reinterpret_cast<const char*>(data)),
                                           static_cast<unsigned int>(size), 0, 0);
  if (r != BZ_OK) throw std::runtime_error("bz2: chunk does not decompress (code " + std::to_string(r) + ")");
  if (out_n != out.size()) throw std::runtime_error("bz2 chunk is shorter than its recorded size");
}

}  // namespace

void decompress_chunk(const std::string& compression, const std::uint8_t* data, std::size_t size,
                      std::uint64_t uncompressed_size, std::vector<std::uint8_t>& out) {
  check_claim(compression, size, uncompressed_size);
  out.resize(static_cast<std::size_t>(uncompressed_size));
  if (compression.empty() || compression == "none") {
    if (size) std::memcpy(out.data(), data, size);
  } else if (compression == "zstd") {
    zstd_decompress(data, size, out);
  } else if (compression == "lz4") {
    lz4_decompress(data, size, out);
  } else if (compression == "bz2") {
    bz2_decompress(data, size, out);
  } else {
    throw std::runtime_error("unknown chunk compression '" + compression + "'");
  }
}

}  // namespace tunnelmap::recordings
