// tunnelmap_allocation_count: allocations per frame of each pipeline stage in the steady state
// (requirement: no allocation per frame). The same few simulated VGA frames run through the
// Pipeline again and again with one reused FrameResult; after the warm-up rounds every run is
// counted. The frames' integration into the sparse TSDF volume ("fusion", as `fuse` runs it on
// all cores) is counted the same way once every block they touch is allocated. Stages are
// separated with Pipeline::run's `from` argument:
//   run(from = Tunnel) = tunnel (+ the pipeline's own bookkeeping), run(from = Planes) - that =
//   planes, and so on. Prints the worst and mean count per frame and stage; exits 1 if a stage
//   exceeds its --max-STAGE limit (the ctest in CMakeLists.txt sets them), 77 (skipped) when
//   built with a sanitizer.
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "core/fusion/fusion_options.h"
#include "core/fusion/sparse_tsdf_volume.h"
#include "core/pipeline/pipeline.h"
#include "core/sim/tunnel_simulator.h"
#include "core/util/build_paths.h"
#include "tests/allocation/counting_allocator.h"

using namespace tunnelmap;

namespace {

const char* const kStages[] = {"cloud", "normals", "planes", "tunnel", "total", "fusion"};

struct Case {
  std::string name;
  Pipeline pipeline;
  std::vector<DepthFrame> frames;
  std::vector<Eigen::Isometry3d> poses;  // camera to world (the simulator's)
  std::unique_ptr<SparseTsdfVolume> volume;
};

Case make_case(const std::string& preset, unsigned seed, std::vector<int> indices,
               const std::vector<std::string>& sets) {
  SimConfig config = SimConfig::from_preset(preset);
  config.seed = seed;
  const TunnelSimulator sim(config);
  Parameters params;
  params.load_json_file(std::string(TUNNELMAP_SOURCE_DIR) + "/resources/presets/" + preset + ".json");
  params.set_from_strings(sets);
  Case c{preset, Pipeline(params), {}, {}, nullptr};
  c.pipeline.set_world_up(Eigen::Vector3d::UnitZ());
  for (int i : indices) {
    c.frames.push_back(sim.render(i).frame);
    c.poses.push_back(c.frames.back().pose.value_or(Eigen::Isometry3d::Identity()));
  }
  const FusionOptions fusion = fusion_options(params);
  c.volume = std::make_unique<SparseTsdfVolume>(fusion.voxel_m, tsdf_options(fusion));
  return c;
}

struct Tally {
  long long calls = 0, bytes = 0;
};

Tally since(const alloc::Counts& before) {
  const alloc::Counts now = alloc::snapshot();
  return {static_cast<long long>(now.calls - before.calls), static_cast<long long>(now.bytes - before.bytes)};
}

// Allocations of one frame, per stage.
std::map<std::string, Tally> count_frame(const Pipeline& p, const DepthFrame& f, FrameResult& r) {
  Tally from[4];
  const Stage stages[4] = {Stage::Cloud, Stage::Normals, Stage::Planes, Stage::Tunnel};
  for (int s = 0; s < 4; ++s) {
    const alloc::Counts before = alloc::snapshot();
    p.run(f, r, nullptr, stages[s]);
    from[s] = since(before);
  }
  const auto minus = [](Tally a, Tally b) { return Tally{a.calls - b.calls, a.bytes - b.bytes}; };
  return {{"cloud", minus(from[0], from[1])},
          {"normals", minus(from[1], from[2])},
          {"planes", minus(from[2], from[3])},
          {"tunnel", from[3]},
          {"total", from[0]}};
}

Tally count_integration(Case& c, std::size_t i) {
  const alloc::Counts before = alloc::snapshot();
  c.volume->integrate(c.frames[i], c.poses[i]);
  return since(before);
}

}  // namespace

int main(int argc, char** argv) {
  int warmup = 2, rounds = 2;
  std::map<std::string, long long> limit;  // stage -> max calls per frame (absent = no check)
  std::vector<std::string> sets;           // KEY=VALUE overrides of the presets
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    const bool has_value = i + 1 < argc;
    if (a == "--warmup" && has_value) {
      warmup = std::atoi(argv[++i]);
    } else if (a == "--rounds" && has_value) {
      rounds = std::max(1, std::atoi(argv[++i]));
    } else if (a == "--set" && has_value) {
      sets.push_back(argv[++i]);
    } else if (a.rfind("--max-", 0) == 0 && has_value) {
      limit[a.substr(6)] = std::atoll(argv[++i]);
    } else {
      std::fprintf(stderr,
                   "usage: %s [--warmup N] [--rounds N] [--set KEY=VALUE] [--max-cloud|normals|planes|tunnel|total|fusion N]\n",
                   argv[0]);
      return 2;
    }
  }
  if (!alloc::counting_enabled()) {
    std::printf("allocation counting is off in sanitizer builds: skipped\n");
    return 77;
  }

  std::vector<Case> cases;
  cases.push_back(make_case("lab", 31, {0, 15}, sets));
  cases.push_back(make_case("field", 32, {0}, sets));

  std::map<std::string, long long> worst, sum, bytes;
  int counted = 0;
  for (Case& c : cases) {
    FrameResult result;  // reused across the case's frames and rounds, like a sequence slot
    for (int round = 0; round < warmup + rounds; ++round) {
      for (std::size_t i = 0; i < c.frames.size(); ++i) {
        auto counts = count_frame(c.pipeline, c.frames[i], result);
        counts["fusion"] = count_integration(c, i);
        if (round < warmup) continue;
        ++counted;
        for (const auto& [stage, t] : counts) {
          worst[stage] = std::max(worst.count(stage) ? worst[stage] : t.calls, t.calls);
          sum[stage] += t.calls;
          bytes[stage] += t.bytes;
        }
        std::printf("%s frame %zu round %d:", c.name.c_str(), i, round - warmup);
        for (const char* s : kStages) std::printf(" %s %lld", s, counts.at(s).calls);
        std::printf(" (%zu planes)\n", result.planes.planes.size());
      }
    }
  }

  std::printf("\nsteady-state allocations per frame (%d frames after %d warm-up rounds)\n", counted, warmup);
  std::printf("%-8s %8s %8s %12s %8s\n", "stage", "worst", "mean", "mean bytes", "limit");
  bool ok = true;
  for (const char* s : kStages) {
    const bool has_limit = limit.count(s) > 0;
    std::printf("%-8s %8lld %8.1f %12.0f %8s\n", s, worst[s], double(sum[s]) / std::max(1, counted),
                double(bytes[s]) / std::max(1, counted),
                has_limit ? std::to_string(limit[s]).c_str() : "-");
    if (has_limit && worst[s] > limit[s]) {
      std::printf("FAIL: %s allocates %lld times per frame, limit %lld\n", s, worst[s], limit[s]);
      ok = false;
    }
  }
  for (const auto& [stage, n] : limit)
    if (!worst.count(stage)) {
      std::fprintf(stderr, "unknown stage in --max-%s\n", stage.c_str());
      return 2;
    }
  return ok ? 0 : 1;
}
