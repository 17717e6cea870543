#pragma once
// Writes output files so that a failed or interrupted run never leaves a truncated file and
// never destroys the previous one: write to "<path>.tmp-XXXX" beside it, then rename.
#include <functional>
#include <ostream>
#include <string>

#include "core/util/output_path.h"  // check_output_path: what may be written

namespace tunnelmap {

// Calls `write` with a binary stream on a temporary file next to `path`; on success renames it
// over `path` (over the file a symlink `path` points to, which keeps the link). Refuses what
// check_output_path refuses. On any failure (exception from `write`, stream error, rename error) removes the
// temporary file and throws InputError naming `path`.
void write_file_atomically(const std::string& path, const std::function<void(std::ostream&)>& write);

// For writers that need a file name (OpenCV, VTK): `write` receives the temporary path.
void write_path_atomically(const std::string& path,
                           const std::function<void(const std::string& tmp_path)>& write);

}  // namespace tunnelmap
