#pragma once
// The pixel size a compressed image (PNG or JPEG, as image_transport writes them) declares in
// its header, read before anything is decoded: a small message that declares a huge image is
// refused before the decoder allocates it.
#include <cstddef>
#include <cstdint>

namespace tunnelmap::recordings {

// False when the bytes are neither a PNG with its IHDR nor a JPEG with a frame header.
bool compressed_image_size(const std::uint8_t* data, std::size_t size, int& width, int& height);

}  // namespace tunnelmap::recordings
