// Tunnel detection (paper 2.2) on hand-built plane sets from a known rectangular tunnel.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include "core/tunnel/tunnel_detector.h"
#include "core/tunnel/zone_clustering.h"
#include "core/tunnel/zone_support.h"
#include "core/util/error.h"

namespace tunnelmap {
namespace {

constexpr double kW = 0.82, kH = 1.30, kBand = 0.15;
constexpr double kDeg = M_PI / 180.0;

// A synthetic scan. Tunnel frame: x across (to the right looking down the tunnel), y up,
// z along the tunnel. The camera sits inside at `cam` with axes R (columns, tunnel frame).
struct SceneSpec {
  double yaw_deg = 8, pitch_deg = -12, roll_deg = 20;
  Eigen::Vector3d cam = Eigen::Vector3d(0.12, -0.25, 0.0);
  double proud_m = 0.008;        // middle plates protrude this far into the tunnel
  double normal_noise_deg = 0.15;
  double offset_noise_m = 0.0003;
  bool outliers = true;          // planes with wrong normals, a manhole plate, a small stray zone
  bool with[4] = {true, true, true, true};  // per WallClass
  double tilt_top_bottom_deg = 0;  // rotate roof+floor normals about the axis (rhombus)
  double tilt_left_deg = 0;        // rotate only the left wall's normals about the axis
};

struct Scene {
  PlaneSegments planes;
  std::vector<WallClass> truth;  // class the plane belongs to (Unassigned for manhole)
  std::vector<bool> is_outlier;  // planes built with a wrong normal
  Eigen::Matrix3d R;             // camera axes in the tunnel frame
  Eigen::Vector3d cam;
  Eigen::Vector3d up_cam;
  Eigen::Vector3d to_tunnel(const Eigen::Vector3d& p) const { return R * p + cam; }
};

Eigen::Matrix3d camera_axes(double yaw, double pitch, double roll) {
  Eigen::Matrix3d base;  // camera X = right, Y = down, Z = along the tunnel
  base.col(0) = Eigen::Vector3d::UnitX();
  base.col(1) = -Eigen::Vector3d::UnitY();
  base.col(2) = Eigen::Vector3d::UnitZ();
  return Eigen::AngleAxisd(yaw * kDeg, Eigen::Vector3d::UnitY()).toRotationMatrix() * base *
         Eigen::AngleAxisd(pitch * kDeg, Eigen::Vector3d::UnitX()).toRotationMatrix() *
         Eigen::AngleAxisd(roll * kDeg, Eigen::Vector3d::UnitZ()).toRotationMatrix();
}

class SceneBuilder {
 public:
  explicit SceneBuilder(const SceneSpec& spec) : spec_(spec), rng_(12345) {
    scene_.R = camera_axes(spec.yaw_deg, spec.pitch_deg, spec.roll_deg);
    scene_.cam = spec.cam;
    scene_.up_cam = scene_.R.transpose() * Eigen::Vector3d::UnitY();
  }

  // One patch of `points` points centred at `c` (tunnel frame) with true inward normal `n`,
  // spanning `du` x `dv` along the unit directions u, v.
  void patch(WallClass truth, const Eigen::Vector3d& c, Eigen::Vector3d n, const Eigen::Vector3d& u,
             const Eigen::Vector3d& v, double du, double dv, int points, bool outlier = false) {
    std::normal_distribution<double> g(0.0, 1.0);
    // Small random rotation of the normal: the noise of a fitted plane.
    Eigen::Vector3d axis = n.cross(Eigen::Vector3d(g(rng_), g(rng_), g(rng_))).normalized();
    n = Eigen::AngleAxisd(spec_.normal_noise_deg * kDeg * g(rng_), axis) * n;
    const Eigen::Vector3d centre = c + spec_.offset_noise_m * g(rng_) * n;
    PlaneSegment p;
    p.id = static_cast<int>(scene_.planes.planes.size()) + 1;
    p.normal = scene_.R.transpose() * n;
    p.mean_normal = p.normal;
    p.centroid = scene_.R.transpose() * (centre - scene_.cam);
    p.offset_m = -p.normal.dot(p.centroid);
    p.points = points;
    p.area_m2 = du * dv;
    for (double su : {-0.5, 0.5})
      for (double sv : {-0.5, 0.5}) {
        const Eigen::Vector3d q = centre + su * du * u + (su < 0 ? sv : -sv) * dv * v;
        p.contour.push_back(scene_.R.transpose() * (q - scene_.cam));
      }
    scene_.planes.planes.push_back(p);
    scene_.truth.push_back(truth);
    scene_.is_outlier.push_back(outlier);
  }

