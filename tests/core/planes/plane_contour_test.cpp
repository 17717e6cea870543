// Plane contours: the allocation-free border tracer and Douglas-Peucker against OpenCV
// (findContours RETR_EXTERNAL/CHAIN_APPROX_SIMPLE + largest contourArea + approxPolyDP),
// which stays here only as the reference.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <opencv2/imgproc.hpp>
#include <random>
#include <string>

#include "core/io/depth_png.h"
#include "core/pipeline/pipeline.h"
#include "core/planes/boundary_trace.h"
#include "core/planes/plane_contour.h"
#include "core/planes/polygon_simplify.h"
#include "core/sim/tunnel_simulator.h"
#include "core/util/build_paths.h"

using namespace tunnelmap;

namespace {

constexpr std::int32_t kLabel = 7;
constexpr std::int32_t kOtherLabel = 3;

struct Box {
  int u0, v0, u1, v1;
};

struct LabelImage {
  int width = 0, height = 0;
  std::vector<std::int32_t> labels;
};

std::vector<PixelPoint> to_pixels(const std::vector<cv::Point>& pts) {
  std::vector<PixelPoint> out;
  for (const cv::Point& p : pts) out.push_back({p.x, p.y});
  return out;
}

std::vector<cv::Point> to_cv(const std::vector<PixelPoint>& pts) {
  std::vector<cv::Point> out;
  for (const PixelPoint& p : pts) out.emplace_back(p.x, p.y);
  return out;
}

std::string describe(const std::vector<PixelPoint>& pts) {
  std::string s;
  for (const PixelPoint& p : pts) s += "(" + std::to_string(p.x) + "," + std::to_string(p.y) + ")";
  return s;
}

// OpenCV's answer: the largest-area external contour of `label` in the box, image coordinates
// (the first of equal areas in OpenCV's list, as compute_contour used to pick it).
std::vector<cv::Point> opencv_largest_outer(const LabelImage& img, std::int32_t label, const Box& b) {
  const int bw = b.u1 - b.u0 + 1, bh = b.v1 - b.v0 + 1;
  cv::Mat mask = cv::Mat::zeros(bh + 2, bw + 2, CV_8UC1);
  for (int v = 0; v < bh; ++v)
    for (int u = 0; u < bw; ++u)
      mask.at<std::uint8_t>(v + 1, u + 1) = img.labels[(v + b.v0) * img.width + u + b.u0] == label ? 255 : 0;
  std::vector<std::vector<cv::Point>> contours;
  cv::findContours(mask, contours, cv::RETR_EXTERNAL, cv::CHAIN_APPROX_SIMPLE);
  std::vector<cv::Point> best;
  double best_area = -1;
  for (const auto& c : contours) {
    const double a = cv::contourArea(c);
    if (a > best_area) best_area = a, best = c;
  }
  for (cv::Point& p : best) p += cv::Point(b.u0 - 1, b.v0 - 1);
  return best;
}

// compute_contour as it was with OpenCV: the reference for the pipeline comparisons.
void opencv_compute_contour(const std::vector<std::int32_t>& labels, int width, const Intrinsics& K,
                            PlaneSegment& plane, double tolerance_px = 1.0) {
  plane.contour.clear();
  const LabelImage img{width, static_cast<int>(labels.size()) / width, labels};
  const std::vector<cv::Point> outer =
      opencv_largest_outer(img, plane.id, {plane.bbox_u0, plane.bbox_v0, plane.bbox_u1, plane.bbox_v1});
  if (outer.empty()) return;
  std::vector<cv::Point> poly;
  cv::approxPolyDP(outer, poly, tolerance_px, true);
  for (const cv::Point& pt : poly) {
    const Eigen::Vector3d ray = K.ray(pt.x, pt.y);
    const double denom = plane.normal.dot(ray);
    if (std::abs(denom) < 1e-9) continue;
    const double t = -plane.offset_m / denom;
    if (t > 0) plane.contour.push_back(ray * t);
  }
}

// Random scene drawn with OpenCV: blobs (ellipses, rectangles) with holes, one-pixel lines
// (4- and 8-connected), single pixels, speckle, another label next to ours; several
// 8-connected components of kLabel, often touching the image border.
LabelImage random_scene(std::mt19937& rng) {
  std::uniform_int_distribution<int> size_w(1, 70), size_h(1, 50);
  const int w = size_w(rng), h = size_h(rng);
  cv::Mat img = cv::Mat::zeros(h, w, CV_8UC1);
  const auto ux = [&] { return std::uniform_int_distribution<int>(-3, w + 2)(rng); };
  const auto uy = [&] { return std::uniform_int_distribution<int>(-3, h + 2)(rng); };
  const auto pick = [&](int n) { return std::uniform_int_distribution<int>(0, n - 1)(rng); };
  const int shapes = 1 + pick(10);
  for (int i = 0; i < shapes; ++i) {
    const std::uint8_t value = pick(4) == 0 ? kOtherLabel : pick(6) == 0 ? 0 : kLabel;  // 0 cuts holes
    const int kind = pick(6);
    if (kind == 0) {
      cv::ellipse(img, {ux(), uy()}, {1 + pick(std::max(1, w / 2)), 1 + pick(std::max(1, h / 2))}, pick(180), 0, 360,
                  value, cv::FILLED, cv::LINE_8);
    } else if (kind == 1) {
      cv::rectangle(img, cv::Point(ux(), uy()), cv::Point(ux(), uy()), value, cv::FILLED);
    } else if (kind == 2) {
      cv::line(img, {ux(), uy()}, {ux(), uy()}, value, 1, pick(2) ? cv::LINE_8 : cv::LINE_4);
    } else if (kind == 3) {
      cv::circle(img, {ux(), uy()}, 1 + pick(8), value, 1 + pick(2), cv::LINE_8);  // rings: holes
    } else if (kind == 4) {
      for (int k = pick(12); k > 0; --k) img.at<std::uint8_t>(pick(h), pick(w)) = value;
    } else {
      cv::ellipse(img, {ux(), uy()}, {1 + pick(6), 1 + pick(6)}, 0, 0, 360, 0, cv::FILLED);  // hole
    }
  }
  LabelImage out{w, h, {}};
  out.labels.assign(img.begin<std::uint8_t>(), img.end<std::uint8_t>());
  return out;
}

// Random smooth blobs with ragged borders, holes and islands, as grown regions look.
LabelImage random_blobs(std::mt19937& rng, int w, int h) {
  cv::Mat noise(h, w, CV_32FC1);
  std::uniform_real_distribution<float> U(0.0f, 1.0f);
  for (int v = 0; v < h; ++v)
    for (int u = 0; u < w; ++u) noise.at<float>(v, u) = U(rng);
  cv::GaussianBlur(noise, noise, cv::Size(0, 0), 2.5);
  LabelImage out{w, h, std::vector<std::int32_t>(static_cast<std::size_t>(w) * h)};
  for (int v = 0; v < h; ++v)
    for (int u = 0; u < w; ++u) {
      const float x = noise.at<float>(v, u);
      out.labels[v * w + u] = x > 0.5f ? kLabel : x < 0.45f ? kOtherLabel : 0;
    }
  return out;
}

Box label_bbox(const LabelImage& img, std::int32_t label) {
  Box b{img.width, img.height, -1, -1};
  for (int v = 0; v < img.height; ++v)
    for (int u = 0; u < img.width; ++u)
      if (img.labels[v * img.width + u] == label)
        b = {std::min(b.u0, u), std::min(b.v0, v), std::max(b.u1, u), std::max(b.v1, v)};
  return b;
}

// Our tracer and simplifier against OpenCV on one box: identical vertex lists.
void expect_matches_opencv(const LabelImage& img, const Box& b, const std::string& what) {
  std::vector<PixelPoint> ours;
  const std::int64_t twice_area =
      trace_largest_outer_boundary(img.labels.data(), img.width, kLabel, b.u0, b.v0, b.u1, b.v1, ours);
  const std::vector<cv::Point> ref = opencv_largest_outer(img, kLabel, b);
  ASSERT_EQ(describe(ours), describe(to_pixels(ref))) << what;
  if (ref.empty()) return;
  EXPECT_EQ(static_cast<double>(twice_area), 2.0 * cv::contourArea(ref)) << what;
  EXPECT_EQ(twice_area, twice_polygon_area(ours)) << what;
  for (double tol : {0.5, 1.0, 2.0, 3.7}) {
    std::vector<PixelPoint> simplified;
    simplify_closed_polygon(ours, tol, simplified);
    std::vector<cv::Point> ref_simplified;
    cv::approxPolyDP(ref, ref_simplified, tol, true);
    ASSERT_EQ(describe(simplified), describe(to_pixels(ref_simplified))) << what << " tolerance " << tol;
  }
}

// Polygon area on the plane (m^2) of a contour of 3-D vertices.
double polygon_area_m2(const std::vector<Eigen::Vector3d>& poly) {
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  for (std::size_t i = 0; i < poly.size(); ++i) sum += poly[i].cross(poly[(i + 1) % poly.size()]);
  return 0.5 * sum.norm();
}

// Every plane's contour from the pipeline equals the OpenCV-based one (same vertices, so the
// same area on the plane).
void expect_pipeline_matches_opencv(const DepthFrame& frame, const std::string& name) {
  Parameters params;
  params.set("grow.cell_px", 0);  // the pixel grid: the cell order traces on every 4th pixel
  params.set("grow.grid_step", 1);  // the contours are then traced on the labels we get back
  OrganizedCloud cloud;
  build_cloud(frame, cloud_options(params), cloud);
  estimate_normals(normal_options(params), cloud);
  PlaneSegments planes;
  extract_planes(cloud, grow_options(params), planes);
  ASSERT_GT(planes.planes.size(), 10u) << name;
  int with_area = 0;
  for (const PlaneSegment& p : planes.planes) {
    PlaneSegment ref = p;
    opencv_compute_contour(planes.labels, planes.width, cloud.intrinsics, ref);
    ASSERT_EQ(p.contour.size(), ref.contour.size()) << name << " plane " << p.id;
    for (std::size_t i = 0; i < p.contour.size(); ++i)
      EXPECT_LT((p.contour[i] - ref.contour[i]).norm(), 1e-12) << name << " plane " << p.id << " vertex " << i;
    const double area = polygon_area_m2(p.contour), ref_area = polygon_area_m2(ref.contour);
    EXPECT_NEAR(area, ref_area, 0.02 * ref_area) << name << " plane " << p.id;
    if (ref_area > 0.01) ++with_area;
  }
  EXPECT_GT(with_area, 3) << name;
}

PlaneSegment plane_facing_camera(int id, const Box& b, double distance_m = 2.0) {
  PlaneSegment p;
  p.id = id;
  p.normal = Eigen::Vector3d(0, 0, -1);
  p.offset_m = distance_m;  // z = distance
  p.bbox_u0 = b.u0, p.bbox_v0 = b.v0, p.bbox_u1 = b.u1, p.bbox_v1 = b.v1;
  return p;
}

}  // namespace

