#include "core/mapping/section_sizes.h"

#include <algorithm>
#include <cmath>

#include "core/util/median.h"

namespace tunnelmap {

namespace {
// Views of one size agree within a few times a band's noise, far below a plate's thickness.
constexpr double kAgreeM = 0.001;
}  // namespace

void SectionSizes::record(const std::vector<FramePatch>& patches) {
  for (const FramePatch& p : patches)
    for (const FramePatch& q : patches) {
      if (p.plate || q.plate || p.wall % 2 != 0 || q.wall != p.wall + 1 || q.band != p.band) continue;
      const Eigen::Vector3d across = (q.normal - p.normal).normalized();
      const double size = across.dot(q.centroid - p.centroid);
      if (std::isfinite(size)) sizes_[{p.wall / 2, p.band}].push_back(size);
    }
}

double SectionSizes::change(int dimension, const std::vector<long>& before, const std::vector<long>& after,
                            double tolerance_m) const {
  const Extremes a = clustered_extremes(dimension, before), b = clustered_extremes(dimension, after);
  if (std::isnan(a.smallest) || std::isnan(b.smallest)) return std::nan("");
  const bool a_one = a.largest == a.smallest, b_one = b.largest == b.smallest;
  if (a_one && b_one) return std::nan("");
  if (!a_one && !b_one) {
    const double smallest = b.smallest - a.smallest, largest = b.largest - a.largest;
    return std::abs(largest - smallest) <= tolerance_m ? 0.5 * (smallest + largest) : std::nan("");
  }
  // The one cluster may be any of the other side's: the change lies between these two.
  const double low = b.smallest - a.largest, high = b.largest - a.smallest;
  if (low > 0.0) return low;
  if (high < 0.0) return high;
  return std::nan("");
}

SectionSizes::Extremes SectionSizes::clustered_extremes(int dimension, const std::vector<long>& bands) const {
  std::vector<long> unique_bands = bands;  // several ties may name one band
  std::sort(unique_bands.begin(), unique_bands.end());
  unique_bands.erase(std::unique(unique_bands.begin(), unique_bands.end()), unique_bands.end());
  std::vector<double> sizes;
  for (long band : unique_bands)
    if (const auto it = sizes_.find({dimension, band}); it != sizes_.end())
      sizes.insert(sizes.end(), it->second.begin(), it->second.end());
  std::sort(sizes.begin(), sizes.end());
  Extremes out{std::nan(""), std::nan("")};
  for (std::size_t first = 0, next = 0; first < sizes.size(); first = next) {
    next = first + 1;
    while (next < sizes.size() && sizes[next] - sizes[next - 1] <= kAgreeM) ++next;
    if (next - first < 2) continue;  // a size no second view confirms
    const double size = median_of_measured(std::vector<double>(sizes.begin() + first, sizes.begin() + next));
    if (std::isnan(out.smallest)) out.smallest = size;
    out.largest = size;
  }
  return out;
}

}  // namespace tunnelmap
