#pragma once
// Writes the bench frames as 16-bit millimetre depth PNGs so that peers built outside the
// project (scripts/bench.sh: CAPE) time exactly the frames tunnelmap_bench times.
#include <string>

namespace tunnelmap::bench {

// DIR/<name>.png per frame and DIR/frames.tsv ("name png fx fy cx cy" per line). Returns false
// with a one-line message on stderr when a file cannot be written.
bool export_bench_frames(const std::string& dir);

}  // namespace tunnelmap::bench
