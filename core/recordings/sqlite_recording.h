#pragma once
// rosbag2 sqlite3 storage (.db3), opened read-only and immutable (a bag is never modified,
// not even its -wal/-shm files). Both schemas are read: the old topics/messages tables and
// the newer one with schema, metadata and message_definitions.
#include <memory>
#include <string>

#include "core/recordings/recording.h"

namespace tunnelmap::recordings {

std::unique_ptr<Recording> open_rosbag2_sqlite(const std::string& path);

}  // namespace tunnelmap::recordings
