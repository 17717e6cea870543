// Plane extraction on the real third-party frames (resources/real-frames) must not get worse
// than the code of 2026-11-24 (before the plane-extraction speed work): default parameters with
// the pixel-grid order (grow.cell_px = 0, the default then), the frames' intrinsics from
// SOURCES.md, exactly what `tunnelmap-cli planes FRAME --intrinsics ... --set grow.cell_px=0`
// runs. Recorded with that command's --json: plane count, summed area, labelled pixels, and
// every plane of at least 0.05 m^2 (normal, offset, area). The cell order is held to the same
// records by coverage and fragmentation (below).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "core/io/depth_png.h"
#include "core/pipeline/pipeline.h"
#include "core/util/build_paths.h"

using namespace tunnelmap;

namespace {

struct RecordedPlane {
  Eigen::Vector3d normal;
  double offset_m;
  double area_m2;
};

struct RecordedFrame {
  const char* file;
  double fx, fy, cx, cy;
  int planes;
  double total_area_m2;
  long labelled_pixels;
  std::vector<RecordedPlane> large;  // area >= 0.05 m^2
};

// A recorded plane is found again when a new plane lies on it (normals within 5 degrees,
// offsets within 3 cm) and covers at least 70 % of its area: a merge with a neighbour still
// counts, a plane shattered into small pieces does not.
constexpr double kMaxAngleDeg = 5.0;
constexpr double kMaxOffsetM = 0.03;
constexpr double kMinAreaShare = 0.7;
// Tolerances for changes in what is computed (e.g. where normals are sampled): a few planes
// more or fewer among hundreds of small ones, 3 % less summed area and labelled pixels, at
// most one recorded large plane in ten missing.
constexpr double kCountTolerance = 0.15;
constexpr double kMinAreaRatio = 0.97;
constexpr double kMinPixelRatio = 0.97;
constexpr double kMinLargeRecall = 0.9;

const std::vector<RecordedFrame>& recorded() {
  static const std::vector<RecordedFrame> frames = {
      {"cape_tunnel_depth.png", 575.927, 576.408, 315.150, 230.586, 265, 5.1240, 175838,
       {{{0.9486, 0.0357, -0.3144}, 0.7838, 0.4493},
        {{0.9353, -0.0690, -0.3472}, 0.8350, 0.3612},
        {{0.9140, -0.1543, -0.3752}, 0.8909, 0.3463},
        {{0.9437, 0.2294, -0.2382}, 0.7071, 0.2803},
        {{0.9331, 0.2902, -0.2124}, 0.6927, 0.1540},
        {{0.9487, 0.1729, -0.2648}, 0.7258, 0.1266},
        {{0.9527, 0.1342, -0.2725}, 0.7374, 0.1238},
        {{0.8541, -0.2999, -0.4250}, 1.0311, 0.1040},
        {{0.8844, -0.2565, -0.3899}, 0.9486, 0.0989},
        {{0.9100, 0.3674, -0.1920}, 0.7029, 0.0930},
        {{0.8275, -0.3563, -0.4339}, 1.0664, 0.0908},
        {{0.7966, -0.4089, -0.4453}, 1.1016, 0.0752},
        {{0.9284, 0.3058, -0.2112}, 0.6923, 0.0723},
        {{0.0054, -0.9275, -0.3738}, 1.3935, 0.0645},
        {{0.9411, 0.2560, -0.2210}, 0.6720, 0.0630},
        {{-0.1154, -0.9350, -0.3354}, 1.3854, 0.0599},
        {{-0.0735, -0.9406, -0.3314}, 1.3438, 0.0586}}},
      {"pcl_office_depth.png", 525, 525, 320, 240, 414, 5.8297, 48048,
       {{{-0.9742, -0.0527, -0.2193}, 1.5647, 0.2106},
        {{0.0000, -0.0000, -1.0000}, 3.3410, 0.0848},
        {{-0.9857, -0.0403, -0.1636}, 1.4245, 0.0664},
        {{-0.9851, 0.0534, -0.1635}, 1.4461, 0.0534}}},
      {"rtabmap_lab_depth_17.png", 525, 525, 319.5, 239.5, 132, 6.6303, 86595,
       {{{0.0079, -0.9981, 0.0607}, 0.4135, 4.6232},
        {{0.0057, -0.9966, 0.0822}, 0.3562, 0.0762},
        {{-0.0275, -0.9975, 0.0647}, 0.4206, 0.0692},
        {{0.9948, 0.0269, 0.0979}, 0.1111, 0.0673},
        {{0.0035, -0.9985, 0.0540}, 0.4404, 0.0543}}},
  };
  return frames;
}

OrganizedCloud cloud_of(const RecordedFrame& r) {
  ReadOptions opt;
  Intrinsics K;
  K.fx = r.fx, K.fy = r.fy, K.cx = r.cx, K.cy = r.cy;
  opt.intrinsics = K;
  const DepthFrame frame =
      read_depth_png(std::string(TUNNELMAP_TEST_DATA_DIR) + "/real-frames/" + r.file, opt);
  const Parameters p;
  OrganizedCloud cloud;
  build_cloud(frame, cloud_options(p), cloud);
  estimate_normals(normal_options(p), cloud);
  return cloud;
}

// The records are of the pixel-grid order (grow.cell_px = 0), which stays the paper's exact
// growing; `cell_px` picks the order compared.
GrowOptions options_of(int cell_px) {
  GrowOptions o = grow_options(Parameters());
  o.cell_px = cell_px;
  return o;
}

PlaneSegments planes_of(const RecordedFrame& r, int cell_px = 0) {
  return extract_planes(cloud_of(r), options_of(cell_px));
}

struct Totals {
  int planes = 0;
  double area_m2 = 0.0;
  long pixels = 0;
};

Totals totals_of(const PlaneSegments& s) {
  Totals t;
  t.planes = static_cast<int>(s.planes.size());
  for (const PlaneSegment& p : s.planes) t.area_m2 += p.area_m2, t.pixels += p.points;
  return t;
}

bool found_again(const RecordedPlane& old, const PlaneSegments& now) {
  const double cos_max = std::cos(kMaxAngleDeg * M_PI / 180.0);
  for (const PlaneSegment& p : now.planes)
    if (p.normal.dot(old.normal.normalized()) >= cos_max &&
        std::abs(p.offset_m - old.offset_m) <= kMaxOffsetM && p.area_m2 >= kMinAreaShare * old.area_m2)
      return true;
  return false;
}

void expect_not_worse(const RecordedFrame& r) {
  SCOPED_TRACE(r.file);
  const PlaneSegments now = planes_of(r);
  const Totals t = totals_of(now);
  const int count = t.planes;
  const double area = t.area_m2;
  const long pixels = t.pixels;
  std::printf("%s: %d planes (recorded %d), %.4f m^2 (%.4f), %ld labelled pixels (%ld)\n", r.file,
              count, r.planes, area, r.total_area_m2, pixels, r.labelled_pixels);
  EXPECT_NEAR(count, r.planes, kCountTolerance * r.planes);
  EXPECT_GE(area, kMinAreaRatio * r.total_area_m2);
  EXPECT_GE(pixels, kMinPixelRatio * r.labelled_pixels);
  int found = 0;
  for (const RecordedPlane& old : r.large) {
    const bool ok = found_again(old, now);
    found += ok;
    if (!ok)
      std::printf("  not found again: normal (%.4f, %.4f, %.4f), offset %.4f m, area %.4f m^2\n",
                  old.normal.x(), old.normal.y(), old.normal.z(), old.offset_m, old.area_m2);
  }
  EXPECT_GE(found, kMinLargeRecall * static_cast<double>(r.large.size()))
      << found << " of " << r.large.size() << " recorded planes of >= 0.05 m^2 found again";
}

}  // namespace

