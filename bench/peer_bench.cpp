// The peer implementations on the same frames as TunnelMap, one thread: PCL's
// IntegralImageNormalEstimation + OrganizedMultiPlaneSegmentation and OpenCV contrib's
// RgbdNormals + RgbdPlane, stage by stage and in total, with plane recall/precision against
// the simulator's true surfaces (bench/plane_quality.h).
//
// What each total contains (TunnelMap's BM_PlaneExtraction starts from the depth image and
// includes cloud, normals, PG&C, areas and contours):
// - BM_PclTotal: normals + segmentation from an organised cloud (PCL has no depth-to-cloud step
//   of its own; ours takes < 1 ms), no contours (PCL's PlanarRegion contours would add more).
// - BM_OpenCvTotal_*: normals + planes from the 3D points; BM_OpenCvTotalWithCloud_* adds
//   depthTo3d from the CV_32F metre depth image. RgbdPlane returns no areas or contours.
#include <benchmark/benchmark.h>

#include <string>

#include "bench/bench_frames.h"
#include "bench/frame_args.h"
#include "bench/opencv_peer.h"
#include "bench/pcl_peer.h"
#include "bench/plane_quality.h"
#include "core/pipeline/pipeline.h"

using namespace tunnelmap;
using namespace tunnelmap::bench;

namespace {

OrganizedCloud cloud_of(const NamedFrame& nf) {
  const Parameters p;
  OrganizedCloud cloud;
  build_cloud(nf.frame, cloud_options(p), cloud);
  return cloud;
}

void BM_PclNormals(benchmark::State& state) {
  const NamedFrame& nf = bench_frames()[state.range(0)];
  PclPeer peer(tuned_pcl_settings());
  peer.set_cloud(cloud_of(nf));
  for (auto _ : state) peer.estimate_normals();
  state.SetLabel(nf.name);
}

void BM_PclSegmentation(benchmark::State& state) {
  const NamedFrame& nf = bench_frames()[state.range(0)];
  PclPeer peer(tuned_pcl_settings());
  peer.set_cloud(cloud_of(nf));
  peer.estimate_normals();
  for (auto _ : state) peer.segment();
  set_plane_counters(state, nf, peer.segments());
  state.SetLabel(nf.name);
}

void BM_PclTotal(benchmark::State& state) {
  const NamedFrame& nf = bench_frames()[state.range(0)];
  PclPeer peer(tuned_pcl_settings());
  peer.set_cloud(cloud_of(nf));
  for (auto _ : state) {
    peer.estimate_normals();
    peer.segment();
  }
  set_plane_counters(state, nf, peer.segments());
  state.SetLabel(nf.name);
}

void BM_OpenCvCloud(benchmark::State& state) {
  const NamedFrame& nf = bench_frames()[state.range(0)];
  OpenCvPeer peer(nf.frame, cloud_options(Parameters()), tuned_opencv_settings(CvNormalsMethod::Fals));
  for (auto _ : state) peer.depth_to_3d();
  state.SetLabel(nf.name);
}

void opencv_normals(benchmark::State& state, CvNormalsMethod method) {
  const NamedFrame& nf = bench_frames()[state.range(0)];
  OpenCvPeer peer(nf.frame, cloud_options(Parameters()), tuned_opencv_settings(method));
  peer.depth_to_3d();
  for (auto _ : state) peer.estimate_normals();
  state.SetLabel(nf.name);
}

void opencv_planes(benchmark::State& state, CvNormalsMethod method) {
  const NamedFrame& nf = bench_frames()[state.range(0)];
  OpenCvPeer peer(nf.frame, cloud_options(Parameters()), tuned_opencv_settings(method));
  peer.depth_to_3d();
  peer.estimate_normals();
  for (auto _ : state) peer.find_planes();
  set_plane_counters(state, nf, peer.segments());
  state.SetLabel(nf.name);
}

void opencv_total(benchmark::State& state, CvNormalsMethod method, bool with_cloud) {
  const NamedFrame& nf = bench_frames()[state.range(0)];
  OpenCvPeer peer(nf.frame, cloud_options(Parameters()), tuned_opencv_settings(method));
  peer.depth_to_3d();
  for (auto _ : state) {
    if (with_cloud) peer.depth_to_3d();
    peer.estimate_normals();
    peer.find_planes();
  }
  set_plane_counters(state, nf, peer.segments());
  state.SetLabel(nf.name);
}

// One family per OpenCV normals method: BM_OpenCvNormals_FALS, BM_OpenCvTotal_SRI, ...
// LINEMOD is left out: Debian's OpenCV 4.6 segfaults inside RgbdNormals::operator() for it
// (any window, CV_16U depth, CV_32F depth or points alike).
const bool opencv_registered = [] {
  for (const CvNormalsMethod m : {CvNormalsMethod::Fals, CvNormalsMethod::Sri}) {
    const std::string s = method_name(m);
    benchmark::RegisterBenchmark(("BM_OpenCvNormals_" + s).c_str(),
                                 [m](benchmark::State& st) { opencv_normals(st, m); })->Apply(per_frame);
    benchmark::RegisterBenchmark(("BM_OpenCvPlanes_" + s).c_str(),
                                 [m](benchmark::State& st) { opencv_planes(st, m); })->Apply(per_frame);
    benchmark::RegisterBenchmark(("BM_OpenCvTotal_" + s).c_str(),
                                 [m](benchmark::State& st) { opencv_total(st, m, false); })->Apply(per_frame);
    benchmark::RegisterBenchmark(("BM_OpenCvTotalWithCloud_" + s).c_str(),
                                 [m](benchmark::State& st) { opencv_total(st, m, true); })->Apply(per_frame);
  }
  return true;
}();

}  // namespace

BENCHMARK(BM_PclNormals)->Apply(per_frame);
BENCHMARK(BM_PclSegmentation)->Apply(per_frame);
BENCHMARK(BM_PclTotal)->Apply(per_frame);
BENCHMARK(BM_OpenCvCloud)->Apply(per_frame);
