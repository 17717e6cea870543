#pragma once
// Counts messages and their time range per topic while a reader indexes a recording.
#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "core/recordings/recording.h"

namespace tunnelmap::recordings {

class TopicTally {
 public:
  // A topic exists once declared, even with no messages. A second declaration with another
  // type keeps the first (ROS 1 bags may hold several connections per topic).
  void declare(const std::string& topic, const std::string& type);
  void add(const std::string& topic, std::int64_t time_ns);
  void merge(const TopicInfo& other);  // another file's counts of the same topic (split bags)
  std::vector<TopicInfo> topics() const;  // sorted by name

 private:
  std::map<std::string, TopicInfo> topics_;
};

}  // namespace tunnelmap::recordings
