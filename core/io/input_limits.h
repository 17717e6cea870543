#pragma once
// Limits on what readers accept, each far beyond any real survey, so that a hostile or
// corrupt file fails at once with one line instead of running for minutes into gigabytes.
#include <cstddef>

namespace tunnelmap {

// A tunnel survey spans kilometres at most; a coordinate beyond this is garbage, and one such
// pose would make the fused volume and the station map span it.
constexpr double kMaxPoseTranslationM = 1e5;  // 100 km
inline constexpr const char* kMaxPoseTranslationText = "1e5 m";

// Frames in one dataset: an hour at 30 fps is 108,000; each frame read costs about 1 KB of
// index memory, so the bound keeps a dataset's index near 100 MB.
constexpr std::size_t kMaxDatasetFrames = 100000;

// Pixels in one image: a parameter, input.max_image_pixels (core/io/input_options.h), which
// the readers take as ReadOptions::max_image_pixels.

}  // namespace tunnelmap
