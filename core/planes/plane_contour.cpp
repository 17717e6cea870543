#include "core/planes/plane_contour.h"

#include <opencv2/imgproc.hpp>

namespace tunnelmap {

void compute_contour(const std::vector<std::int32_t>& labels, int width, const Intrinsics& K,
                     PlaneSegment& plane, double tolerance_px) {
  plane.contour.clear();
  const int u0 = plane.bbox_u0, v0 = plane.bbox_v0;
  const int bw = plane.bbox_u1 - u0 + 1, bh = plane.bbox_v1 - v0 + 1;
  // One pixel of padding so that regions touching the box border still close. The mask and
  // contour buffers are per thread and only grow: no allocation per plane in the steady state.
  thread_local std::vector<std::uint8_t> mask_buffer;
  thread_local std::vector<std::vector<cv::Point>> contours;
  thread_local std::vector<cv::Point> poly;
  const std::size_t mask_size = static_cast<std::size_t>(bh + 2) * (bw + 2);
  if (mask_buffer.size() < mask_size) mask_buffer.resize(mask_size);
  std::fill(mask_buffer.begin(), mask_buffer.begin() + mask_size, 0);
  cv::Mat mask(bh + 2, bw + 2, CV_8UC1, mask_buffer.data());
  for (int v = 0; v < bh; ++v) {
    const std::int32_t* row = labels.data() + static_cast<std::size_t>(v + v0) * width + u0;
    std::uint8_t* m = mask.ptr<std::uint8_t>(v + 1) + 1;
    for (int u = 0; u < bw; ++u) m[u] = row[u] == plane.id ? 255 : 0;
  }
  cv::findContours(mask, contours, cv::RETR_EXTERNAL, cv::CHAIN_APPROX_SIMPLE);
  if (contours.empty()) return;
  std::size_t best = 0;
  double best_area = -1;
  for (std::size_t i = 0; i < contours.size(); ++i) {
    const double a = cv::contourArea(contours[i]);
    if (a > best_area) best_area = a, best = i;
  }
  cv::approxPolyDP(contours[best], poly, tolerance_px, true);
  plane.contour.reserve(poly.size());
  for (const cv::Point& pt : poly) {
    const Eigen::Vector3d ray = K.ray(pt.x - 1 + u0, pt.y - 1 + v0);
    const double denom = plane.normal.dot(ray);
    if (std::abs(denom) < 1e-9) continue;  // ray parallel to the plane
    const double t = -plane.offset_m / denom;
    if (t > 0) plane.contour.push_back(ray * t);
  }
}

}  // namespace tunnelmap
