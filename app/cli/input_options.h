#pragma once
// Options shared by the commands that read frames and run the pipeline.
#include <CLI/CLI.hpp>
#include <optional>
#include <string>
#include <vector>

#include "core/io/dataset.h"
#include "core/io/frame_source.h"
#include "core/io/read_options.h"
#include "core/params/parameters.h"
#include "core/pipeline/pipeline.h"

namespace tunnelmap::cli {

struct InputOptions {
  std::string input;
  std::string params_file;
  std::vector<std::string> sets;
  std::string intrinsics;   // "FX,FY,CX,CY"
  std::optional<double> depth_scale;  // unset = reader default (1000 for PNG, 5000 for TUM sequences)
  std::string up;           // "X,Y,Z" camera frame
  std::optional<double> max_time_diff;  // TUM pairing limit in seconds (default 0.02)
  std::string world_up;     // "X,Y,Z" world frame, replaces a dataset's up
  recordings::RecordingOptions recording;  // --depth-topic ... --every (robot recordings)

  // Parameters: defaults, then --params FILE, then each --set (ParameterError / InputError).
  Parameters parameters() const;
  // ParameterError for malformed values; reader notes (unmatched TUM frames) go to stderr.
  ReadOptions read_options() const;
  std::optional<Eigen::Vector3d> camera_up() const;  // ParameterError for malformed values
  Pipeline pipeline() const;                         // parameters + up, world up from a dataset
};

// Registers INPUT and --params/--set/--intrinsics/--depth-scale/--up/--max-time-diff/--world-up
// on `cmd`. INPUT is optional when the command has another source (detect --device): it then
// checks for one itself.
void add_input_options(CLI::App* cmd, InputOptions& opt, bool input_required = true);

// Only the options that change how a sequence is read: --intrinsics, --depth-scale,
// --max-time-diff, --world-up and the recording options (for commands that read but run no
// pipeline, e.g. convert).
void add_read_options(CLI::App* cmd, InputOptions& opt);

// A dataset folder, a TUM sequence or a robot recording read as a Dataset (a recording is
// extracted to a temporary dataset folder that lives as long as this object).
class DatasetInput {
 public:
  explicit DatasetInput(const InputOptions& in);
  const Dataset& dataset() const { return recording_ ? *recording_->dataset() : dataset_; }

 private:
  std::unique_ptr<FrameSource> recording_;
  Dataset dataset_;
};

// Progress bar on stderr when it is a terminal (sequences only).
class Progress {
 public:
  explicit Progress(std::size_t total);
  void step(std::size_t done);
  ~Progress();

 private:
  std::size_t total_;
  bool enabled_;
};

}  // namespace tunnelmap::cli