  Scene build() {
    const Eigen::Vector3d X = Eigen::Vector3d::UnitX(), Y = Eigen::Vector3d::UnitY(),
                          Z = Eigen::Vector3d::UnitZ();
    const Eigen::AngleAxisd tb(spec_.tilt_top_bottom_deg * kDeg, Z);
    const Eigen::AngleAxisd tl(spec_.tilt_left_deg * kDeg, Z);
    struct WallSpec { WallClass cls; Eigen::Vector3d n, across; double pos, span; };
    const WallSpec walls[] = {
        {WallClass::Left, tl * X, Y, -kW / 2, kH},
        {WallClass::Right, -X, Y, kW / 2, kH},
        {WallClass::Top, tb * -Y, X, kH / 2, kW},
        {WallClass::Bottom, tb * Y, X, -kH / 2, kW},
    };
    for (const auto& w : walls) {
      if (!spec_.with[static_cast<int>(w.cls)]) continue;
      // Outermost surface: a point of the wall plane is -n * |pos| from the centre line.
      const bool side = w.cls == WallClass::Left || w.cls == WallClass::Right;
      const Eigen::Vector3d outer = w.pos * (side ? X : Y);  // on the outermost surface
      for (int k = 0; k < 6; ++k) {
        const double z = 0.6 + 0.4 * k;
        const double edge = 0.5 * w.span - 0.5 * kBand;  // centre of the riveted band
        for (double s : {-1.0, 1.0})
          patch(w.cls, outer + s * edge * w.across + z * Z, w.n, Z, w.across, 0.3, 0.12, 400);
        for (double s : {-1.0, 1.0})
          patch(w.cls, outer + spec_.proud_m * w.n + s * 0.2 * w.span / 1.3 * w.across + z * Z,
                w.n, Z, w.across, 0.3, 0.25, 900);
      }
    }
    if (spec_.outliers) {
      // Left wall: 5 deg off, 30 mm outside the wall; would widen the tunnel if kept.
      if (spec_.with[0])
        patch(WallClass::Left, Eigen::Vector3d(-kW / 2 - 0.03, 0.0, 2.0),
              Eigen::AngleAxisd(5 * kDeg, Y) * X, Z, Y, 0.2, 0.2, 2000, true);
      // Roof: 15 deg off (beyond outlier_max_deg).
      if (spec_.with[2])
        patch(WallClass::Top, Eigen::Vector3d(0.0, kH / 2 + 0.02, 1.5),
              Eigen::AngleAxisd(15 * kDeg, X) * -Y, Z, X, 0.2, 0.2, 800, true);
      // Right wall: a small stray zone 25 mm outside, correct normal, too few points to bound.
      if (spec_.with[1])
        patch(WallClass::Right, Eigen::Vector3d(kW / 2 + 0.025, 0.0, 1.2), -X, Z, Y, 0.1, 0.1, 100);
      // Manhole rim plate facing the camera across the tunnel.
      patch(WallClass::Unassigned, Eigen::Vector3d(0.0, 0.0, 3.2), -Z, X, Y, 0.3, 0.3, 1500);
    }
    return scene_;
  }