TEST(BoundaryTrace, RandomScenesMatchOpenCvExactly) {
  std::mt19937 rng(20261122);
  for (int scene = 0; scene < 3000; ++scene) {
    const LabelImage img = random_scene(rng);
    const std::string what = "scene " + std::to_string(scene);
    const Box tight = label_bbox(img, kLabel);
    if (tight.u1 >= 0) expect_matches_opencv(img, tight, what + " (label box)");
    expect_matches_opencv(img, {0, 0, img.width - 1, img.height - 1}, what + " (whole image)");
    std::uniform_int_distribution<int> U(0, img.width - 1), V(0, img.height - 1);
    const int ua = U(rng), ub = U(rng), va = V(rng), vb = V(rng);
    expect_matches_opencv(img, {std::min(ua, ub), std::min(va, vb), std::max(ua, ub), std::max(va, vb)},
                          what + " (random box)");
    if (HasFatalFailure()) return;
  }
}

TEST(BoundaryTrace, RaggedBlobsWithHolesAndIslandsMatchOpenCvExactly) {
  std::mt19937 rng(7);
  for (int scene = 0; scene < 40; ++scene) {
    const LabelImage img = random_blobs(rng, 160, 120);
    const std::string what = "blobs " + std::to_string(scene);
    expect_matches_opencv(img, label_bbox(img, kLabel), what);
    expect_matches_opencv(img, {17, 9, 140, 101}, what + " (cut by the box)");
    if (HasFatalFailure()) return;
  }
}

