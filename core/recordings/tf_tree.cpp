#include "core/recordings/tf_tree.h"

#include <algorithm>

namespace tunnelmap::recordings {

namespace {
// Frame ids are compared without a leading '/', which ROS 1 tf allowed and tf2 dropped.
std::string canonical(const std::string& frame) {
  return !frame.empty() && frame.front() == '/' ? frame.substr(1) : frame;
}

Eigen::Isometry3d make_isometry(const Eigen::Quaterniond& q, const Eigen::Vector3d& t) {
  Eigen::Isometry3d iso = Eigen::Isometry3d::Identity();
  iso.linear() = q.toRotationMatrix();
  iso.translation() = t;
  return iso;
}

constexpr std::size_t kMaxDepth = 1000;  // a cycle in a corrupt bag must not loop forever
}  // namespace

void TfTree::add(const RosTransform& t, bool is_static) {
  Edge& e = edges_[canonical(t.child_frame_id)];
  e.parent = canonical(t.header.frame_id);
  e.is_static = e.is_static || is_static;
  const Sample s{t.header.stamp_ns, Eigen::Quaterniond(t.transform.rotation()), t.transform.translation()};
  if (e.is_static) {
    e.samples.assign(1, s);  // a later static transform replaces the earlier one
    return;
  }
  // Kept in time order; messages mostly arrive in order, so this is an append.
  const auto at = std::upper_bound(e.samples.begin(), e.samples.end(), s.time_ns,
                                   [](std::int64_t time, const Sample& x) { return time < x.time_ns; });
  e.samples.insert(at, s);
}

bool TfTree::has_frame(const std::string& frame) const {
  const std::string f = canonical(frame);
  if (edges_.count(f)) return true;
  for (const auto& [child, e] : edges_)
    if (e.parent == f) return true;
  return false;
}

std::string TfTree::root_of(const std::string& frame) const { return ancestors(frame).back(); }

std::optional<Eigen::Isometry3d> TfTree::edge_at(const Edge& e, std::int64_t t,
                                                 std::int64_t tolerance_ns) const {
  if (e.samples.empty()) return std::nullopt;
  if (e.is_static) return make_isometry(e.samples.front().rotation, e.samples.front().translation);
  const std::vector<Sample>& samples = e.samples;
  const auto after = std::lower_bound(samples.begin(), samples.end(), t,
                                      [](const Sample& s, std::int64_t time) { return s.time_ns < time; });
  if (after != samples.end() && after->time_ns == t) return make_isometry(after->rotation, after->translation);
  if (after == samples.begin() || after == samples.end()) {
    // Outside the samples: only a sample within the tolerance stands for the time.
    const Sample& nearest = after == samples.end() ? samples.back() : samples.front();
    if (std::llabs(nearest.time_ns - t) > tolerance_ns) return std::nullopt;
    return make_isometry(nearest.rotation, nearest.translation);
  }
  const Sample& b = *after;
  const Sample& a = *(after - 1);
  const double w = static_cast<double>(t - a.time_ns) / static_cast<double>(b.time_ns - a.time_ns);
  return make_isometry(a.rotation.slerp(w, b.rotation), (1.0 - w) * a.translation + w * b.translation);
}

std::vector<std::string> TfTree::ancestors(const std::string& frame) const {
  std::vector<std::string> chain{canonical(frame)};
  while (chain.size() < kMaxDepth) {
    const auto it = edges_.find(chain.back());
    if (it == edges_.end()) break;
    if (std::find(chain.begin(), chain.end(), it->second.parent) != chain.end()) break;  // cycle
    chain.push_back(it->second.parent);
  }
  return chain;
}

std::optional<Eigen::Isometry3d> TfTree::lookup(const std::string& target, const std::string& source,
                                                std::int64_t time_ns, std::int64_t tolerance_ns) const {
  const std::vector<std::string> up_from_source = ancestors(source);
  const std::vector<std::string> up_from_target = ancestors(target);
  // The nearest common ancestor: the first frame above the source that is above the target.
  auto common = up_from_source.end();
  std::size_t target_depth = 0;
  for (auto it = up_from_source.begin(); it != up_from_source.end() && common == up_from_source.end(); ++it) {
    const auto hit = std::find(up_from_target.begin(), up_from_target.end(), *it);
    if (hit != up_from_target.end()) {
      common = it;
      target_depth = static_cast<std::size_t>(hit - up_from_target.begin());
    }
  }
  if (common == up_from_source.end()) return std::nullopt;
  // ancestor <- frame along one branch: the product of the edges below the ancestor.
  auto chain_to_ancestor = [&](const std::vector<std::string>& chain,
                               std::size_t depth) -> std::optional<Eigen::Isometry3d> {
    Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
    for (std::size_t k = 0; k < depth; ++k) {
      const auto edge = edge_at(edges_.at(chain[k]), time_ns, tolerance_ns);
      if (!edge) return std::nullopt;
      T = *edge * T;
    }
    return T;
  };
  const auto ancestor_from_source =
      chain_to_ancestor(up_from_source, static_cast<std::size_t>(common - up_from_source.begin()));
  const auto ancestor_from_target = chain_to_ancestor(up_from_target, target_depth);
  if (!ancestor_from_source || !ancestor_from_target) return std::nullopt;
  return ancestor_from_target->inverse() * *ancestor_from_source;
}

}  // namespace tunnelmap::recordings
