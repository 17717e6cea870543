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

// Pixels in one image, checked from the header before decoding: 4096 x 4096, four times the
// largest depth camera's frame; an 8192 x 8192 frame would take over 2 GB through the pipeline.
constexpr long long kMaxImagePixels = 4096LL * 4096LL;

}  // namespace tunnelmap