TEST(BoundaryTrace, SinglePixelLineAndFullImage) {
  LabelImage img{5, 4, std::vector<std::int32_t>(20, 0)};
  std::vector<PixelPoint> c;
  // Empty: no pixel of the label in the box.
  img.labels[0] = kOtherLabel;
  EXPECT_EQ(trace_largest_outer_boundary(img.labels.data(), 5, kLabel, 0, 0, 4, 3, c), 0);
  EXPECT_TRUE(c.empty());
  // A single pixel in the image's corner: one point.
  img.labels[19] = kLabel;
  EXPECT_EQ(trace_largest_outer_boundary(img.labels.data(), 5, kLabel, 4, 3, 4, 3, c), 0);
  EXPECT_EQ(describe(c), "(4,3)");
  // A horizontal one-pixel line: out and back, zero area.
  for (int u = 1; u < 4; ++u) img.labels[5 + u] = kLabel;
  img.labels[19] = 0;
  EXPECT_EQ(trace_largest_outer_boundary(img.labels.data(), 5, kLabel, 0, 0, 4, 3, c), 0);
  EXPECT_EQ(describe(c), "(1,1)(3,1)");
  // The whole image: its four corners, counter-clockwise on screen from the top left.
  std::fill(img.labels.begin(), img.labels.end(), kLabel);
  EXPECT_EQ(trace_largest_outer_boundary(img.labels.data(), 5, kLabel, 0, 0, 4, 3, c), 2 * 4 * 3);
  EXPECT_EQ(describe(c), "(0,0)(0,3)(4,3)(4,0)");
  // An empty or inverted box.
  EXPECT_EQ(trace_largest_outer_boundary(img.labels.data(), 5, kLabel, 3, 0, 2, 3, c), 0);
  EXPECT_TRUE(c.empty());
}

