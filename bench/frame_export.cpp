#include "bench/frame_export.h"

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>

#include "bench/bench_frames.h"

namespace tunnelmap::bench {

bool export_bench_frames(const std::string& dir) {
  std::filesystem::create_directories(dir);
  std::ofstream list(dir + "/frames.tsv");
  for (const NamedFrame& nf : bench_frames()) {
    const DepthFrame& f = nf.frame;
    // Millimetres, 0 = none: the unit of every real frame and of CAPE's own input.
    const double to_mm = 1000.0 / f.depth_units_per_m;
    cv::Mat img(f.height, f.width, CV_16UC1);
    for (int v = 0; v < f.height; ++v)
      for (int u = 0; u < f.width; ++u) {
        const double mm = f.depth[static_cast<std::size_t>(v) * f.width + u] * to_mm;
        img.at<std::uint16_t>(v, u) =
            std::isfinite(mm) && mm > 0 && mm < 65535 ? static_cast<std::uint16_t>(std::lround(mm)) : 0;
      }
    const std::string png = dir + "/" + nf.name + ".png";
    if (!cv::imwrite(png, img)) {
      std::fprintf(stderr, "%s: cannot write the depth image\n", png.c_str());
      return false;
    }
    const Intrinsics& K = f.intrinsics;
    list << nf.name << '\t' << png << '\t' << K.fx << '\t' << K.fy << '\t' << K.cx << '\t' << K.cy << '\n';
  }
  list.close();
  if (!list) {
    std::fprintf(stderr, "%s/frames.tsv: cannot write the frame list\n", dir.c_str());
    return false;
  }
  return true;
}

}  // namespace tunnelmap::bench
