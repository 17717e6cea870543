// libFuzzer target: the TUM RGB-D list parsers (core/io/tum_list) from memory, and the time
// pairing that consumes them. The input is a "timestamp path" list and a ground-truth list
// separated by a line "%%" (without one, the whole input is tried as both), so that the seeds
// can reach association and interpolation with timestamps the parsers accepted.
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <string>

#include "core/io/tum_associate.h"
#include "core/io/tum_list.h"
#include "core/util/error.h"

namespace {

using namespace tunnelmap;

void check_increasing(const std::vector<double>& t) {
  for (std::size_t i = 1; i < t.size(); ++i)
    if (!(t[i] > t[i - 1]) || !std::isfinite(t[i])) std::abort();
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  const std::size_t split = text.find("\n%%\n");
  const std::string list_text = split == std::string::npos ? text : text.substr(0, split + 1);
  const std::string gt_text = split == std::string::npos ? text : text.substr(split + 4);

  std::vector<TumFileEntry> list;
  std::vector<TumPoseEntry> gt;
  try {
    list = parse_tum_file_list(list_text, "depth.txt");
  } catch (const InputError&) {
  }
  try {
    gt = parse_tum_groundtruth(gt_text, "groundtruth.txt");
  } catch (const InputError&) {
  }
  std::vector<double> times, gt_times;
  for (const TumFileEntry& e : list) {
    if (e.path.empty() || e.line <= 0) std::abort();
    times.push_back(e.timestamp_s);
  }
  for (const TumPoseEntry& p : gt) {
    if (std::abs(p.rotation.norm() - 1.0) > 1e-9) std::abort();
    gt_times.push_back(p.timestamp_s);
  }
  check_increasing(times);
  check_increasing(gt_times);

  // Pair the list with itself shifted by 10 ms, and pose every listed time.
  std::vector<double> shifted;
  for (double t : times) shifted.push_back(t + 0.01);
  const std::vector<int> m = associate_nearest(times, shifted, 0.02);
  std::vector<bool> used(shifted.size(), false);
  for (int j : m) {
    if (j < -1 || j >= static_cast<int>(shifted.size())) std::abort();
    if (j >= 0 && used[static_cast<std::size_t>(j)]) std::abort();  // one-to-one
    if (j >= 0) used[static_cast<std::size_t>(j)] = true;
  }
  for (double t : times) {
    const auto pose = interpolate_pose(gt, t, 0.02);
    if (pose && !pose->matrix().allFinite()) std::abort();
  }
  for (const TumPoseEntry& p : gt)  // between two samples too
    if (const auto pose = interpolate_pose(gt, p.timestamp_s + 0.005, 0.02); pose && !pose->matrix().allFinite())
      std::abort();
  return 0;
}