TEST(RealFramePlanes, CapeTunnelNotWorse) { expect_not_worse(recorded()[0]); }
TEST(RealFramePlanes, PclOfficeNotWorse) { expect_not_worse(recorded()[1]); }
TEST(RealFramePlanes, RtabmapLabNotWorse) { expect_not_worse(recorded()[2]); }

// The cell order (grow.cell_px = 8) cuts the same frames into other planes (fewer on cape's
// curved tunnel, more in rtabmap's clutter), so its planes are not the recorded ones. What it
// must keep is the surfaces: the pixels of each large plane of the default order (>= 0.05 m^2
// and >= 100 pixels) lie on planes of the cell order (95 % of them at least), within epsilon
// (RMS). Measured: 97.2-100 % of each plane's pixels, at 0.3-9.2 mm RMS. The one large plane of fewer
// pixels, a 49-pixel sliver seen edge-on at 3.5 m in rtabmap (its 0.067 m^2 is its grazing
// footprint), is 65 % covered: the frame's noise there is beyond the last pass's 4 mm limit.
TEST(RealFramePlanes, CellOrderExplainsTheLargePlanesOfTheDefaultOrder) {
  constexpr double kMinCovered = 0.95;
  constexpr int kMinPixels = 100;
  for (const RecordedFrame& r : recorded()) {
    SCOPED_TRACE(r.file);
    const OrganizedCloud cloud = cloud_of(r);
    const PlaneSegments grid = extract_planes(cloud, options_of(0));
    const GrowOptions by_cells = options_of(8);
    const PlaneSegments cells = extract_planes(cloud, by_cells);
    for (const PlaneSegment& g : grid.planes) {
      if (g.area_m2 < 0.05 || g.points < kMinPixels) continue;
      long n = 0, covered = 0;
      double sq = 0.0;
      for (std::size_t i = 0; i < grid.labels.size(); ++i) {
        if (grid.labels[i] != g.id) continue;
        ++n;
        if (cells.labels[i] <= 0) continue;
        ++covered;
        const PlaneSegment& q = cells.planes[cells.labels[i] - 1];
        const double d = q.normal.dot(cloud.points[i].cast<double>()) + q.offset_m;
        sq += d * d;
      }
      ASSERT_GT(n, 0);
      EXPECT_GE(static_cast<double>(covered) / n, kMinCovered) << "plane " << g.id << ", " << n << " pixels";
      if (covered > 0) {
        EXPECT_LE(std::sqrt(sq / covered), by_cells.distance_m) << "plane " << g.id;
      }
    }
  }
}