 private:
  SceneSpec spec_;
  std::mt19937 rng_;
  Scene scene_;
};

TunnelOptions fine_options() {
  TunnelOptions o;
  o.zone_cluster_m = 0.004;  // below the 8 mm plate step, so the middle plates are their own zone
  return o;
}

TunnelMap detect(const Scene& s, const TunnelOptions& o = fine_options(),
                 const TunnelContext* ctx = nullptr) {
  return detect_tunnel(s.planes, s.up_cam, o, ctx);
}

TEST(TunnelDetector, MeasuresWidthAndHeightOfTheOutermostZones) {
  const Scene s = SceneBuilder(SceneSpec()).build();
  const TunnelMap m = detect(s);
  ASSERT_TRUE(m.detected) << m.status << ": " << m.reason;
  EXPECT_EQ(m.status, TunnelStatus::Ok);
  EXPECT_NEAR(m.width_m, kW, 0.001);
  EXPECT_NEAR(m.height_m, kH, 0.001);
  EXPECT_EQ(m.timings_ms.count("tunnel"), 1u);
  // Left wall: edge zones (outermost) and middle plates 8 mm proud are separate clusters; the
  // wall plane is the outermost one.
  const Wall& left = m.wall(WallClass::Left);
  ASSERT_EQ(left.clusters.size(), 2u);
  EXPECT_NEAR(left.clusters[0].offset_m - left.clusters[1].offset_m, 0.008, 0.001);
  EXPECT_EQ(left.clusters[0].planes, 12);
  EXPECT_EQ(left.clusters[0].points, 12 * 400);
  EXPECT_DOUBLE_EQ(left.offset_m, left.clusters[0].offset_m);
  EXPECT_NEAR(left.offset_m, kW / 2 + 0.12, 0.001);  // camera is 0.12 m right of centre
  // Right wall: the 100-point stray zone is listed but does not bound the tunnel.
  const Wall& right = m.wall(WallClass::Right);
  ASSERT_EQ(right.clusters.size(), 3u);
  EXPECT_EQ(right.clusters[0].points, 100);
  EXPECT_NEAR(right.clusters[0].offset_m, kW / 2 - 0.12 + 0.025, 0.001);
  EXPECT_NEAR(right.offset_m, kW / 2 - 0.12, 0.001);
  // Orthonormal frame, axis away from the camera, up matching the truth.
  EXPECT_NEAR(m.axis_dir.norm(), 1.0, 1e-12);
  EXPECT_GT(m.axis_dir.z(), 0.0);
  EXPECT_NEAR(m.up.dot(m.axis_dir), 0.0, 1e-12);
  EXPECT_GT((s.R * m.up).dot(Eigen::Vector3d::UnitY()), std::cos(0.2 * kDeg));
  EXPECT_GT((s.R * m.axis_dir).dot(Eigen::Vector3d::UnitZ()), std::cos(0.2 * kDeg));
}

TEST(TunnelDetector, PlanesSeenEdgeOnMeasureNoZone) {
  // Two large planes on the left wall between its edge bands and its middle plates (8 mm
  // proud), as a plane seen nearly edge-on that straddles both plates comes out. Counted as
  // zones they would chain the two plates into one cluster; marked edge_on (the edge-on pass
  // of coarse-to-fine growing) they are left out and the zones stay as measured without them.
  Scene s = SceneBuilder(SceneSpec()).build();
  const TunnelMap clean = detect(s);
  ASSERT_TRUE(clean.detected);
  ASSERT_EQ(clean.wall(WallClass::Left).clusters.size(), 2u);
  const std::size_t band = [&] {  // a left-wall edge band plane (400 points)
    for (std::size_t i = 0; i < s.planes.planes.size(); ++i)
      if (clean.plane_classes[i] == WallClass::Left && s.planes.planes[i].points == 400) return i;
    return s.planes.planes.size();
  }();
  ASSERT_LT(band, s.planes.planes.size());
  for (double f : {1.0 / 3.0, 2.0 / 3.0}) {
    PlaneSegment p = s.planes.planes[band];
    p.id = static_cast<int>(s.planes.planes.size()) + 1;
    p.centroid += f * 0.008 * p.normal;  // the normal faces into the tunnel, like the plates' step
    p.offset_m = -p.normal.dot(p.centroid);
    p.points = 3000;
    s.planes.planes.push_back(p);
  }
  const TunnelMap bridged = detect(s);
  ASSERT_TRUE(bridged.detected);
  EXPECT_EQ(bridged.wall(WallClass::Left).clusters.size(), 1u) << "unmarked, they chain the plates";
  for (std::size_t i = s.planes.planes.size() - 2; i < s.planes.planes.size(); ++i) s.planes.planes[i].edge_on = true;
  const TunnelMap marked = detect(s);
  ASSERT_TRUE(marked.detected);
  EXPECT_EQ(marked.wall(WallClass::Left).clusters.size(), 2u);
  EXPECT_NEAR(marked.width_m, clean.width_m, 1e-6);  // they still vote in the wall directions
  EXPECT_NEAR(marked.height_m, clean.height_m, 1e-6);
  EXPECT_EQ(marked.plane_classes.back(), WallClass::Left) << "still classified (and shown) as the left wall";
}

TEST(TunnelDetector, FlagsOutliersAndLeavesTheManholeUnassigned) {
  const Scene s = SceneBuilder(SceneSpec()).build();
  const TunnelMap m = detect(s);
  ASSERT_TRUE(m.detected) << m.reason;
  ASSERT_EQ(m.plane_classes.size(), s.planes.planes.size());
  ASSERT_EQ(m.plane_outlier.size(), s.planes.planes.size());
  int outliers = 0;
  for (size_t i = 0; i < s.truth.size(); ++i) {
    SCOPED_TRACE(i);
    EXPECT_EQ(m.plane_candidate_classes[i], s.truth[i]);
    EXPECT_EQ(m.plane_outlier[i], s.is_outlier[i]);
    EXPECT_EQ(m.plane_classes[i], s.is_outlier[i] ? WallClass::Unassigned : s.truth[i]);
    outliers += m.plane_outlier[i];
  }
  EXPECT_EQ(outliers, 2);
  EXPECT_EQ(m.wall(WallClass::Left).outlier_planes, 1);
  EXPECT_EQ(m.wall(WallClass::Top).outlier_planes, 1);
  EXPECT_EQ(m.wall(WallClass::Left).inlier_planes, 24);
  EXPECT_LT(m.wall(WallClass::Left).normal_sd_deg, 0.5);
  EXPECT_GT(m.wall(WallClass::Left).normal_sd_deg, 0.02);
}

TEST(TunnelDetector, ClassesHoldForRolledAndPitchedCameras) {
  const double poses[][3] = {{0, 0, 0}, {15, -30, 90}, {-20, 35, -60}, {5, 10, 175}, {-10, -45, 250}};
  for (const auto& pose : poses) {
    SCOPED_TRACE(testing::Message() << "yaw " << pose[0] << " pitch " << pose[1] << " roll " << pose[2]);
    SceneSpec spec;
    spec.yaw_deg = pose[0];
    spec.pitch_deg = pose[1];
    spec.roll_deg = pose[2];
    const Scene s = SceneBuilder(spec).build();
    const TunnelMap m = detect(s);
    ASSERT_TRUE(m.detected) << m.status << ": " << m.reason;
    for (size_t i = 0; i < s.truth.size(); ++i) EXPECT_EQ(m.plane_candidate_classes[i], s.truth[i]) << i;
    EXPECT_NEAR(m.width_m, kW, 0.001);
    EXPECT_NEAR(m.height_m, kH, 0.001);
  }
}

TEST(TunnelDetector, DefaultClusterGapMergesAn8mmStepButSeparatesA15mmStep) {
  // zone_cluster_m = 10 mm (paper): an 8 mm plate step is one zone, a 15 mm step two.
  SceneSpec spec;
  spec.proud_m = 0.015;
  const TunnelMap apart = detect(SceneBuilder(spec).build(), TunnelOptions());
  ASSERT_TRUE(apart.detected) << apart.reason;
  EXPECT_EQ(apart.wall(WallClass::Left).clusters.size(), 2u);
  EXPECT_NEAR(apart.width_m, kW, 0.001);
  const TunnelMap merged = detect(SceneBuilder(SceneSpec()).build(), TunnelOptions());
  ASSERT_TRUE(merged.detected) << merged.reason;
  EXPECT_EQ(merged.wall(WallClass::Left).clusters.size(), 1u);
  EXPECT_LT(merged.width_m, kW - 0.004);  // pulled inwards by the middle plates
}

TEST(TunnelDetector, TooFewPlanes) {
  Scene s = SceneBuilder(SceneSpec()).build();
  s.planes.planes.resize(1);
  const TunnelMap m = detect(s);
  EXPECT_FALSE(m.detected);
  EXPECT_EQ(m.status, TunnelStatus::TooFewPlanes);
  EXPECT_NE(m.reason.find("1 planes"), std::string::npos) << m.reason;
  EXPECT_EQ(m.plane_classes.size(), 1u);
  EXPECT_EQ(m.plane_outlier.size(), 1u);
}

TEST(TunnelDetector, OneFlatWallIsNotATunnel) {
  SceneSpec spec;
  spec.with[1] = spec.with[2] = spec.with[3] = false;
  spec.outliers = false;
  const Scene s = SceneBuilder(spec).build();
  ASSERT_EQ(s.planes.planes.size(), 24u);
  const TunnelMap m = detect(s);
  EXPECT_FALSE(m.detected);
  EXPECT_EQ(m.status, TunnelStatus::MissingWall);
  for (const char* w : {"right wall: 0 planes", "top wall: 0 planes", "bottom wall: 0 planes"})
    EXPECT_NE(m.reason.find(w), std::string::npos) << m.reason;
  EXPECT_EQ(m.reason.find("left"), std::string::npos) << m.reason;
}

TEST(TunnelDetector, MissingTopGivesAPartialMapWithTheWidthMeasured) {
  SceneSpec spec;
  spec.with[static_cast<int>(WallClass::Top)] = false;
  const TunnelMap m = detect(SceneBuilder(spec).build());
  ASSERT_TRUE(m.detected) << m.reason;
  EXPECT_EQ(m.status, TunnelStatus::Partial);
  EXPECT_EQ(m.reason, "height unknown");
  EXPECT_EQ(m.width_source, DimensionSource::Measured);
  EXPECT_EQ(m.height_source, DimensionSource::Unseen);
  EXPECT_NEAR(m.width_m, kW, 0.001);
  EXPECT_FALSE(m.wall(WallClass::Top).found);  // never invented
  EXPECT_TRUE(m.wall(WallClass::Top).zones.empty());
  for (WallClass c : {WallClass::Left, WallClass::Right, WallClass::Bottom})
    EXPECT_EQ(m.wall(c).source, DimensionSource::Measured);
}

TEST(TunnelDetector, MissingTopWithADesignInfersTheRoofFromTheFloor) {
  SceneSpec spec;
  spec.with[static_cast<int>(WallClass::Top)] = false;
  TunnelOptions o;
  o.design_height_m = 1.25;
  const TunnelMap m = detect(SceneBuilder(spec).build(), o);
  ASSERT_TRUE(m.detected) << m.reason;
  EXPECT_EQ(m.status, TunnelStatus::Partial);
  EXPECT_EQ(m.reason, "height from design");
  EXPECT_EQ(m.height_source, DimensionSource::Design);
  EXPECT_DOUBLE_EQ(m.height_m, 1.25);
  const Wall& top = m.wall(WallClass::Top);
  EXPECT_TRUE(top.found);
  EXPECT_EQ(top.source, DimensionSource::Design);
  EXPECT_NEAR(top.offset_m + m.wall(WallClass::Bottom).offset_m, 1.25, 1e-9);
  EXPECT_FALSE(top.zones.empty());
}

TEST(TunnelDetector, TwoAdjacentWallsMeasureNothingWithoutADesign) {
  SceneSpec spec;
  spec.with[static_cast<int>(WallClass::Top)] = false;
  spec.with[static_cast<int>(WallClass::Right)] = false;
  const TunnelMap m = detect(SceneBuilder(spec).build());
  EXPECT_FALSE(m.detected);
  EXPECT_EQ(m.status, TunnelStatus::MissingWall);
  EXPECT_NE(m.reason.find("neither the width nor the height"), std::string::npos) << m.reason;
}

// The design fills a dimension the frame did not measure; it never makes a tunnel by itself:
// with one wall of each pair seen (a floor and a side wall: a room's corner), nothing is
// measured, so a full design is no reason to report a tunnel.
TEST(TunnelDetector, ADesignAloneMakesNoTunnel) {
  SceneSpec spec;
  spec.with[static_cast<int>(WallClass::Top)] = false;
  spec.with[static_cast<int>(WallClass::Right)] = false;
  TunnelOptions o;
  o.design_width_m = 0.82;
  o.design_height_m = 1.30;
  const TunnelMap m = detect(SceneBuilder(spec).build(), o);
  EXPECT_FALSE(m.detected);
  EXPECT_EQ(m.status, TunnelStatus::MissingWall);
  EXPECT_EQ(m.reason, "neither the width nor the height was measured (walls seen: left bottom)");
}

TEST(TunnelDetector, OutOfTemplateWhenThePriorIsNarrowed) {
  TunnelOptions o = fine_options();
  o.width_max_m = 0.70;
  const TunnelMap m = detect(SceneBuilder(SceneSpec()).build(), o);
  EXPECT_FALSE(m.detected);
  EXPECT_EQ(m.status, TunnelStatus::OutOfTemplate);
  EXPECT_EQ(m.reason, "width 0.820 m outside [0.30, 0.70]");
  EXPECT_NEAR(m.width_m, kW, 0.001);  // still reported for inspection
  o = fine_options();
  o.height_min_m = 1.5;
  const TunnelMap h = detect(SceneBuilder(SceneSpec()).build(), o);
  EXPECT_EQ(h.status, TunnelStatus::OutOfTemplate);
  EXPECT_NE(h.reason.find("height 1.300 m outside [1.50, 3.00]"), std::string::npos) << h.reason;
}

TEST(TunnelDetector, ContextOfEarlierScans) {
  const Scene s = SceneBuilder(SceneSpec()).build();
  TunnelMap prior;
  prior.detected = true;
  prior.width_source = prior.height_source = DimensionSource::Measured;
  prior.height_m = kH;
  TunnelContext far;
  prior.width_m = 0.90;  // 80 mm wider than this scan: beyond the 40 mm tolerance
  far.accept(prior);
  const TunnelMap bad = detect(s, fine_options(), &far);
  EXPECT_FALSE(bad.detected);
  EXPECT_EQ(bad.status, TunnelStatus::InconsistentWithContext);
  EXPECT_NE(bad.reason.find("width 0.820 m differs from the context's 0.900 m by more than 40 mm"),
            std::string::npos) << bad.reason;
  TunnelContext near;
  prior.width_m = 0.85;  // 30 mm: within tolerance
  near.accept(prior);
  const TunnelMap good = detect(s, fine_options(), &near);
  EXPECT_TRUE(good.detected) << good.reason;
  near.accept(good);
  EXPECT_NEAR(near.width_m(), 0.5 * (0.85 + good.width_m), 1e-12);
  TunnelContext empty;
  EXPECT_TRUE(detect(s, fine_options(), &empty).detected);
}

TEST(TunnelContext, KeepsOnlyTheLastWindowOfScans) {
  // A long stream: 1000 scans of a 0.80 m tunnel, then 1001 of a 0.90 m one; the context
  // follows the recent scans and its memory stays bounded.
  TunnelContext c;
  TunnelMap m;
  m.detected = true;
  m.width_source = m.height_source = DimensionSource::Measured;
  m.height_m = 1.2;
  m.width_m = 0.80;
  for (std::size_t i = 0; i < TunnelContext::kWindow; ++i) c.accept(m);
  EXPECT_DOUBLE_EQ(c.width_m(), 0.80);
  m.width_m = 0.90;
  for (std::size_t i = 0; i < TunnelContext::kWindow / 2 + 1; ++i) c.accept(m);
  EXPECT_DOUBLE_EQ(c.width_m(), 0.90);  // the newer scans are now the majority of the window
  for (std::size_t i = 0; i < TunnelContext::kWindow; ++i) c.accept(m);
  EXPECT_DOUBLE_EQ(c.width_m(), 0.90);
  EXPECT_DOUBLE_EQ(c.height_m(), 1.2);
}

TEST(TunnelContext, MediansOfDetectedMapsOnly) {
  TunnelContext c;
  EXPECT_TRUE(c.empty());
  TunnelMap m;
  m.detected = true;
  m.width_source = m.height_source = DimensionSource::Measured;
  for (double w : {0.80, 0.90, 0.82}) {
    m.width_m = w;
    m.height_m = 2 * w;
    c.accept(m);
  }
  EXPECT_DOUBLE_EQ(c.width_m(), 0.82);
  EXPECT_DOUBLE_EQ(c.height_m(), 1.64);
  m.width_m = 0.84;
  c.accept(m);
  EXPECT_DOUBLE_EQ(c.width_m(), 0.83);
  m.detected = false;
  m.width_m = 5.0;
  c.accept(m);
  EXPECT_DOUBLE_EQ(c.width_m(), 0.83);
  m.detected = true;  // a partial map adds only what it measured
  m.height_source = DimensionSource::Context;
  m.width_m = 0.83;
  m.height_m = 9.0;
  c.accept(m);
  EXPECT_DOUBLE_EQ(c.width_m(), 0.83);
  EXPECT_DOUBLE_EQ(c.height_m(), 1.64);  // the inferred 9 m is not a measurement
  c.clear();
  EXPECT_TRUE(c.empty());
}

TEST(TunnelDetector, NonPerpendicularPairs) {
  SceneSpec spec;
  spec.tilt_top_bottom_deg = 20;  // roof and floor parallel to each other, 70 deg to the walls
  const TunnelMap m = detect(SceneBuilder(spec).build());
  EXPECT_FALSE(m.detected);
  EXPECT_EQ(m.status, TunnelStatus::NotRectangular);
  EXPECT_NE(m.reason.find("20.0 deg from perpendicular"), std::string::npos) << m.reason;
}

TEST(TunnelDetector, NoParallelPair) {
  SceneSpec spec;
  spec.tilt_left_deg = 20;
  const TunnelMap m = detect(SceneBuilder(spec).build());
  EXPECT_FALSE(m.detected);
  EXPECT_EQ(m.status, TunnelStatus::NoParallelPair);
  EXPECT_NE(m.reason.find("left and right walls are 20.0 deg"), std::string::npos) << m.reason;
}

TEST(TunnelDetector, WallRectanglesAndZones) {
  const Scene s = SceneBuilder(SceneSpec()).build();
  const TunnelOptions o = fine_options();
  const TunnelMap m = detect(s, o);
  ASSERT_TRUE(m.detected) << m.reason;
  // Centre line at the tunnel centre, at the nearest visible wall point (z = 0.6 - 0.15).
  const Eigen::Vector3d c = s.to_tunnel(m.axis_point);
  EXPECT_NEAR(c.x(), 0.0, 0.001);
  EXPECT_NEAR(c.y(), 0.0, 0.001);
  EXPECT_NEAR(c.z(), 0.45, 0.005);
  EXPECT_DOUBLE_EQ(m.extent_min_m, 0.0);
  EXPECT_NEAR(m.extent_max_m, 2.75 - 0.45, 0.005);

  for (WallClass cls : {WallClass::Left, WallClass::Right, WallClass::Top, WallClass::Bottom}) {
    SCOPED_TRACE(wall_class_name(cls));
    const Wall& w = m.wall(cls);
    EXPECT_TRUE(w.found);
    EXPECT_EQ(w.cls, cls);
    for (const auto& p : w.boundary) EXPECT_NEAR(w.normal.dot(p) + w.offset_m, 0.0, 1e-9);
    // Counter-clockwise seen from inside: right-hand normal of the corner loop is +normal.
    const Eigen::Vector3d turn = (w.boundary[1] - w.boundary[0]).cross(w.boundary[2] - w.boundary[1]);
    EXPECT_GT(turn.normalized().dot(w.normal), 1.0 - 1e-9);
    const double along = (w.boundary[1] - w.boundary[0]).norm();
    const double across = (w.boundary[2] - w.boundary[1]).norm();
    EXPECT_NEAR(along, m.extent_max_m - m.extent_min_m, 1e-9);
    const bool side = cls == WallClass::Left || cls == WallClass::Right;
    EXPECT_NEAR(across, side ? m.height_m : m.width_m, 1e-9);

    ASSERT_EQ(w.zones.size(), 3u);
    EXPECT_EQ(w.zones[0].kind, ZoneKind::Forbidden);
    EXPECT_EQ(w.zones[1].kind, ZoneKind::Traversable);
    EXPECT_EQ(w.zones[2].kind, ZoneKind::Forbidden);
    for (const auto& z : w.zones) {
      for (const auto& p : z.corners) EXPECT_NEAR(w.normal.dot(p) + w.offset_m, 0.0, 1e-9);
      EXPECT_NEAR((z.corners[1] - z.corners[0]).norm(), along, 1e-9);
    }
    EXPECT_NEAR((w.zones[0].corners[2] - w.zones[0].corners[1]).norm(), o.forbidden_band_m, 1e-9);
    EXPECT_NEAR((w.zones[2].corners[2] - w.zones[2].corners[1]).norm(), o.forbidden_band_m, 1e-9);
    EXPECT_NEAR((w.zones[1].corners[2] - w.zones[1].corners[1]).norm(), across - 2 * o.forbidden_band_m, 1e-9);
    // The bands hug the corners, the middle lies between them with no gap.
    EXPECT_NEAR((w.zones[0].corners[0] - w.boundary[0]).norm(), 0.0, 1e-9);
    EXPECT_NEAR((w.zones[2].corners[2] - w.boundary[2]).norm(), 0.0, 1e-9);
    EXPECT_NEAR((w.zones[1].corners[0] - w.zones[0].corners[3]).norm(), 0.0, 1e-9);
    EXPECT_NEAR((w.zones[1].corners[3] - w.zones[2].corners[0]).norm(), 0.0, 1e-9);
  }
  // Adjacent walls share their corner edges.
  const auto& L = m.wall(WallClass::Left).boundary;
  const auto& T = m.wall(WallClass::Top).boundary;
  int shared = 0;
  for (const auto& p : L)
    for (const auto& q : T) shared += (p - q).norm() < 1e-9;
  EXPECT_EQ(shared, 2);
}

TEST(TunnelDetector, EmptyContoursFallBackToCentroidsForTheExtent) {
  Scene s = SceneBuilder(SceneSpec()).build();
  for (auto& p : s.planes.planes) p.contour.clear();
  const TunnelMap m = detect(s);
  ASSERT_TRUE(m.detected) << m.reason;
  EXPECT_NEAR(s.to_tunnel(m.axis_point).z(), 0.6, 0.005);  // nearest centroid
  EXPECT_NEAR(m.extent_max_m, 2.6 - 0.6, 0.005);
  EXPECT_NEAR(m.width_m, kW, 0.001);
}

TEST(TunnelDetector, NarrowWallIsAllForbidden) {
  TunnelOptions o = fine_options();
  o.forbidden_band_m = 0.45;  // 2 bands = 0.90 m > width 0.82: roof and floor all riveted
  const TunnelMap m = detect(SceneBuilder(SceneSpec()).build(), o);
  ASSERT_TRUE(m.detected) << m.reason;
  ASSERT_EQ(m.wall(WallClass::Top).zones.size(), 1u);
  EXPECT_EQ(m.wall(WallClass::Top).zones[0].kind, ZoneKind::Forbidden);
  EXPECT_EQ(m.wall(WallClass::Left).zones.size(), 3u);  // 1.30 m > 0.90 m
}

TEST(ZoneClustering, GapStartsANewClusterAndMeansArePointWeighted) {
  const auto c = cluster_zone_positions({{0.500, 100}, {0.503, 300}, {0.520, 50}, {0.528, 1}}, 0.010);
  ASSERT_EQ(c.size(), 2u);
  EXPECT_NEAR(c[0].offset_m, (0.520 * 50 + 0.528 * 1) / 51.0, 1e-12);  // outermost first
  EXPECT_EQ(c[0].points, 51);
  EXPECT_NEAR(c[1].offset_m, (0.500 * 100 + 0.503 * 300) / 400.0, 1e-12);
  EXPECT_EQ(c[1].planes, 2);
  EXPECT_EQ(outermost_supported_cluster(c, 300), 1);
  EXPECT_EQ(outermost_supported_cluster(c, 50), 0);
  EXPECT_EQ(outermost_supported_cluster(c, 1000), -1);
}

TEST(TunnelDetector, RejectsAZeroUpVector) {
  const Scene s = SceneBuilder(SceneSpec()).build();
  EXPECT_THROW(detect_tunnel(s.planes, Eigen::Vector3d::Zero(), TunnelOptions(), nullptr),
               ParameterError);
  EXPECT_STREQ(wall_class_name(WallClass::Bottom), "bottom");
  EXPECT_STREQ(wall_class_name(WallClass::Unassigned), "unassigned");
}

// Detection into a reused map (no allocation per frame) must not carry anything over
// from the previous frame: every field equal, doubles bit for bit.
void expect_same_map(const TunnelMap& a, const TunnelMap& b) {
  EXPECT_EQ(a.detected, b.detected);
  EXPECT_EQ(a.status, b.status);
  EXPECT_EQ(a.reason, b.reason);
  EXPECT_EQ(a.width_m, b.width_m);
  EXPECT_EQ(a.height_m, b.height_m);
  EXPECT_EQ(a.axis_point, b.axis_point);
  EXPECT_EQ(a.axis_dir, b.axis_dir);
  EXPECT_EQ(a.up, b.up);
  EXPECT_EQ(a.extent_min_m, b.extent_min_m);
  EXPECT_EQ(a.extent_max_m, b.extent_max_m);
  EXPECT_EQ(a.plane_classes, b.plane_classes);
  EXPECT_EQ(a.plane_outlier, b.plane_outlier);
  EXPECT_EQ(a.plane_candidate_classes, b.plane_candidate_classes);
  EXPECT_EQ(a.timings_ms.size(), b.timings_ms.size());
  for (int c = 0; c < 4; ++c) {
    SCOPED_TRACE(wall_class_name(static_cast<WallClass>(c)));
    const Wall& wa = a.walls[c];
    const Wall& wb = b.walls[c];
    EXPECT_EQ(wa.cls, wb.cls);
    EXPECT_EQ(wa.found, wb.found);
    EXPECT_EQ(wa.normal, wb.normal);
    EXPECT_EQ(wa.offset_m, wb.offset_m);
    EXPECT_EQ(wa.inlier_planes, wb.inlier_planes);
    EXPECT_EQ(wa.outlier_planes, wb.outlier_planes);
    EXPECT_EQ(wa.normal_sd_deg, wb.normal_sd_deg);
    EXPECT_EQ(wa.symmetric_step_m, wb.symmetric_step_m);
    ASSERT_EQ(wa.clusters.size(), wb.clusters.size());
    for (size_t k = 0; k < wa.clusters.size(); ++k) {
      EXPECT_EQ(wa.clusters[k].offset_m, wb.clusters[k].offset_m);
      EXPECT_EQ(wa.clusters[k].planes, wb.clusters[k].planes);
      EXPECT_EQ(wa.clusters[k].points, wb.clusters[k].points);
    }
    ASSERT_EQ(wa.zones.size(), wb.zones.size());
    for (size_t k = 0; k < wa.zones.size(); ++k) {
      EXPECT_EQ(wa.zones[k].kind, wb.zones[k].kind);
      EXPECT_EQ(wa.zones[k].corners, wb.zones[k].corners);
    }
    if (a.detected) {
      EXPECT_EQ(wa.boundary, wb.boundary);  // only set once geometry is built
    }
  }
}

TEST(TunnelDetector, DetectingTwiceIntoOneMapGivesBitIdenticalWalls) {
  const Scene s = SceneBuilder(SceneSpec()).build();
  const TunnelMap fresh = detect(s);
  ASSERT_TRUE(fresh.detected) << fresh.reason;
  TunnelMap reused;
  detect_tunnel(s.planes, s.up_cam, fine_options(), nullptr, reused);
  const TunnelMap first = reused;
  detect_tunnel(s.planes, s.up_cam, fine_options(), nullptr, reused);
  for (int c = 0; c < 4; ++c) {
    EXPECT_EQ(reused.walls[c].offset_m, first.walls[c].offset_m) << c;
    EXPECT_EQ(reused.walls[c].inlier_planes, first.walls[c].inlier_planes) << c;  // not summed
  }
  EXPECT_EQ(reused.width_m, first.width_m);
  EXPECT_EQ(reused.height_m, first.height_m);
  EXPECT_NEAR(reused.width_m, kW, 0.001);
  expect_same_map(first, fresh);
  expect_same_map(reused, fresh);
  EXPECT_EQ(reused.timings_ms.count("tunnel"), 1u);
}

TEST(TunnelDetector, FrameAThenOthersThenAGivesTheFirstResultForA) {
  // A: the default scan. B: a partial map with another wall count and reason. C: another detected
  // scan (other pose, 15 mm plates: more clusters, other extent). D: too few planes.
  const Scene a = SceneBuilder(SceneSpec()).build();
  SceneSpec spec_b;
  spec_b.with[static_cast<int>(WallClass::Top)] = false;
  const Scene b = SceneBuilder(spec_b).build();
  SceneSpec spec_c;
  spec_c.roll_deg = 175;
  spec_c.proud_m = 0.015;
  spec_c.outliers = false;
  const Scene c = SceneBuilder(spec_c).build();
  Scene d = a;
  d.planes.planes.resize(1);

  TunnelMap map;
  detect_tunnel(a.planes, a.up_cam, fine_options(), nullptr, map);
  const TunnelMap first = map;
  ASSERT_TRUE(first.detected) << first.reason;
  const Scene* others[] = {&b, &c, &d};
  for (const Scene* o : others) {
    detect_tunnel(o->planes, o->up_cam, fine_options(), nullptr, map);
    SCOPED_TRACE(map.status);
    expect_same_map(map, detect(*o));  // the other frame's own result, nothing of A's
    detect_tunnel(a.planes, a.up_cam, fine_options(), nullptr, map);
    expect_same_map(map, first);
  }
  EXPECT_EQ(first.status, TunnelStatus::Ok);
  EXPECT_EQ(detect(b).status, TunnelStatus::Partial);
  EXPECT_TRUE(detect(c).detected);
  EXPECT_EQ(detect(d).status, TunnelStatus::TooFewPlanes);
}


// ---- Zone support and gap scaled with the wall's distance (zone_support.h).

ZoneScaling scaling(int min_points, double support_ref_m, double gap_m, double gap_ref_m) {
  ZoneScaling z;
  z.min_points = min_points;
  z.support_ref_m = support_ref_m;
  z.gap_m = gap_m;
  z.gap_ref_m = gap_ref_m;
  return z;
}

TEST(ZoneSupport, OffKeepsTheConfiguredSupportAndGapAtEveryDistance) {
  const ZoneScaling off = scaling(300, 0.0, 0.010, 0.0);
  for (double d : {0.2, 1.0, 3.0, 12.0}) {
    EXPECT_EQ(off.support_at(d), 300) << d;
    EXPECT_EQ(off.gap_at(d), 0.010) << d;
  }
}

TEST(ZoneSupport, SupportFallsWithTheSquareOfTheDistanceDownToTheFloor) {
  const ZoneScaling z = scaling(300, 1.0, 0.010, 0.0);
  EXPECT_EQ(z.support_at(0.4), 300);  // nearer than the reference: never above the configured
  EXPECT_EQ(z.support_at(1.0), 300);
  EXPECT_EQ(z.support_at(1.5), 134);  // 300 / 2.25 = 133.3, rounded up
  EXPECT_EQ(z.support_at(2.0), 75);
  EXPECT_EQ(z.support_at(3.0), kMinScaledZoneSupport);  // 33.3 < 40
  EXPECT_EQ(z.support_at(0.0), 300);
  EXPECT_EQ(z.support_at(-1.0), 300);  // a plane behind the camera: no bonus
  EXPECT_EQ(scaling(30, 1.0, 0.010, 0.0).support_at(3.0), 30);  // the floor never raises it
  EXPECT_EQ(z.gap_at(5.0), 0.010);  // the gap has its own switch
}

TEST(ZoneSupport, GapGrowsWithTheSquareOfTheDistance) {
  const ZoneScaling z = scaling(300, 0.0, 0.020, 2.0);
  EXPECT_EQ(z.gap_at(1.0), 0.020);
  EXPECT_EQ(z.gap_at(2.0), 0.020);
  EXPECT_NEAR(z.gap_at(3.0), 0.045, 1e-12);
  EXPECT_NEAR(z.gap_at(4.0), 0.080, 1e-12);
  EXPECT_EQ(z.support_at(4.0), 300);
}

TEST(ZoneSupport, NegativeOrNonFiniteReferencesAreOneLineErrors) {
  for (const ZoneScaling& bad :
       {scaling(300, -1.0, 0.010, 0.0), scaling(300, 0.0, 0.010, std::nan("")),
        scaling(300, std::numeric_limits<double>::infinity(), 0.010, 0.0),
        scaling(300, 1.0, 0.0, 1.0)}) {
    try {
      check_zone_scaling(bad);
      ADD_FAILURE() << "accepted";
    } catch (const ParameterError& e) {
      EXPECT_EQ(std::string(e.what()).find('\n'), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find("zone support ref"), std::string::npos) << e.what();
    }
  }
  EXPECT_NO_THROW(check_zone_scaling(scaling(300, 1.0, 0.020, 2.0)));
  TunnelOptions o;
  o.zone_gap_ref_m = -0.5;
  const Scene s = SceneBuilder(SceneSpec()).build();
  EXPECT_THROW(detect(s, o), ParameterError);
}

TEST(ZoneClustering, ScaledGapMergesFarFragmentsButKeepsNearZonesApart) {
  // 15 mm apart at 0.5 m: two zones (gap 10 mm). 30 mm apart at 3 m: one zone (gap 90 mm).
  std::vector<ZonePosition> p = {{0.500, 1000}, {0.515, 1000}, {3.000, 1000}, {3.030, 1000}};
  std::vector<ZoneCluster> c;
  cluster_zone_positions(p, scaling(0, 0.0, 0.010, 1.0), c);
  ASSERT_EQ(c.size(), 3u);
  EXPECT_NEAR(c[0].offset_m, 3.015, 1e-12);
  EXPECT_EQ(c[0].planes, 2);
  EXPECT_EQ(c[1].planes, 1);
  EXPECT_EQ(c[2].planes, 1);
  // Unscaled, the same positions are four zones; and the fixed-gap overload agrees with it.
  cluster_zone_positions(p, scaling(0, 0.0, 0.010, 0.0), c);
  EXPECT_EQ(c.size(), 4u);
  EXPECT_EQ(cluster_zone_positions(p, 0.010).size(), 4u);
}

TEST(ZoneClustering, ScaledSupportLetsAFarZoneOfFewPointsBoundTheWall) {
  const std::vector<ZoneCluster> far = {{3.0, 1, 100}, {2.9, 3, 5000}};
  EXPECT_EQ(outermost_supported_cluster(far, scaling(300, 0.0, 0.010, 0.0)), 1);
  EXPECT_EQ(outermost_supported_cluster(far, scaling(300, 1.0, 0.010, 0.0)), 0);  // needs 40
  const std::vector<ZoneCluster> near = {{0.6, 1, 100}, {0.5, 3, 5000}};
  EXPECT_EQ(outermost_supported_cluster(near, scaling(300, 1.0, 0.010, 0.0)), 1);  // needs 300
}

// A 4 m wide, 2.4 m high corridor seen from its axis (camera frame: x right, y down, z forward).
// Roof and floor are large planes 1.2 m away; each side wall 2 m away is three planes of 60
// points whose offsets spread over +-20 mm, as far noisy walls break up.
PlaneSegments far_walled_corridor(bool with_roof_and_floor) {
  PlaneSegments s;
  const auto add = [&s](const Eigen::Vector3d& n, const Eigen::Vector3d& c, int points) {
    PlaneSegment p;
    p.id = static_cast<int>(s.planes.size()) + 1;
    p.normal = p.mean_normal = n;
    p.centroid = c;
    p.offset_m = -n.dot(c);
    p.points = points;
    s.planes.push_back(p);
  };
  for (int k = 0; k < 3; ++k) {
    const double spread = 0.020 * (k - 1), z = 3.5 + 0.5 * k;
    add(Eigen::Vector3d::UnitX(), {-2.0 - spread, 0.2, z}, 60);  // left wall, normal inwards
    add(-Eigen::Vector3d::UnitX(), {2.0 + spread, -0.2, z}, 60);
  }
  if (with_roof_and_floor) {
    add(Eigen::Vector3d::UnitY(), {0.1, -1.2, 3.0}, 5000);  // roof: normal down the image
    add(-Eigen::Vector3d::UnitY(), {-0.1, 1.2, 3.0}, 5000);
  }
  return s;
}

TEST(TunnelDetector, ScaledZoneSupportAndGapMeasureFarWallsOfFewPoints) {
  const Eigen::Vector3d up = -Eigen::Vector3d::UnitY();
  const PlaneSegments planes = far_walled_corridor(true);
  TunnelOptions o;
  o.width_max_m = 7.0;
  // Fixed support and gap: each side wall is three 60-point zones, none with 300 points.
  TunnelMap m = detect_tunnel(planes, up, o, nullptr);
  EXPECT_EQ(m.status, TunnelStatus::Partial);
  EXPECT_FALSE(m.wall(WallClass::Left).found);
  EXPECT_NEAR(m.height_m, 2.4, 1e-9);
  // Scaled support alone: 75 points at 2 m, still three zones of 60.
  o.zone_support_ref_m = 1.0;
  m = detect_tunnel(planes, up, o, nullptr);
  EXPECT_EQ(m.status, TunnelStatus::Partial);
  // With the gap scaled too (40 mm at 2 m) each wall is one zone of 180 points.
  o.zone_gap_ref_m = 1.0;
  m = detect_tunnel(planes, up, o, nullptr);
  ASSERT_EQ(m.status, TunnelStatus::Ok) << m.reason;
  EXPECT_EQ(m.wall(WallClass::Left).clusters.size(), 1u);
  EXPECT_EQ(m.wall(WallClass::Left).clusters[0].points, 180);
  EXPECT_NEAR(m.width_m, 4.0, 1e-9);
  EXPECT_NEAR(m.height_m, 2.4, 1e-9);
}

TEST(TunnelDetector, AFarWallWithoutEnoughScaledSupportSaysWhatItNeeded) {
  TunnelOptions o;
  o.width_max_m = 7.0;
  o.zone_support_ref_m = 1.0;  // gap fixed: 60-point zones at 1.98, 2.00 and 2.02 m
  const TunnelMap m = detect_tunnel(far_walled_corridor(false), -Eigen::Vector3d::UnitY(), o, nullptr);
  EXPECT_EQ(m.status, TunnelStatus::MissingWall);
  // 300 * (1 / 2.02)^2 = 73.5 points needed at the outermost (first of the equal) zones.
  for (const char* wall : {"left", "right"})
    EXPECT_NE(m.reason.find(std::string(wall) +
                            " wall: no zone cluster with enough points (largest 60 at 2.02 m, needs 74)"),
              std::string::npos)
        << m.reason;
  EXPECT_EQ(m.reason.find('\n'), std::string::npos);
}

}  // namespace
}  // namespace tunnelmap