TEST(BoundaryTrace, EqualAreasPickTheComponentOpenCvPicks) {
  // Two equal squares and single pixels: OpenCV lists contours bottom-up and compute_contour
  // kept the first of equal areas, i.e. the lowest component.
  LabelImage img{12, 12, std::vector<std::int32_t>(144, 0)};
  for (int v = 0; v < 3; ++v)
    for (int u = 0; u < 3; ++u) img.labels[(1 + v) * 12 + 1 + u] = img.labels[(7 + v) * 12 + 6 + u] = kLabel;
  std::vector<PixelPoint> c;
  EXPECT_EQ(trace_largest_outer_boundary(img.labels.data(), 12, kLabel, 0, 0, 11, 11, c), 2 * 4);
  EXPECT_EQ(describe(c), "(6,7)(6,9)(8,9)(8,7)");
  expect_matches_opencv(img, {0, 0, 11, 11}, "squares");
  LabelImage dots{6, 6, std::vector<std::int32_t>(36, 0)};
  dots.labels[1 * 6 + 1] = dots.labels[4 * 6 + 2] = dots.labels[4 * 6 + 5] = kLabel;
  EXPECT_EQ(trace_largest_outer_boundary(dots.labels.data(), 6, kLabel, 0, 0, 5, 5, c), 0);
  EXPECT_EQ(describe(c), "(5,4)");
  expect_matches_opencv(dots, {0, 0, 5, 5}, "dots");
}

