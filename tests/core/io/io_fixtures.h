#pragma once
// Inputs shared by the reader tests: an organised PCD plane cloud (organised PCD and the input
// dispatcher) and a valid two-frame dataset folder (dataset folders and the input dispatcher).
#include <pcl/point_cloud.h>
#include <pcl/point_types.h>

#include <filesystem>
#include <functional>
#include <limits>
#include <nlohmann/json.hpp>
#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>
#include <string>
#include <vector>

#include "core/frame/intrinsics.h"
#include "core/io/dataset.h"
#include "tests/support/expect_input_error.h"
#include "tests/support/io_temp_dir.h"

namespace tunnelmap::testing {

inline const Intrinsics kPcdTruth{301.5, 298.25, 39.3, 29.8, 80, 60};

// A tilted plane seen by a camera with kPcdTruth, with a rectangular hole of NaNs.
inline pcl::PointCloud<pcl::PointXYZ> organised_plane_cloud() {
  pcl::PointCloud<pcl::PointXYZ> cloud(80, 60);
  const float nan = std::numeric_limits<float>::quiet_NaN();
  for (int v = 0; v < 60; ++v)
    for (int u = 0; u < 80; ++u) {
      auto& p = cloud.at(u, v);
      if (u >= 10 && u < 20 && v >= 5 && v < 15) {
        p.x = p.y = p.z = nan;
        continue;
      }
      const float z = 1.5f + 0.01f * u + 0.004f * v;
      p.x = static_cast<float>((u - kPcdTruth.cx) * z / kPcdTruth.fx);
      p.y = static_cast<float>((v - kPcdTruth.cy) * z / kPcdTruth.fy);
      p.z = z;
    }
  cloud.is_dense = false;
  return cloud;
}

constexpr int kDsW = 32, kDsH = 24;

// A valid 2-frame dataset: depth, rgb and ground-truth images, poses, joints, up, ground truth.
struct DatasetFixture {
  using json = nlohmann::json;
  IoTempDir tmp;
  json j;

  DatasetFixture() {
    namespace fs = std::filesystem;
    fs::create_directories(tmp.path() / "depth");
    fs::create_directories(tmp.path() / "rgb");
    fs::create_directories(tmp.path() / "gt");
    for (int i = 0; i < 2; ++i) {
      const std::string n = "00000" + std::to_string(i) + ".png";
      cv::Mat d(kDsH, kDsW, CV_16UC1, cv::Scalar(1200 + 100 * i));
      cv::Mat rgb(kDsH, kDsW, CV_8UC3, cv::Scalar(10, 20, 30));  // B G R
      cv::Mat gt(kDsH, kDsW, CV_16UC1, cv::Scalar(3));
      gt.at<std::uint16_t>(0, 1) = 7;
      cv::imwrite(tmp.file("depth/" + n), d);
      cv::imwrite(tmp.file("rgb/" + n), rgb);
      cv::imwrite(tmp.file("gt/" + n), gt);
    }
    // Frame 1: camera rotated 90 degrees about world Z, at (1, 2, 3).
    j = json::parse(R"({
      "format": "tunnelmap-dataset/1",
      "simulator": {"seed": 4},
      "intrinsics": {"fx": 28.5, "fy": 28.6, "cx": 15.5, "cy": 11.5, "width": 32, "height": 24},
      "depth_scale": 1000,
      "up": [0, 0, 2],
      "frames": [
        {"depth": "depth/000000.png", "rgb": "rgb/000000.png", "gt_surfaces": "gt/000000.png",
         "pose": [1,0,0,0, 0,1,0,0, 0,0,1,0, 0,0,0,1], "joints": [0.1, -0.2, 0.3], "timestamp": 0.5,
         "pose_group": 2, "distance_to_manhole_m": 1.25},
        {"depth": "depth/000001.png",
         "pose": [0,-1,0,1, 1,0,0,2, 0,0,1,3, 0,0,0,1], "timestamp": 1.0}
      ],
      "robot": {"links": [0.3, 0.25]},
      "ground_truth": {"width_m": 0.82, "height_m": 1.30, "material": "steel"}
    })");
  }
  std::string json_path() const { return tmp.file("dataset.json"); }
  std::string write() const {
    testing::write_text_file(json_path(), j.dump(2));
    return json_path();
  }
  // Writes `j` after `edit` and expects read_dataset to fail naming dataset.json and `parts`.
  void expect_error(const std::function<void(json&)>& edit, std::vector<std::string> parts) {
    json saved = j;
    edit(j);
    write();
    parts.insert(parts.begin(), json_path());
    expect_input_error([&] { read_dataset(tmp.path().string()); }, parts);
    j = saved;
  }
};

}  // namespace tunnelmap::testing
