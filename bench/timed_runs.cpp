#include "bench/timed_runs.h"

#include <chrono>
#include <cstdio>
#include <string>
#include <vector>

#include "bench/bench_frames.h"
#include "bench/opencv_peer.h"
#include "bench/pcl_peer.h"
#include "core/pipeline/pipeline.h"

namespace tunnelmap::bench {

namespace {
using Clock = std::chrono::steady_clock;

template <class Run>
void time_runs(const std::string& frame, const char* method, int reps, int warmup, Run run) {
  std::vector<double> ms;
  ms.reserve(reps);
  int planes = 0;
  for (int i = 0; i < warmup + reps; ++i) {
    const auto t0 = Clock::now();
    planes = run();
    const double t = std::chrono::duration<double, std::milli>(Clock::now() - t0).count();
    if (i >= warmup) ms.push_back(t);
  }
  std::printf("RAW|%s|%s|%d|", frame.c_str(), method, planes);
  for (const double t : ms) std::printf("%.4f ", t);
  std::printf("\n");
}
}  // namespace

int print_timed_runs(int reps, int warmup, const std::string& methods) {
  const auto wanted = [&](const std::string& m) {
    return ("," + methods + ",").find("," + m + ",") != std::string::npos;
  };
  const Parameters p;
  const CloudOptions co = cloud_options(p);
  const NormalOptions no = normal_options(p);
  const GrowOptions go = grow_options(p);
  GrowOptions pixel_grid = go;  // the pixel grid on every other pixel (grow.cell_px = 0)
  pixel_grid.cell_px = 0;
  for (const NamedFrame& nf : bench_frames()) {
    // The paper's plane extraction from the depth image: cloud + normals (only where the
    // growing order reads them) + PG&C + areas + contours (BM_PlaneExtraction).
    OrganizedCloud cloud;
    PlaneSegments planes;
    FrameScratch scratch;  // reused across runs, as Pipeline::run does
    const auto extract = [&](const GrowOptions& g) {
      build_cloud(nf.frame, co, cloud, scratch.cloud);
      if (needs_point_normals(g)) estimate_normals(no, cloud, scratch.normals);
      extract_planes(cloud, g, planes, scratch.planes);
      return static_cast<int>(planes.planes.size());
    };
    if (wanted("tunnelmap-pixel-grid"))
      time_runs(nf.name, "tunnelmap-pixel-grid", reps, warmup, [&] { return extract(pixel_grid); });
    if (wanted("tunnelmap-detection")) {
      // Full detection: plane extraction and the tunnel template (Pipeline::run).
      const Pipeline pipeline(p);
      FrameResult result;
      time_runs(nf.name, "tunnelmap-detection", reps, warmup, [&] {
        pipeline.run(nf.frame, result, nullptr);
        return static_cast<int>(result.planes.planes.size());
      });
    }
    if (wanted("tunnelmap")) time_runs(nf.name, "tunnelmap", reps, warmup, [&] { return extract(go); });
    else extract(go);  // the PCL peer starts from this cloud
    // BM_OpenCvTotalWithCloud_FALS: depthTo3d + RgbdNormals + RgbdPlane (tuned settings).
    if (wanted("opencv")) {
      OpenCvPeer cv_peer(nf.frame, co, tuned_opencv_settings(CvNormalsMethod::Fals));
      time_runs(nf.name, "opencv", reps, warmup, [&] {
        cv_peer.depth_to_3d();
        cv_peer.estimate_normals();
        cv_peer.find_planes();
        return cv_peer.plane_count();
      });
    }
    // BM_PclTotal: IINE + OMPS from the organised cloud (PCL has no depth-to-cloud step).
    if (!wanted("pcl")) continue;
    PclPeer pcl_peer(tuned_pcl_settings());
    pcl_peer.set_cloud(cloud);
    time_runs(nf.name, "pcl", reps, warmup, [&] {
      pcl_peer.estimate_normals();
      pcl_peer.segment();
      return pcl_peer.plane_count();
    });
  }
  return 0;
}

}  // namespace tunnelmap::bench