TEST(PolygonSimplify, RandomPolygonsMatchApproxPolyDp) {
  // Closed random walks (self-touching, with back-tracking) and random point clouds as polygons.
  std::mt19937 rng(99);
  std::uniform_int_distribution<int> step(-3, 3), coord(-40, 40), len(1, 120);
  for (int k = 0; k < 2000; ++k) {
    std::vector<PixelPoint> poly;
    const int n = len(rng);
    PixelPoint p{coord(rng), coord(rng)};
    for (int i = 0; i < n; ++i) {
      poly.push_back(p);
      if (k % 2) p = {p.x + step(rng), p.y + step(rng)};
      else p = {coord(rng), coord(rng)};
    }
    for (double tol : {0.0, 0.7, 1.0, 2.5, 6.0}) {
      std::vector<PixelPoint> ours;
      simplify_closed_polygon(poly, tol, ours);
      std::vector<cv::Point> ref;
      try {
        cv::approxPolyDP(to_cv(poly), ref, tol, true);
      } catch (const cv::Exception&) {
        continue;  // OpenCV asserts on a chord between two equal points; we keep going
      }
      ASSERT_EQ(describe(ours), describe(to_pixels(ref))) << "polygon " << k << " tolerance " << tol;
    }
  }
}

TEST(PolygonSimplify, EdgeCases) {
  std::vector<PixelPoint> out;
  simplify_closed_polygon({}, 1.0, out);
  EXPECT_TRUE(out.empty());
  simplify_closed_polygon({{3, 4}}, 1.0, out);
  EXPECT_EQ(describe(out), "(3,4)");
  // Everything within the tolerance of one vertex collapses to one vertex.
  simplify_closed_polygon({{0, 0}, {1, 0}, {1, 1}}, 2.0, out);
  EXPECT_EQ(out.size(), 1u);
  // A square traced pixel by pixel keeps its four corners.
  std::vector<PixelPoint> square;
  for (int i = 0; i < 10; ++i) square.push_back({0, i});
  for (int i = 0; i < 10; ++i) square.push_back({i, 10});
  for (int i = 10; i > 0; --i) square.push_back({10, i});
  for (int i = 10; i > 0; --i) square.push_back({i, 0});
  simplify_closed_polygon(square, 1.0, out);
  EXPECT_EQ(out.size(), 4u);
  EXPECT_EQ(twice_polygon_area(out), 200);
}

TEST(PlaneContour, SimulatedVgaFrameMatchesOpenCvContours) {
  SimConfig config = SimConfig::from_preset("lab");
  config.seed = 101;
  const TunnelSimulator sim(config);
  expect_pipeline_matches_opencv(sim.render(0).frame, "sim lab");
}

TEST(PlaneContour, RealFrameMatchesOpenCvContours) {
  ReadOptions opt;
  Intrinsics K;  // resources/real-frames/SOURCES.md
  K.fx = 575.927, K.fy = 576.408, K.cx = 315.150, K.cy = 230.586;
  opt.intrinsics = K;
  expect_pipeline_matches_opencv(
      read_depth_png(std::string(TUNNELMAP_TEST_DATA_DIR) + "/real-frames/cape_tunnel_depth.png", opt),
      "real cape tunnel");
}

