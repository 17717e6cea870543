#include "core/fusion/fuse_dataset.h"

#include <chrono>

#include "core/fusion/fusion_options.h"
#include "core/mapping/station_map_builder.h"
#include "core/pipeline/pipeline.h"
#include "core/util/error.h"

namespace tunnelmap {

namespace {
double ms_since(std::chrono::steady_clock::time_point t) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t).count();
}
}  // namespace

FusionResult fuse_dataset(const Dataset& ds, const Parameters& params, const FuseSettings& s) {
  const auto t0 = std::chrono::steady_clock::now();
  const FusionOptions fo = fusion_options(params);
  FusionResult r;
  const int n = static_cast<int>(ds.frames.size());
  if (n == 0) throw InputError(ds.json_path, "the dataset has no frames");

  // Pass 1: poses, per-frame detection, volume bounds (frames are not kept: memory stays flat).
  Pipeline pipeline(params);
  pipeline.set_world_up(ds.up);
  // The context of a posed sequence: the station map along the tunnel.
  StationMapBuilder stations(station_map_options(params), tunnel_options(params));
  Eigen::AlignedBox3d box;
  std::vector<Eigen::Isometry3d> poses;
  for (int i = 0; i < n; ++i) {
    const ResolvedPose rp = resolve_frame_pose(ds, static_cast<std::size_t>(i), s.prefer_joints);
    if (!rp.pose)
      throw InputError(ds.json_path, "frames[" + std::to_string(i) +
                                         "] has neither \"pose\" nor \"joints\": fusion needs "
                                         "every camera pose");
    DepthFrame f = ds.load_frame(static_cast<std::size_t>(i));
    f.pose = *rp.pose;
    FusedFrame ff;
    ff.index = i;
    ff.pose_source = rp.source;
    ff.camera_to_world = *rp.pose;
    if (s.detect) {
      FrameResult fr = pipeline.run(f);
      stations.add_frame(i, fr, *rp.pose);
      ff.map = std::move(fr.map);
    }
    extend_depth_bounds(f, *rp.pose, fo, box);
    poses.push_back(*rp.pose);
    r.frames.push_back(std::move(ff));
    if (s.progress) s.progress("detect", i + 1, n);
  }
  r.timings_ms["load+detect"] = ms_since(t0);

  // Pass 2: integration.
  const auto t1 = std::chrono::steady_clock::now();
  TsdfOptions to = tsdf_options(fo);
  to.threads = s.threads;
  r.volume = std::make_unique<TsdfVolume>(fusion_grid(box, fo), to);
  for (int i = 0; i < n; ++i) {
    const DepthFrame f = ds.load_frame(static_cast<std::size_t>(i));
    r.volume->integrate(f, poses[static_cast<std::size_t>(i)]);
    if (s.progress) s.progress("integrate", i + 1, n);
  }
  r.timings_ms["integrate"] = ms_since(t1);

  const std::vector<int> groups = group_poses(poses, fo.pose_group_m);
  std::vector<ScanInput> scans;
  for (std::size_t i = 0; i < r.frames.size(); ++i) {
    r.frames[i].pose_group = groups[i];
    scans.push_back({r.frames[i].map, r.frames[i].camera_to_world, r.frames[i].index});
  }
  if (s.detect) {
    r.merged = merge_scans(scans, groups, params.get("tunnel.zone_cluster_mm") / 1000.0);
    r.stations = stations.finish(groups);
  }
  r.timings_ms["total"] = ms_since(t0);
  return r;
}

}  // namespace tunnelmap
