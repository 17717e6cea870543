// `tunnelmap-cli topics BAG [--json FILE]`: the topics of a robot recording (ROS 1 bag, MCAP,
// rosbag2 sqlite3 or folder) with their types, message counts and rates, what TunnelMap can
// use each for, and a suggested command line.
#include <algorithm>
#include <cstdio>
#include <iostream>
#include <map>
#include <memory>
#include <nlohmann/json.hpp>

#include "app/cli/commands.h"
#include "app/cli/output_options.h"
#include "core/recordings/recording.h"
#include "core/recordings/topic_roles.h"
#include "core/util/atomic_file.h"
#include "core/util/error.h"

namespace tunnelmap::cli {

namespace {

using namespace recordings;
using nlohmann::json;

struct TopicsOptions {
  std::string input;
  std::string json_path;
};

// The suggested command, or why there is none (no depth topic, several candidates); and why
// an IMU is not read by it.
struct Suggestion {
  std::string command, reason, imu_note;
};

Suggestion suggest(const std::string& path, const Recording& rec, const std::map<std::string, TopicRole>& roles) {
  try {
    const TopicChoice choice = choose_topics(rec, roles, RecordingOptions{});
    return {suggested_command(path, choice), "", choice.imu_not_read_because};
  } catch (const InputError& e) {
    return {"", e.problem(), ""};
  } catch (const ParameterError& e) {
    return {"", e.what(), ""};
  }
}

json optional_json(const std::optional<double>& v) { return v ? json(*v) : json(nullptr); }

json topics_json(const std::string& path, const RecordingSummary& s, const std::map<std::string, TopicRole>& roles,
                 const Suggestion& suggestion) {
  json topics = json::array();
  for (const TopicInfo& t : s.topics) {
    const char* use = topic_role_name(roles.at(t.name));
    topics.push_back({{"name", t.name},
                      {"type", t.type},
                      {"count", t.message_count},
                      {"rate_hz", optional_json(t.rate_hz())},
                      {"use", *use ? json(use) : json(nullptr)}});
  }
  return {{"path", path},
          {"format", s.format},
          {"files", s.files},
          {"message_count", s.message_count()},
          {"topics", topics},
          {"truncated", s.truncation_note ? json(*s.truncation_note) : json(nullptr)},
          {"suggested_command", suggestion.command.empty() ? json(nullptr) : json(suggestion.command)},
          {"no_suggestion_because", suggestion.reason.empty() ? json(nullptr) : json(suggestion.reason)},
          {"imu_not_read_because", suggestion.imu_note.empty() ? json(nullptr) : json(suggestion.imu_note)}};
}

void print_table(const std::string& path, const RecordingSummary& s, const std::map<std::string, TopicRole>& roles,
                 const Suggestion& suggestion) {
  std::printf("%s: %s, %zu file%s, %zu topics, %llu messages\n", path.c_str(), s.format.c_str(), s.files.size(),
              s.files.size() == 1 ? "" : "s", s.topics.size(), static_cast<unsigned long long>(s.message_count()));
  if (s.truncation_note) std::printf("truncated: %s\n", s.truncation_note->c_str());
  std::size_t name_w = 5, type_w = 4;
  for (const TopicInfo& t : s.topics) {
    name_w = std::max(name_w, t.name.size());
    type_w = std::max(type_w, t.type.size());
  }
  std::printf("%-*s  %-*s  %8s  %9s  %s\n", static_cast<int>(name_w), "topic", static_cast<int>(type_w), "type",
              "count", "rate_hz", "use");
  for (const TopicInfo& t : s.topics) {
    char rate[32] = "-";
    if (const auto r = t.rate_hz()) std::snprintf(rate, sizeof rate, "%.2f", *r);
    std::printf("%-*s  %-*s  %8llu  %9s  %s\n", static_cast<int>(name_w), t.name.c_str(), static_cast<int>(type_w),
                t.type.c_str(), static_cast<unsigned long long>(t.message_count), rate,
                topic_role_name(roles.at(t.name)));
  }
  if (!suggestion.command.empty())
    std::printf("suggested: %s\n", suggestion.command.c_str());
  else
    std::printf("no suggestion: %s\n", suggestion.reason.c_str());
  if (!suggestion.imu_note.empty()) std::printf("no gravity: %s\n", suggestion.imu_note.c_str());
}

void run(const TopicsOptions& o, CliContext& ctx) {
  check_outputs({o.input}, {o.json_path});
  const std::unique_ptr<Recording> rec = open_recording(o.input);
  const std::map<std::string, TopicRole> roles = classify_topics(*rec);
  const Suggestion suggestion = suggest(o.input, *rec, roles);
  print_table(o.input, rec->summary(), roles, suggestion);
  if (!o.json_path.empty())
    write_file_atomically(o.json_path, [&](std::ostream& out) {
      out << topics_json(o.input, rec->summary(), roles, suggestion).dump(2) << "\n";
    });
  ctx.exit_code = 0;
}

}  // namespace

void add_topics_command(CLI::App& app, CliContext& ctx) {
  auto o = std::make_shared<TopicsOptions>();
  CLI::App* cmd = app.add_subcommand(
      "topics", "List the topics of a ROS bag (.bag, .mcap, .db3 or rosbag2 folder) and what TunnelMap can use");
  cmd->add_option("BAG", o->input, "ROS 1 bag, MCAP file, rosbag2 sqlite3 file, or rosbag2 folder")->required();
  add_output_option(cmd, "--json", o->json_path, "Also write the listing as JSON to FILE");
  cmd->callback([o, &ctx] { run(*o, ctx); });
}

}  // namespace tunnelmap::cli
