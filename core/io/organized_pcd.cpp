// The only translation unit that includes PCL's point-cloud I/O templates (they are heavy).
#include "core/io/organized_pcd.h"

#include <pcl/console/print.h>
#include <pcl/io/pcd_io.h>
#include <pcl/point_cloud.h>
#include <pcl/point_types.h>

#include <algorithm>
#include <filesystem>

#include "core/io/depth_png.h"
#include "core/io/intrinsics_estimation.h"
#include "core/io/pcd_header.h"
#include "core/util/error.h"

namespace tunnelmap {

namespace {

// PCL prints its own warnings to the console; we report one clear line instead.
class QuietPcl {
 public:
  QuietPcl() : saved_(pcl::console::getVerbosityLevel()) {
    pcl::console::setVerbosityLevel(pcl::console::L_ALWAYS);
  }
  ~QuietPcl() { pcl::console::setVerbosityLevel(saved_); }

 private:
  pcl::console::VERBOSITY_LEVEL saved_;
};

// read_pcd_header has bounded the size; here: organised, with x, y, z.
void check_fields(const std::string& path, const PcdHeader& h) {
  const auto has = [&](const char* name) {
    return std::find(h.fields.begin(), h.fields.end(), name) != h.fields.end();
  };
  if (h.height <= 1)
    throw InputError(path, "is not organised (height " + std::to_string(h.height) +
                               "); an organised PCD from a depth camera is required");
  if (!has("x") || !has("y") || !has("z")) throw InputError(path, "has no x, y, z fields");
  // PCL silently leaves fields of another type at 0: refuse them instead.
  for (std::size_t i = 0; i < h.fields.size(); ++i) {
    const std::string& f = h.fields[i];
    if ((f == "x" || f == "y" || f == "z") && (h.types[i] != 'F' || h.sizes[i] != 4 || h.counts[i] != 1))
      throw InputError(path, "field '" + f + "' must be a single 32-bit float (TYPE F, SIZE 4, COUNT 1)");
  }
}

}  // namespace

DepthFrame read_organized_pcd(const std::string& path, const ReadOptions& opt) {
  std::error_code ec;
  if (!std::filesystem::exists(path, ec)) throw InputError(path, "file not found");
  if (std::filesystem::is_directory(path, ec)) throw InputError(path, "is a folder, expected a file");
  const QuietPcl quiet;
  check_fields(path, read_pcd_header(path));

  pcl::PointCloud<pcl::PointXYZ> cloud;
  int rc = -1;
  try {
    rc = pcl::io::loadPCDFile(path, cloud);
  } catch (const std::exception&) {
    rc = -1;
  }
  if (rc < 0) throw InputError(path, "cannot read the PCD file (corrupt or truncated)");
  if (cloud.height <= 1 || !cloud.isOrganized())
    throw InputError(path, "is not organised; an organised PCD from a depth camera is required");
  if (cloud.size() != std::size_t(cloud.width) * cloud.height)
    throw InputError(path, "corrupt PCD: point count differs from WIDTH x HEIGHT");

  DepthFrame f;
  f.width = static_cast<int>(cloud.width);
  f.height = static_cast<int>(cloud.height);
  f.depth_units_per_m = 1.0;
  f.source = path;
  f.depth.resize(cloud.size());
  std::vector<Eigen::Vector3f> points(cloud.size());
  for (std::size_t i = 0; i < cloud.size(); ++i) {
    const auto& p = cloud[i];
    const bool valid = std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z) && p.z > 0;
    f.depth[i] = valid ? p.z : 0.f;
    points[i] = valid ? Eigen::Vector3f(p.x, p.y, p.z)
                      : Eigen::Vector3f::Constant(std::numeric_limits<float>::quiet_NaN());
  }
  f.intrinsics = opt.intrinsics ? intrinsics_for_image(opt, f.width, f.height)
                                : estimate_intrinsics(points, f.width, f.height, path);
  return f;
}

}  // namespace tunnelmap
