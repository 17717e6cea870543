// tunnelmap_fusion_rss: memory of the sparse TSDF fusion of a long girder. A simulated field
// girder (exact poses, one frame every 0.2 m) is fused once along world x and once turned 45 deg
// about the vertical; checks that
//   - the volume's bytes per metre of girder stay under --max-mib-per-m, both halfway and at
//     the end (memory follows the length of surface, not the bounding box),
//   - the turned girder allocates the same blocks within --max-turned-ratio,
//   - the mesh is within 10 mm of the true surfaces for at least --min-within of its vertices,
//   - the process's peak RSS (fusion, mesh and all) stays under --max-peak-mb.
// The dataset is written by a child process so that the simulator never counts towards the peak.
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>

#include "core/fusion/fuse_dataset.h"
#include "core/fusion/fusion_options.h"
#include "core/fusion/mesh_accuracy.h"
#include "core/io/dataset.h"
#include "core/io/refined_dataset.h"
#include "core/kinematics/frame_pose.h"
#include "core/sim/sim_dataset_writer.h"
#include "mesh/tsdf_mesher.h"
#include "tests/allocation/process_memory.h"

using namespace tunnelmap;
namespace fs = std::filesystem;

using testing::status_mb;

namespace {

struct Limits {
  double girder_m = 30.0;
  double max_mib_per_m = 7.0;
  double max_turned_ratio = 0.10;
  double min_within = 0.99;
  double max_peak_mb = 900.0;
};

bool write_girder_in_child(const std::string& dir, double girder_m) {
  const pid_t pid = fork();
  if (pid < 0) return false;
  if (pid == 0) {
    try {
      SimConfig c = SimConfig::from_preset("field");
      const int stops = static_cast<int>(std::lround((girder_m - 1.0) / 0.2)) + 1;
      c.frames = stops;
      for (double x = 4.0; x < girder_m; x += 4.0) c.diaphragm_x_m.push_back(x);
      SimWalk w;
      w.start_x_m = 0.5;
      w.end_x_m = girder_m - 0.5;
      w.stops = stops;
      c.walk = w;
      write_sim_dataset(dir, c);
      _exit(0);
    } catch (const std::exception& e) {
      std::fprintf(stderr, "simulate: %s\n", e.what());
      _exit(1);
    }
  }
  int status = 0;
  return waitpid(pid, &status, 0) == pid && WIFEXITED(status) && WEXITSTATUS(status) == 0;
}

// Length of the allocated blocks along the lattice's x (the girder's axis in both runs: the
// lattice turns with the heading).
double blocks_span_m(const SparseTsdfVolume& v) {
  int lo = 0, hi = -1;
  for (const auto& b : v.blocks()) {
    if (hi < lo) lo = hi = b->coords.x();
    lo = std::min(lo, b->coords.x());
    hi = std::max(hi, b->coords.x());
  }
  return double(hi - lo + 1) * v.block_m();
}

double mib_per_m(const SparseTsdfVolume& v) { return double(v.memory_bytes()) / double(1 << 20) / blocks_span_m(v); }

struct FusedGirder {
  std::size_t blocks = 0;
  double mib = 0.0, half_mib_per_m = 0.0, mib_per_m = 0.0, integrate_s = 0.0;
  std::size_t vertices = 0;
  double within = 0.0, mesh_s = 0.0;
};

// Fuses and meshes the dataset; the volume's cost per metre is also taken after half of the
// frames (the first half again, on a volume of its own with the same lattice).
// `world_to_truth` takes the mesh to the frame of the dataset's true surfaces.
FusedGirder fuse_girder(const Dataset& ds, const Parameters& params, const nlohmann::json& ground_truth,
                        const Eigen::Isometry3d& world_to_truth) {
  FuseSettings s;
  s.refine_poses = false;  // exact simulated poses: both runs fuse the same frames at the same poses
  s.threads = 2;
  FusedGirder g;
  FusionResult r = fuse_dataset(ds, params, s);
  g.blocks = r.volume->block_count();
  g.mib = double(r.volume->memory_bytes()) / double(1 << 20);
  g.mib_per_m = mib_per_m(*r.volume);
  g.integrate_s = r.timings_ms.at("integrate") / 1000.0;
  {
    SparseTsdfVolume half(r.volume->voxel_m(), r.volume->options(), SparseVolumeLimits(),
                          r.volume->lattice_to_world(), r.volume->lattice_origin());
    for (std::size_t i = 0; i < r.frames.size() / 2; ++i) half.integrate(ds.load_frame(i), r.frames[i].camera_to_world);
    g.half_mib_per_m = mib_per_m(half);
  }
  MeshStats ms;
  const TriangleMesh mesh = extract_mesh_releasing(*r.volume, fusion_options(params).min_weight, &ms);
  g.vertices = mesh.vertices.size();
  g.mesh_s = ms.milliseconds / 1000.0;
  g.within = mesh_accuracy(mesh, ground_truth_planes(ground_truth), 0.010, world_to_truth).fraction_within;
  return g;
}

void print(const char* name, const FusedGirder& g) {
  std::printf("%s: %zu blocks, %.1f MiB, %.2f MiB/m (half way %.2f), integrate %.1f s; mesh %zu vertices "
              "in %.1f s, %.2f %% within 10 mm\n", name, g.blocks, g.mib, g.mib_per_m, g.half_mib_per_m,
              g.integrate_s, g.vertices, g.mesh_s, 100.0 * g.within);
}

bool check(bool ok, const char* what) {
  if (!ok) std::printf("FAIL: %s\n", what);
  return ok;
}

int run(const std::string& dir, const Limits& lim) {
  Parameters params;  // the defaults: 8 mm voxels
  const Dataset along_ds = read_dataset(dir + "/along");
  Eigen::Isometry3d turn = Eigen::Isometry3d::Identity();
  turn.linear() = Eigen::AngleAxisd(M_PI / 4, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  std::vector<Eigen::Isometry3d> turned;
  for (std::size_t i = 0; i < along_ds.frames.size(); ++i)
    turned.push_back(turn * *resolve_frame_pose(along_ds, i).pose);
  write_dataset_with_poses(along_ds, turned, dir + "/turned");

  const FusedGirder along = fuse_girder(along_ds, params, along_ds.ground_truth, Eigen::Isometry3d::Identity());
  print("along x", along);
  const FusedGirder diagonal =
      fuse_girder(read_dataset(dir + "/turned"), params, along_ds.ground_truth, turn.inverse());
  print("turned 45 deg", diagonal);
  const double ratio = double(diagonal.blocks) / double(along.blocks);
  const double peak = status_mb("VmHWM");
  std::printf("turned / along: %.4f of the blocks; peak RSS %.0f MB\n", ratio, peak);

  bool ok = check(along.mib_per_m <= lim.max_mib_per_m, "MiB per metre along x over the limit");
  ok &= check(along.half_mib_per_m <= lim.max_mib_per_m, "MiB per metre half way over the limit");
  ok &= check(diagonal.mib_per_m <= lim.max_mib_per_m, "MiB per metre of the turned girder over the limit");
  ok &= check(std::abs(ratio - 1.0) <= lim.max_turned_ratio, "the turned girder's blocks differ by more than the limit");
  ok &= check(along.within >= lim.min_within, "mesh accuracy along x under the limit");
  ok &= check(diagonal.within >= lim.min_within, "mesh accuracy of the turned girder under the limit");
  ok &= check(peak <= lim.max_peak_mb, "peak RSS over the limit");
  return ok ? 0 : 1;
}

}  // namespace

int main(int argc, char** argv) {
  Limits lim;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    const bool v = i + 1 < argc;
    if (a == "--girder-m" && v) lim.girder_m = std::atof(argv[++i]);
    else if (a == "--max-mib-per-m" && v) lim.max_mib_per_m = std::atof(argv[++i]);
    else if (a == "--max-turned-ratio" && v) lim.max_turned_ratio = std::atof(argv[++i]);
    else if (a == "--min-within" && v) lim.min_within = std::atof(argv[++i]);
    else if (a == "--max-peak-mb" && v) lim.max_peak_mb = std::atof(argv[++i]);
    else {
      std::fprintf(stderr, "usage: %s [--girder-m M] [--max-mib-per-m X] [--max-turned-ratio R] "
                   "[--min-within F] [--max-peak-mb MB]\n", argv[0]);
      return 2;
    }
  }
  char pattern[] = "/tmp/tunnelmap-fusion-rss-XXXXXX";
  if (!mkdtemp(pattern)) {
    std::perror("mkdtemp");
    return 2;
  }
  const std::string dir = pattern;
  int rc = 2;
  const auto t0 = std::chrono::steady_clock::now();
  try {
    if (write_girder_in_child(dir + "/along", lim.girder_m)) rc = run(dir, lim);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "tunnelmap_fusion_rss: %s\n", e.what());
  }
  std::printf("%.0f m girder in %.1f s\n", lim.girder_m,
              std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
  fs::remove_all(dir);
  return rc;
}
