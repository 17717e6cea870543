#pragma once
// A structural check of an OpenNI recording (.oni) before OpenNI2's player opens it. The
// player trusts the file: record sizes, string lengths, node ids, frame sizes and table
// positions go into its buffers unchecked, so a single damaged byte can crash or hang it
// inside the process. The check walks the whole record chain as the player would, with every
// size and offset bounded by the file, and every frame payload decoded in outline
// (core/io/oni_payload.h). It accepts what OpenNI2's recorder writes (format 1.0.1.0) and
// refuses anything else with one line naming the file, before OpenNI sees it.
#include <cstddef>
#include <cstdint>
#include <string>

namespace tunnelmap::oni {

// InputError(path, reason) unless the recording at `path` passes; a stream's frames may have
// at most `max_pixels` pixels (ReadOptions::max_image_pixels).
void check_recording_file(const std::string& path, long long max_pixels);

// The same check on a recording in memory; `name` is the file the error names.
void check_recording(const std::uint8_t* data, std::size_t size, const std::string& name, long long max_pixels);

}  // namespace tunnelmap::oni
