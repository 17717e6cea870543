#pragma once
// The TF tree of a recording: time series of parent <- child transforms from /tf (and pose
// topics), time-independent ones from /tf_static. A lookup composes the edges between two
// frames through their nearest common ancestor, each dynamic edge interpolated at the asked
// time (linear translation, slerp rotation), as tf2 does.
#include <Eigen/Geometry>
#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "core/recordings/ros_messages.h"

namespace tunnelmap::recordings {

class TfTree {
 public:
  void add(const RosTransform& t, bool is_static);

  // target <- source at `time_ns` (maps points of `source` into `target`). Unknown when the
  // frames are not connected, or a dynamic edge on the way has no samples on both sides of
  // the time (no extrapolation), except a sample within `tolerance_ns` of it.
  std::optional<Eigen::Isometry3d> lookup(const std::string& target, const std::string& source,
                                          std::int64_t time_ns, std::int64_t tolerance_ns = 0) const;

  bool has_frame(const std::string& frame) const;
  std::string root_of(const std::string& frame) const;  // the frame itself when it has no parent
  std::size_t edge_count() const { return edges_.size(); }

 private:
  struct Sample {
    std::int64_t time_ns;
    Eigen::Quaterniond rotation;
    Eigen::Vector3d translation;
  };
  struct Edge {
    std::string parent;
    bool is_static = false;
    std::vector<Sample> samples;  // in time order
  };
  std::optional<Eigen::Isometry3d> edge_at(const Edge& e, std::int64_t time_ns,
                                           std::int64_t tolerance_ns) const;
  std::vector<std::string> ancestors(const std::string& frame) const;  // frame, parent, ...

  std::map<std::string, Edge> edges_;  // by child frame
};

}  // namespace tunnelmap::recordings
