#pragma once
// MCAP files (ROS 2's default bag storage), read from the specification: the summary
// section's chunk and message indexes when present, a scan of the data section otherwise.
#include <memory>
#include <string>

#include "core/recordings/recording.h"

namespace tunnelmap::recordings {

std::unique_ptr<Recording> open_mcap(const std::string& path);

}  // namespace tunnelmap::recordings
