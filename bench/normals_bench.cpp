// Our integral-image normals against PCL's IntegralImageNormalEstimation (the implementation
// the design card says to prefer unless ours is measured faster at equal quality). Same frames,
// same window; counters give coverage and angular error against the simulator's true surfaces.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>

#include "bench/bench_frames.h"
#include "bench/frame_args.h"
#include "bench/pcl_peer.h"
#include "core/pipeline/pipeline.h"

using namespace tunnelmap;
using tunnelmap::bench::bench_frames;

namespace {

struct NormalQuality {
  double coverage = 0;       // fraction of planar-surface pixels with a normal
  double median_err_deg = 0;
};

// Normals may face either way in PCL's output: compare the unsigned angle.
NormalQuality quality(const std::vector<Eigen::Vector3f>& truth, const std::vector<Eigen::Vector3f>& normals) {
  std::vector<double> errs;
  std::size_t planar = 0;
  for (std::size_t i = 0; i < truth.size(); ++i) {
    if (truth[i].x() != truth[i].x()) continue;
    ++planar;
    const Eigen::Vector3f& n = normals[i];
    if (n.x() != n.x()) continue;
    const double c = std::min(1.0, static_cast<double>(std::abs(n.normalized().dot(truth[i]))));
    errs.push_back(std::acos(c) * 180.0 / M_PI);
  }
  NormalQuality q;
  if (planar == 0 || errs.empty()) return q;
  q.coverage = static_cast<double>(errs.size()) / planar;
  std::nth_element(errs.begin(), errs.begin() + errs.size() / 2, errs.end());
  q.median_err_deg = errs[errs.size() / 2];
  return q;
}

void BM_NormalsOurs(benchmark::State& state) {
  const auto& nf = bench_frames()[state.range(0)];
  const Parameters p;
  OrganizedCloud cloud;
  build_cloud(nf.frame, cloud_options(p), cloud);
  NormalScratch scratch;  // reused, as Pipeline::run does: the steady state
  for (auto _ : state) estimate_normals(normal_options(p), cloud, scratch);
  if (!nf.true_normals.empty()) {
    const NormalQuality q = quality(nf.true_normals, cloud.normals);
    state.counters["coverage"] = q.coverage;
    state.counters["median_err_deg"] = q.median_err_deg;
  }
  state.SetLabel(nf.name);
}

// PCL's IntegralImageNormalEstimation with our window (AVERAGE_3D_GRADIENT, depth-change
// factor 0.02): the same settings as the PCL peer's normal stage (bench/pcl_peer.cpp).
void BM_NormalsPcl(benchmark::State& state) {
  const auto& nf = bench_frames()[state.range(0)];
  const Parameters p;
  OrganizedCloud cloud;
  build_cloud(nf.frame, cloud_options(p), cloud);
  tunnelmap::bench::PclPeerSettings s = tunnelmap::bench::tuned_pcl_settings();
  s.smoothing_px = static_cast<float>(p.get("normals.smoothing_px"));
  tunnelmap::bench::PclPeer peer(s);
  peer.set_cloud(cloud);
  for (auto _ : state) peer.estimate_normals();
  if (!nf.true_normals.empty()) {
    const NormalQuality q = quality(nf.true_normals, peer.normals());
    state.counters["coverage"] = q.coverage;
    state.counters["median_err_deg"] = q.median_err_deg;
  }
  state.SetLabel(nf.name);
}

}  // namespace

BENCHMARK(BM_NormalsOurs)->Apply(tunnelmap::bench::per_frame);
BENCHMARK(BM_NormalsPcl)->Apply(tunnelmap::bench::per_frame);
