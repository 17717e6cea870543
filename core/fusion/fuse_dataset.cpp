#include "core/fusion/fuse_dataset.h"

#include <chrono>
#include <cmath>

#include "core/engine/run_engine.h"
#include "core/fusion/fusion_options.h"
#include "core/fusion/lattice_offset.h"
#include "core/mapping/dataset_mapping.h"
#include "core/mapping/posed_sequence.h"
#include "core/util/error.h"

namespace tunnelmap {

namespace {
double ms_since(std::chrono::steady_clock::time_point t) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t).count();
}
// The world box of every frame's depth box (camera frame) through its pose.
Eigen::AlignedBox3d posed_depth_box(const std::vector<Eigen::AlignedBox3d>& boxes,
                                    const std::vector<Eigen::Isometry3d>& poses) {
  Eigen::AlignedBox3d box;
  for (std::size_t i = 0; i < boxes.size(); ++i) {
    if (boxes[i].isEmpty()) continue;
    for (int c = 0; c < 8; ++c)
      box.extend(poses[i] * boxes[i].corner(static_cast<Eigen::AlignedBox3d::CornerType>(c)));
  }
  return box;
}

std::vector<PosedMap> posed_maps(const std::vector<FusedFrame>& frames) {
  std::vector<PosedMap> out;
  for (const FusedFrame& f : frames) out.push_back({&f.map, f.camera_to_world});
  return out;
}
// Moves the lattice by the offset at which a sample of the frames allocates the fewest blocks
// (fusion.offset_fit_frames of them, every kOffsetFitRowStep-th row).
void fit_offset(const Dataset& ds, const std::vector<Eigen::Isometry3d>& poses, const FusionOptions& fo,
                const TsdfOptions& to, LatticeHeading& lattice) {
  if (fo.offset_fit_frames <= 0) return;
  const auto t0 = std::chrono::steady_clock::now();
  std::vector<PosedDepth> sample;
  for (const std::size_t i : evenly_spread(poses.size(), static_cast<std::size_t>(fo.offset_fit_frames)))
    sample.push_back({every_nth_row(ds.load_frame(i), kOffsetFitRowStep), poses[i]});
  lattice.offset_m = fit_lattice_offset(sample, lattice.lattice_to_world, fo.voxel_m, to).offset_m;
  lattice.offset_fit_ms = ms_since(t0);
}
// Every fused point lies within max_depth of its camera, so cameras further apart than the
// volume may span plus twice that depth make data too wide to fuse: refused before a frame is
// read (detecting every frame first took over a minute for a frame 50 km from the others).
void check_camera_span(const std::vector<Eigen::Isometry3d>& poses, const FusionOptions& fo) {
  Eigen::AlignedBox3d cameras;
  for (const Eigen::Isometry3d& p : poses) cameras.extend(p.translation());
  const double least_data_span = (cameras.max() - cameras.min()).maxCoeff() - 2.0 * fo.max_depth_m;
  if (least_data_span > fo.max_extent_m)
    throw FusionDataError("fusion: the cameras are " + std::to_string(least_data_span + 2.0 * fo.max_depth_m) +
                          " m apart, so the data spans more than " + std::string(fusion_keys::max_extent_m.key) +
                          " = " + std::to_string(fo.max_extent_m) + " m");
}

}  // namespace

