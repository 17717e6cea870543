#include "core/sim/sim_tum_writer.h"

#include <unistd.h>

#include <filesystem>

#include "core/io/dataset.h"
#include "core/io/output_folder.h"
#include "core/io/tum_writer.h"
#include "core/kinematics/frame_pose.h"
#include "core/util/error.h"
#include "core/util/temp_registry.h"

namespace tunnelmap {

namespace fs = std::filesystem;

namespace {

// The simulator's own dataset, beside the output (same file system), removed in any case.
struct ScratchDataset {
  fs::path dir;
  explicit ScratchDataset(const fs::path& out) {
    dir = out.parent_path() / ("." + out.filename().string() + ".sim-" + std::to_string(::getpid()));
    std::error_code ec;
    fs::remove_all(dir, ec);
    TempRegistry::create(dir, [] {});  // made by the dataset writer, from a registered staging folder
  }
  ~ScratchDataset() {
    std::error_code ec;
    fs::remove_all(dir, ec);
    TempRegistry::remove(dir);
  }
};

}  // namespace

void write_sim_tum_sequence(const std::string& out_dir, const SimConfig& config,
                            const SimProgress& progress,
                            const std::function<void(const std::string&)>& note) {
  fs::path out = fs::absolute(out_dir).lexically_normal();
  if (out.filename().empty()) out = out.parent_path();
  StagedFolder{out.string()};  // refuses a folder we may not replace, before the simulation
  const fs::path created = first_missing_folder(out.parent_path());  // removed if we fail
  try {
    const ScratchDataset scratch(out);
    write_sim_dataset(scratch.dir.string(), config);
    const Dataset ds = read_dataset(scratch.dir.string());
    SequenceExport ex;
    for (std::size_t i = 0; i < ds.frames.size(); ++i) ex.poses.push_back(resolve_frame_pose(ds, i).pose);
    ex.note = note;
    if (progress)
      ex.progress = [&](std::size_t i, std::size_t n, const std::string& depth) {
        progress(static_cast<int>(i), static_cast<int>(n), depth);
      };
    write_tum_sequence(ds, out.string(), ex);
  } catch (...) {
    std::error_code ec;
    if (!created.empty()) fs::remove_all(created, ec);
    throw;
  }
}

}  // namespace tunnelmap
