#pragma once
// What may be written, checked before any work: an output replaces only a regular file (or
// creates one); a device, a FIFO, a socket or a folder as an output is refused, and so is an
// output that is also an input or that two outputs share. A symlink as an output is followed:
// the file it points to is written (atomically, see atomic_file.h), the link stays.
#include <filesystem>
#include <string>
#include <vector>

namespace tunnelmap {

// Where a write to `path` lands: `path`, or, if it is a symlink, the file at the end of its
// chain of links (which need not exist yet). InputError naming `path` for a link loop.
std::filesystem::path output_target(const std::string& path);

// OutputPathError (bad usage) naming `path` when it is empty or names something other than a
// regular file; InputError when its folder does not exist. Called before long runs so that
// they fail at once, not after all the work.
void check_output_path(const std::string& path);

// OutputPathError when an output is one of `inputs` (or, for an input folder, a file that readers
// take from it: its index files and frame images), or when two outputs are one file.
// Empty strings are ignored.
void check_outputs_apart(const std::vector<std::string>& inputs, const std::vector<std::string>& outputs);

}  // namespace tunnelmap