FusionResult fuse_dataset(const Dataset& ds, const Parameters& params, const FuseSettings& s) {
  const auto t0 = std::chrono::steady_clock::now();
  const FusionOptions fo = fusion_options(params);
  FusionResult r;
  const int n = static_cast<int>(ds.frames.size());
  if (n == 0) throw InputError(ds.json_path, "the dataset has no frames");

  // Pass 1: poses, per-frame detection and wall samples, for the dense volume each frame's
  // depth box in its own camera frame (frames are not kept: memory stays flat).
  std::vector<Eigen::Isometry3d> poses;
  std::vector<TunnelMap> maps(static_cast<std::size_t>(n));
  std::vector<FrameWalls> walls(static_cast<std::size_t>(n));
  std::vector<Eigen::AlignedBox3d> boxes(static_cast<std::size_t>(n));
  for (int i = 0; i < n; ++i) {
    const std::size_t k = static_cast<std::size_t>(i);
    const ResolvedPose rp = resolve_frame_pose(ds, k, s.prefer_joints);
    if (!rp.pose)
      throw InputError(ds.json_path, "frames[" + std::to_string(i) +
                                         "] has neither \"pose\" nor \"joints\": fusion needs "
                                         "every camera pose");
    FusedFrame ff;
    ff.index = i;
    ff.pose_source = rp.source;
    ff.camera_to_world = ff.given_camera_to_world = *rp.pose;
    poses.push_back(*rp.pose);
    r.frames.push_back(std::move(ff));
  }
  check_camera_span(poses, fo);
  // Detection through the run engine (frames independent: the map gives the context below).
  RunSettings settings;
  settings.params = params;
  const PosedFrames frames(ds, poses);
  RunEngine engine(settings, &frames, RunEngine::ContextRule::None);
  const auto detect = [&](SequenceFrame& f) {
    if (!f.ok()) std::rethrow_exception(f.error);  // the frame's InputError
    const std::size_t k = f.index;
    if (s.detect) {
      extract_frame_walls(f.result, walls[k]);
      maps[k] = f.result.map;
      maps[k].plane_classes.clear();
      maps[k].plane_outlier.clear();
      maps[k].plane_candidate_classes.clear();
    }
    if (s.dense) extend_depth_bounds(f.frame, Eigen::Isometry3d::Identity(), fo, boxes[k]);
    if (s.progress) s.progress("detect", static_cast<int>(k) + 1, n);
    return true;
  };
  if (s.detect)
    engine.run(frames, detect);
  else
    run_frames(frames, nullptr, settings, detect);  // only the depth boxes: no stage runs
  r.timings_ms["load+detect"] = ms_since(t0);

  // The map along the tunnel, with the poses refined against it (arm sag), and each frame's
  // context from it.
  const auto tm = std::chrono::steady_clock::now();
  std::vector<int> groups = group_poses(poses, fo.pose_group_m);
  if (s.detect) {
    MappedSequence ms = map_posed_sequence(maps, walls, poses, ds.up, params, s.refine_poses, dataset_gravity(ds));
    r.refinement = std::move(ms.refinement);
    r.stations = std::move(ms.stations);
    poses = ms.poses;
    groups = ms.groups;
  }
  std::vector<ScanInput> scans;
  for (std::size_t i = 0; i < r.frames.size(); ++i) {
    r.frames[i].pose_group = groups[i];
    r.frames[i].camera_to_world = poses[i];
    r.frames[i].map = std::move(maps[i]);
    scans.push_back({r.frames[i].map, r.frames[i].camera_to_world, r.frames[i].index});
  }
  if (s.detect) r.merged = merge_scans(scans, groups, tunnel_options(params).zone_cluster_m);
  r.timings_ms["map"] = ms_since(tm);

  // Pass 2: integration with the final poses.
  const auto t1 = std::chrono::steady_clock::now();
  TsdfOptions to = tsdf_options(fo);
  to.threads = s.threads;
  if (s.dense)
    r.dense_volume = std::make_unique<TsdfVolume>(fusion_grid(posed_depth_box(boxes, poses), fo), to);
  else {
    r.lattice = lattice_heading(posed_maps(r.frames), r.merged.map, ds.up);
    fit_offset(ds, poses, fo, to, r.lattice);
    r.volume = std::make_unique<SparseTsdfVolume>(fo.voxel_m, to, sparse_volume_limits(fo), r.lattice.lattice_to_world,
                                                  r.lattice.origin());
  }
  for (int i = 0; i < n; ++i) {
    const DepthFrame f = ds.load_frame(static_cast<std::size_t>(i));
    const Eigen::Isometry3d& pose = poses[static_cast<std::size_t>(i)];
    if (r.dense_volume)
      r.dense_volume->integrate(f, pose);
    else
      r.volume->integrate(f, pose);
    if (s.progress) s.progress("integrate", i + 1, n);
    if (s.integrated && r.volume) s.integrated(*r.volume, i + 1, n);
  }
  if (r.volume && r.volume->block_count() == 0) throw no_depth_error(fo);
  r.timings_ms["integrate"] = ms_since(t1);

  r.timings_ms["total"] = ms_since(t0);
  return r;
}

}  // namespace tunnelmap
