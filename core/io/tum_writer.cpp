#include "core/io/tum_writer.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <opencv2/imgcodecs.hpp>
#include <sstream>

#include "core/io/output_folder.h"
#include "core/io/tum_sequence.h"
#include "core/io/tum_sidecar.h"
#include "core/util/atomic_file.h"
#include "core/util/error.h"
#include "core/util/image_file.h"

namespace tunnelmap {

namespace fs = std::filesystem;

namespace {

// Locale-independent numbers: "%.6f" for timestamps (as TUM), 17 digits for poses.
std::string fixed6(double v) {
  char buf[64];
  const auto r = std::to_chars(buf, buf + sizeof buf, v, std::chars_format::fixed, 6);
  return std::string(buf, r.ptr);
}
std::string exact(double v) {
  char buf[64];
  const auto r = std::to_chars(buf, buf + sizeof buf, v, std::chars_format::general, 17);
  return std::string(buf, r.ptr);
}
double parsed(const std::string& s) {
  double v = 0;
  std::from_chars(s.data(), s.data() + s.size(), v);
  return v;
}

// Timestamps as written ("%.6f", as TUM); 1/30 s steps when they would not increase.
std::vector<std::string> timestamp_texts(const Dataset& ds, const SequenceExport& ex) {
  std::vector<std::string> t;
  bool increasing = true;
  for (std::size_t i = 0; i < ds.frames.size(); ++i) {
    t.push_back(fixed6(ds.frames[i].timestamp_s));
    if (i > 0 && !(parsed(t[i]) > parsed(t[i - 1]))) increasing = false;
  }
  if (increasing) return t;
  if (ex.note)
    ex.note(ds.json_path + ": frame timestamps do not increase; the TUM sequence uses 1/30 s steps");
  for (std::size_t i = 0; i < t.size(); ++i) t[i] = fixed6(static_cast<double>(i) / 30.0);
  return t;
}

std::string lower_extension(const std::string& path) {
  std::string e = fs::path(path).extension().string();
  std::transform(e.begin(), e.end(), e.begin(), [](unsigned char c) { return std::tolower(c); });
  return e.empty() ? ".png" : e;
}

// Depth in `from_scale` units re-encoded at 5000 per metre; returns the pixels out of range.
std::size_t write_depth_5000(const DepthFrame& f, double from_scale, const fs::path& to) {
  cv::Mat img(f.height, f.width, CV_16UC1);
  std::size_t clipped = 0;
  const double k = kTumDepthScale / from_scale;
  for (int v = 0; v < f.height; ++v)
    for (int u = 0; u < f.width; ++u) {
      const double d = f.depth[static_cast<std::size_t>(v) * f.width + u];
      double out = std::isfinite(d) && d > 0 ? std::round(d * k) : 0.0;
      if (out > 65535.0) {
        out = 0.0;
        ++clipped;
      }
      img.at<std::uint16_t>(v, u) = static_cast<std::uint16_t>(out);
    }
  write_image_file(to.string(), img);
  return clipped;
}

std::string pose_line(const std::string& t, const Eigen::Isometry3d& pose) {
  Eigen::Quaterniond q(pose.linear());
  q.normalize();
  if (q.w() < 0) q.coeffs() *= -1.0;  // one of the two signs, for stable files
  const Eigen::Vector3d p = pose.translation();
  std::string s = t;
  for (double v : {p.x(), p.y(), p.z(), q.x(), q.y(), q.z(), q.w()}) s += " " + exact(v);
  return s + "\n";
}

void write_text(const fs::path& path, const std::string& text) {
  write_file_atomically(path.string(), [&](std::ostream& out) { out << text; });
}

}  // namespace

bool is_tunnelmap_tum_sequence(const fs::path& dir) {
  std::error_code ec;
  return fs::is_regular_file(dir / "depth.txt", ec) && fs::is_regular_file(dir / kTumSidecarName, ec);
}

void write_tum_sequence(const Dataset& ds, const std::string& out_dir, const SequenceExport& ex) {
  const std::size_t n = ds.frames.size();
  if (n == 0) throw InputError(ds.json_path, "the dataset has no frames");
  const std::vector<std::string> times = timestamp_texts(ds, ex);
  StagedFolder out(out_dir);
  make_folder(out.path() / "depth");

  std::string depth_txt = "# depth maps (written by TunnelMap)\n# timestamp filename\n";
  std::string rgb_txt = "# color images (written by TunnelMap)\n# timestamp filename\n";
  std::string gt_txt = "# ground truth trajectory (written by TunnelMap, camera-to-world)\n"
                       "# timestamp tx ty tz qx qy qz qw\n";
  std::size_t with_rgb = 0, with_pose = 0, clipped = 0;
  TumSidecar side;
  for (std::size_t i = 0; i < n; ++i) {
    const DatasetFrameRef& ref = ds.frames[i];
    const DepthFrame f = ds.load_frame(i);  // validates depth and colour
    const std::string depth_rel = "depth/" + times[i] + ".png";
    if (ds.depth_scale == kTumDepthScale)
      copy_file_to(ref.depth_path, out.path() / depth_rel);
    else
      clipped += write_depth_5000(f, ds.depth_scale, out.path() / depth_rel);
    depth_txt += times[i] + " " + depth_rel + "\n";
    if (ref.gravity) side.gravity[depth_rel] = *ref.gravity;
    if (!ref.rgb_path.empty()) {
      if (with_rgb++ == 0) make_folder(out.path() / "rgb");
      const std::string rgb_rel = "rgb/" + times[i] + lower_extension(ref.rgb_path);
      copy_file_to(ref.rgb_path, out.path() / rgb_rel);
      rgb_txt += times[i] + " " + rgb_rel + "\n";
    }
    const std::optional<Eigen::Isometry3d>& pose = ex.poses.empty() ? ref.pose : ex.poses[i];
    if (pose) {
      ++with_pose;
      gt_txt += pose_line(times[i], *pose);
    }
    if (ex.progress) ex.progress(i, n, (out.target() / depth_rel).string());
  }
  write_text(out.path() / "depth.txt", depth_txt);
  if (with_rgb > 0) write_text(out.path() / "rgb.txt", rgb_txt);
  if (with_pose > 0) write_text(out.path() / "groundtruth.txt", gt_txt);
  side.intrinsics = ds.intrinsics;
  side.up = ds.up;
  side.ground_truth = ds.ground_truth;
  write_text(out.path() / kTumSidecarName, tum_sidecar_json(side).dump(2) + "\n");
  out.commit();

  if (ex.note && with_pose < n)
    ex.note(out.target().string() + ": " + std::to_string(n - with_pose) + " of " + std::to_string(n) +
            " frames have no pose and no groundtruth.txt line");
  if (ex.note && clipped > 0)
    ex.note(out.target().string() + ": " + std::to_string(clipped) +
            " depth pixels beyond 13.107 m (65535 / 5000) were stored as 0 (no measurement)");
}

}  // namespace tunnelmap
