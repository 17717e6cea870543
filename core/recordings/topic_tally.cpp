#include "core/recordings/topic_tally.h"

#include <algorithm>

namespace tunnelmap::recordings {

void TopicTally::declare(const std::string& topic, const std::string& type) {
  auto [it, inserted] = topics_.try_emplace(topic);
  if (inserted) {
    it->second.name = topic;
    it->second.type = type;
  } else if (it->second.type.empty()) {
    it->second.type = type;
  }
}

namespace {
void widen(TopicInfo& t, std::int64_t first_ns, std::int64_t last_ns) {
  t.first_time_ns = t.first_time_ns ? std::min(*t.first_time_ns, first_ns) : first_ns;
  t.last_time_ns = t.last_time_ns ? std::max(*t.last_time_ns, last_ns) : last_ns;
}
}  // namespace

void TopicTally::add(const std::string& topic, std::int64_t time_ns) {
  TopicInfo& t = topics_[topic];
  if (t.name.empty()) t.name = topic;
  ++t.message_count;
  widen(t, time_ns, time_ns);
}

void TopicTally::merge(const TopicInfo& other) {
  declare(other.name, other.type);
  TopicInfo& t = topics_[other.name];
  t.message_count += other.message_count;
  if (other.first_time_ns && other.last_time_ns) widen(t, *other.first_time_ns, *other.last_time_ns);
}

std::vector<TopicInfo> TopicTally::topics() const {
  std::vector<TopicInfo> out;
  out.reserve(topics_.size());
  for (const auto& [name, info] : topics_) out.push_back(info);
  return out;
}

}  // namespace tunnelmap::recordings
