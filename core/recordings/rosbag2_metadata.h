#pragma once
// The parts of a rosbag2 folder's metadata.yaml that decide how it is read: its storage
// files in order (a split bag) and each topic's serialization format. A line-based reader
// of the layout rosbag2 writes, not a general YAML parser.
#include <map>
#include <string>
#include <vector>

namespace tunnelmap::recordings {

struct Rosbag2Metadata {
  std::vector<std::string> relative_file_paths;
  std::map<std::string, std::string> serialization_formats;  // topic -> format
};

Rosbag2Metadata parse_rosbag2_metadata(const std::string& yaml_text);

}  // namespace tunnelmap::recordings