TEST(PlaneContour, EmptyRegionGivesNoContour) {
  const std::vector<std::int32_t> labels(64 * 48, kOtherLabel);
  PlaneSegment p = plane_facing_camera(kLabel, {5, 5, 30, 20});
  p.contour.assign(3, Eigen::Vector3d::Ones());
  compute_contour(labels, 64, Intrinsics{}, p);
  EXPECT_TRUE(p.contour.empty());
  // Empty label image, box outside the image, inverted box: no contour, no crash.
  compute_contour({}, 64, Intrinsics{}, p);
  EXPECT_TRUE(p.contour.empty());
  p = plane_facing_camera(kLabel, {70, 50, 80, 60});
  compute_contour(labels, 64, Intrinsics{}, p);
  EXPECT_TRUE(p.contour.empty());
  p = plane_facing_camera(kLabel, {9, 5, 4, 20});
  compute_contour(labels, 64, Intrinsics{}, p);
  EXPECT_TRUE(p.contour.empty());
}

TEST(PlaneContour, RegionFillingTheImageGivesItsCorners) {
  const Intrinsics K;
  const std::vector<std::int32_t> labels(K.width * K.height, kLabel);
  PlaneSegment p = plane_facing_camera(kLabel, {0, 0, K.width - 1, K.height - 1});
  compute_contour(labels, K.width, K, p);
  ASSERT_EQ(p.contour.size(), 4u);
  // The corner pixels' centres 2 m away: (u - cx) z / fx etc.
  const double x0 = (0 - K.cx) * 2 / K.fx, x1 = (K.width - 1 - K.cx) * 2 / K.fx;
  const double y0 = (0 - K.cy) * 2 / K.fy, y1 = (K.height - 1 - K.cy) * 2 / K.fy;
  EXPECT_LT((p.contour[0] - Eigen::Vector3d(x0, y0, 2)).norm(), 1e-12);
  EXPECT_LT((p.contour[1] - Eigen::Vector3d(x0, y1, 2)).norm(), 1e-12);
  EXPECT_LT((p.contour[2] - Eigen::Vector3d(x1, y1, 2)).norm(), 1e-12);
  EXPECT_LT((p.contour[3] - Eigen::Vector3d(x1, y0, 2)).norm(), 1e-12);
  PlaneSegment ref = p;
  opencv_compute_contour(labels, K.width, K, ref);
  EXPECT_NEAR(polygon_area_m2(p.contour), polygon_area_m2(ref.contour), 1e-12);
  // A box reaching past the image is clipped to it.
  PlaneSegment past = plane_facing_camera(kLabel, {-5, -5, K.width + 5, K.height + 5});
  compute_contour(labels, K.width, K, past);
  ASSERT_EQ(past.contour.size(), 4u);
  EXPECT_LT((past.contour[2] - p.contour[2]).norm(), 1e-12);
}

TEST(PlaneContour, OnePixelRegionGivesOneVertexOnThePlane) {
  const Intrinsics K;
  for (const auto& [u, v] : {std::pair{0, 0}, std::pair{K.width - 1, K.height - 1}, std::pair{200, 100}}) {
    std::vector<std::int32_t> labels(K.width * K.height, kOtherLabel);
    labels[v * K.width + u] = kLabel;
    PlaneSegment p = plane_facing_camera(kLabel, {u, v, u, v}, 3.0);
    compute_contour(labels, K.width, K, p);
    ASSERT_EQ(p.contour.size(), 1u) << u << "," << v;
    EXPECT_LT((p.contour[0] - K.ray(u, v) * 3.0).norm(), 1e-12);
    EXPECT_NEAR(p.distance(p.contour[0]), 0.0, 1e-12);
  }
}

TEST(PlaneContour, KeepsTheContourCapacity) {
  const Intrinsics K;
  std::vector<std::int32_t> labels(K.width * K.height, 0);
  for (int v = 100; v < 200; ++v)
    for (int u = 50; u < 300; ++u) labels[v * K.width + u] = kLabel;
  PlaneSegment p = plane_facing_camera(kLabel, {50, 100, 299, 199});
  p.contour.reserve(500);
  const auto* storage = p.contour.data();
  compute_contour(labels, K.width, K, p);
  EXPECT_EQ(p.contour.size(), 4u);
  EXPECT_GE(p.contour.capacity(), 500u);
  EXPECT_EQ(p.contour.data(), storage);
}