// The cell order against the records: it explains as many pixels and as much area, and does not
// shatter them into more planes. Its planes are not the recorded ones (see above), so the count
// is judged per labelled pixel: planes per pixel at most 15 % above the record's. Measured with
// 8-pixel cells: 1.4-2.7 times the pixels and 1.8-3.8 times the area, at 0.42-0.96 times the
// planes per pixel.
TEST(RealFramePlanes, CellOrderLabelsAsMuchInNoMorePiecesThanTheRecords) {
  for (const RecordedFrame& r : recorded()) {
    SCOPED_TRACE(r.file);
    const Totals t = totals_of(planes_of(r, 8));
    std::printf("%s, cells: %d planes (recorded %d), %.4f m^2 (%.4f), %ld labelled pixels (%ld)\n", r.file, t.planes,
                r.planes, t.area_m2, r.total_area_m2, t.pixels, r.labelled_pixels);
    EXPECT_GE(t.area_m2, kMinAreaRatio * r.total_area_m2);
    EXPECT_GE(t.pixels, kMinPixelRatio * r.labelled_pixels);
    const double per_pixel = static_cast<double>(t.planes) / static_cast<double>(t.pixels);
    const double recorded_per_pixel = static_cast<double>(r.planes) / static_cast<double>(r.labelled_pixels);
    EXPECT_LE(per_pixel, (1.0 + kCountTolerance) * recorded_per_pixel);
  }
}

// The matching rule itself can fail: a plane tilted by 10 degrees, or shifted by 10 cm, or
// covering half the area, is not the recorded plane.
TEST(RealFramePlanes, MatchingRejectsOtherPlanes) {
  const RecordedPlane old{{0.0, 0.0, -1.0}, 2.0, 1.0};
  PlaneSegments now;
  PlaneSegment p;
  p.normal = {0.0, 0.0, -1.0};
  p.offset_m = 2.0;
  p.area_m2 = 0.8;
  now.planes = {p};
  EXPECT_TRUE(found_again(old, now));
  const double t = 10.0 * M_PI / 180.0;
  now.planes[0].normal = {std::sin(t), 0.0, -std::cos(t)};
  EXPECT_FALSE(found_again(old, now));
  now.planes[0] = p;
  now.planes[0].offset_m = 2.1;
  EXPECT_FALSE(found_again(old, now));
  now.planes[0] = p;
  now.planes[0].area_m2 = 0.5;
  EXPECT_FALSE(found_again(old, now));
}
