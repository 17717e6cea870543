// No front end has its own sequence loop: the stages' entry points (the method runner, the
// sequence runner, the context, the station map builder, a pipeline's run) are called only from
// core/engine. A source scan of every front end: the CLI verbs, the GUI, the renderer, the
// sequence bench, and the first passes of `map` and `fuse`.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include "core/util/build_paths.h"

namespace {

namespace fs = std::filesystem;
const fs::path kRoot = TUNNELMAP_SOURCE_DIR;

std::string read_text(const fs::path& p) {
  std::ifstream in(p);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

std::vector<fs::path> front_end_files() {
  std::vector<fs::path> files;
  for (const char* dir : {"app", "ui"})
    for (const auto& e : fs::recursive_directory_iterator(kRoot / dir))
      if (e.path().extension() == ".cpp" || e.path().extension() == ".h") files.push_back(e.path());
  for (const char* f : {"bench/sequence_bench.cpp", "core/mapping/dataset_mapping.cpp", "core/fusion/fuse_dataset.cpp"})
    files.push_back(kRoot / f);
  return files;
}

TEST(FrontEnds, CallNoStageEntryPointOutsideTheEngine) {
  const std::regex stage_call(
      R"(\b(SequenceRunner|MethodRunner|TunnelContext|apply_tunnel_context|StationMapBuilder)\b|)"
      R"(\bdetect_tunnel\s*\(|\bpipeline\w*\s*\.\s*run\s*\(|\b(build_cloud|estimate_normals|extract_planes)\s*\()");
  // `planes` times the plane stages themselves (median of --repeat runs) as the work it hands to
  // the engine's run_frames: the loop is still the engine's.
  const fs::path planes_verb = kRoot / "app/cli/cmd_planes.cpp";
  std::size_t scanned = 0;
  for (const fs::path& file : front_end_files()) {
    ++scanned;
    const std::string text = read_text(file);
    std::smatch m;
    std::string rest = text;
    while (std::regex_search(rest, m, stage_call)) {
      const std::string what = m.str();
      const bool planes_stage = file == planes_verb && what.find('(') != std::string::npos &&
                                what.find("pipeline") == std::string::npos && what.find("detect") == std::string::npos;
      EXPECT_TRUE(planes_stage) << fs::relative(file, kRoot).string() << " calls " << what << " itself";
      rest = m.suffix();
    }
  }
  EXPECT_GT(scanned, 40u);
}

TEST(FrontEnds, RunTheirFramesThroughTheEngine) {
  const std::pair<const char*, const char*> calls[] = {
      {"app/cli/cmd_detect.cpp", "RunEngine"},           {"app/cli/cmd_planes.cpp", "run_frames("},
      {"app/cli/cmd_map.cpp", "map_dataset("},           {"app/cli/cmd_fuse.cpp", "fuse_dataset("},
      {"app/render/main.cpp", "run_frame("},             {"app/render/render_map.cpp", "map_dataset("},
      {"ui/sequence_controller.cpp", "RunEngine"},      {"ui/pipeline_runner.cpp", "run_frame("},
      {"ui/live_view.cpp", "run_next("},                 {"ui/review_controller.cpp", "map_dataset("},
      {"bench/sequence_bench.cpp", "RunEngine"},         {"core/mapping/dataset_mapping.cpp", "RunEngine"},
      {"core/fusion/fuse_dataset.cpp", "RunEngine"},
  };
  for (const auto& [file, call] : calls)
    EXPECT_NE(read_text(kRoot / file).find(call), std::string::npos) << file << " does not call " << call;
}

}  // namespace
