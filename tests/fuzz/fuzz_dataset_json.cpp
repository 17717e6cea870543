// libFuzzer target: dataset.json validation and frame loading. Each input becomes the
// dataset.json of a scratch dataset that holds real frames (depth/000000.png, rgb/000000.png,
// gt/000000.png, 4x3), a file just outside the folder (../outside.png), a symlink to it, a
// symlink to /, and a symlink loop, so that the seeds can reach every path check.
#include <cstdint>
#include <filesystem>
#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>

#include "core/io/dataset.h"
#include "core/util/error.h"
#include "tests/fuzz/fuzz_util.h"

namespace {

namespace fs = std::filesystem;

fs::path make_dataset() {
  const fs::path root = tunnelmap::fuzz::scratch_dir("dataset");
  const fs::path ds = root / "ds";
  for (const char* sub : {"depth", "rgb", "gt"}) fs::create_directories(ds / sub);
  cv::imwrite((ds / "depth/000000.png").string(), cv::Mat(3, 4, CV_16UC1, cv::Scalar(1500)));
  cv::imwrite((ds / "rgb/000000.png").string(), cv::Mat(3, 4, CV_8UC3, cv::Scalar(10, 20, 30)));
  cv::imwrite((ds / "gt/000000.png").string(), cv::Mat(3, 4, CV_16UC1, cv::Scalar(2)));
  cv::imwrite((ds / "depth/grey8.png").string(), cv::Mat(3, 4, CV_8UC1, cv::Scalar(7)));
  cv::imwrite((root / "outside.png").string(), cv::Mat(3, 4, CV_16UC1, cv::Scalar(1500)));
  std::error_code ec;
  fs::create_symlink(root / "outside.png", ds / "link_out.png", ec);
  fs::create_directory_symlink("/", ds / "root", ec);
  fs::create_symlink("loop", ds / "loop", ec);
  return ds;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace tunnelmap;
  static const fs::path ds = make_dataset();
  fuzz::write_bytes(ds / "dataset.json", data, size);
  try {
    const Dataset d = read_dataset(ds.string());
    for (std::size_t i = 0; i < d.frames.size() && i < 3; ++i) {
      try {
        d.load_frame(i);
        d.load_gt_surfaces(i);
      } catch (const InputError&) {
      }
    }
  } catch (const InputError&) {
  }
  return 0;
}
