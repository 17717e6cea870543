#pragma once
// ROS 1 bags (format 2.0), read from the rosbag format specification: the index at the end
// (connections, chunk infos and the per-chunk index data) when the bag was closed properly,
// a scan of the chunks otherwise. Chunks may be uncompressed, bz2 or lz4.
#include <memory>
#include <string>

#include "core/recordings/recording.h"

namespace tunnelmap::recordings {

std::unique_ptr<Recording> open_ros1_bag(const std::string& path);

}  // namespace tunnelmap::recordings
