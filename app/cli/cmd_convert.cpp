// `tunnelmap-cli convert INPUT OUT_DIR --to tum|dataset`: moves a sequence between the dataset
// layout (dataset.json) and the TUM RGB-D layout (depth.txt, rgb.txt, groundtruth.txt), and
// extracts a robot recording (ROS bag) into either.
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <memory>

#include "app/cli/commands.h"
#include "app/cli/input_options.h"
#include "core/io/dataset.h"
#include "core/io/dataset_writer.h"
#include "core/io/tum_sequence.h"
#include "core/io/tum_writer.h"
#include "core/kinematics/frame_pose.h"
#include "core/recordings/recording.h"
#include "core/util/error.h"

namespace tunnelmap::cli {

namespace {

struct ConvertOptions {
  InputOptions in;
  std::string out_dir;
  std::string to;
  bool quiet = false;
};

// Single images and clouds have no sequence to convert: say so rather than fail on JSON.
void require_sequence(const std::string& input) {
  namespace fs = std::filesystem;
  std::error_code ec;
  if (is_tum_sequence(input) || fs::is_directory(input, ec) || recordings::is_recording_path(input)) return;
  if (fs::exists(input, ec) && fs::path(input).extension() != ".json")
    throw InputError(input, "convert reads a dataset folder (dataset.json), a TUM RGB-D sequence "
                            "(folder with depth.txt) or a ROS bag (.bag, .mcap, .db3)");
}

void run(const ConvertOptions& o, CliContext& ctx) {
  require_sequence(o.in.input);
  const DatasetInput input(o.in);
  const Dataset& ds = input.dataset();
  SequenceExport ex;
  std::size_t posed = 0, coloured = 0, with_gravity = 0;
  for (std::size_t i = 0; i < ds.frames.size(); ++i) {
    ex.poses.push_back(resolve_frame_pose(ds, i).pose);  // explicit, else the arm's kinematics
    posed += ex.poses.back().has_value();
    coloured += !ds.frames[i].rgb_path.empty();
    with_gravity += ds.frames[i].gravity.has_value();
  }
  Progress progress(ds.frames.size());
  ex.progress = [&](std::size_t i, std::size_t, const std::string&) { progress.step(i + 1); };
  ex.note = [](const std::string& line) { std::fprintf(stderr, "tunnelmap-cli: note: %s\n", line.c_str()); };
  if (o.to == "tum")
    write_tum_sequence(ds, o.out_dir, ex);
  else
    write_dataset_folder(ds, o.out_dir, ex);
  const std::string gravity = with_gravity ? ", " + std::to_string(with_gravity) + " with gravity" : "";
  if (!o.quiet)
    std::cout << "wrote " << ds.frames.size() << " frames (" << coloured << " with colour, " << posed
              << " with a pose" << gravity << ") as " << (o.to == "tum" ? "a TUM RGB-D sequence" : "a dataset")
              << " to " << o.out_dir << "\n";
  ctx.exit_code = 0;
}

}  // namespace

void add_convert_command(CLI::App& app, CliContext& ctx) {
  auto o = std::make_shared<ConvertOptions>();
  CLI::App* cmd = app.add_subcommand(
      "convert", "Convert a sequence between the dataset layout and the TUM RGB-D layout");
  cmd->add_option("INPUT", o->in.input,
                  "Dataset folder (or its dataset.json), TUM RGB-D sequence folder or ROS bag")
      ->required();
  cmd->add_option("OUT_DIR", o->out_dir, "Output folder (new or empty)")->required();
  cmd->add_option("--to", o->to, "Layout to write: tum (depth.txt, rgb.txt, groundtruth.txt) or "
                                 "dataset (dataset.json)")
      ->required()
      ->check(CLI::IsMember({"tum", "dataset"}));
  add_read_options(cmd, o->in);
  cmd->add_flag("--quiet,-q", o->quiet, "Print nothing but errors and notes");
  cmd->callback([o, &ctx] { run(*o, ctx); });
}

}  // namespace tunnelmap::cli
