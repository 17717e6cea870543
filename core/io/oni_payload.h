#pragma once
// Checks one frame payload of an OpenNI recording (.oni) against what OpenNI2's own decoders
// trust without checking: they read past their input on a damaged code stream, index tables
// with unchecked values and skip JPEG segments by unchecked lengths. A payload passes only
// if it decodes to exactly the frame size its stream declares, reading only its own bytes.
#include <cstddef>
#include <cstdint>
#include <string>

namespace tunnelmap::oni {

// The stream's codec, as the four bytes of its node record.
enum class Codec { Uncompressed, Depth16z, Depth16zTable, Jpeg };

// "NONE", "16zP", "16zT", "JPEG" -> the codec; false for any other four bytes.
bool codec_from_fourcc(const char fourcc[4], Codec& codec);

struct FrameShape {
  std::uint32_t width = 0, height = 0;
  std::uint32_t bytes_per_pixel = 0;
};

// Empty when `payload` decodes to `shape` exactly; otherwise why not (one short phrase).
std::string payload_problem(Codec codec, const std::uint8_t* payload, std::size_t size, const FrameShape& shape);

}  // namespace tunnelmap::oni
