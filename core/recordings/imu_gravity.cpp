#include "core/recordings/imu_gravity.h"

#include <algorithm>
#include <cmath>

namespace tunnelmap::recordings {
namespace {

constexpr double kStandardGravityMps2 = 9.80665;

std::int64_t bin_of(std::int64_t stamp_ns, std::int64_t bin_ns) {
  return stamp_ns >= 0 ? stamp_ns / bin_ns : -((-stamp_ns + bin_ns - 1) / bin_ns);
}

}  // namespace

void ImuGravityTrack::add(std::int64_t stamp_ns, const Eigen::Vector3d& specific_force_mps2) {
  if (!specific_force_mps2.allFinite()) return;
  const std::int64_t index = bin_of(stamp_ns, kBinNs);
  // Recordings are in time order but for a few samples: those are found, not appended.
  auto it = bins_.end();
  if (bins_.empty() || bins_.back().index < index) {
    bins_.push_back(Bin{index, Eigen::Vector3d::Zero(), 0});
    it = std::prev(bins_.end());
  } else {
    it = std::lower_bound(bins_.begin(), bins_.end(), index, [](const Bin& b, std::int64_t i) { return b.index < i; });
    if (it == bins_.end() || it->index != index) it = bins_.insert(it, Bin{index, Eigen::Vector3d::Zero(), 0});
  }
  it->sum += specific_force_mps2;
  ++it->count;
}

std::optional<Eigen::Vector3d> ImuGravityTrack::falling_at(std::int64_t stamp_ns) const {
  const std::int64_t first = bin_of(stamp_ns - kHalfWindowNs, kBinNs), last = bin_of(stamp_ns + kHalfWindowNs, kBinNs);
  auto it = std::lower_bound(bins_.begin(), bins_.end(), first, [](const Bin& b, std::int64_t i) { return b.index < i; });
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  int count = 0;
  for (; it != bins_.end() && it->index <= last; ++it) {
    sum += it->sum;
    count += it->count;
  }
  if (count == 0) return std::nullopt;
  const Eigen::Vector3d mean = sum / count;
  if (std::abs(mean.norm() - kStandardGravityMps2) > kStillToleranceMps2) return std::nullopt;
  return -mean.normalized();
}

}  // namespace tunnelmap::recordings
