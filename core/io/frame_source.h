#pragma once
// One entry point for every input the CLI and GUI accept: a depth PNG, an organised PCD, a
// dataset folder (or its dataset.json), a TUM RGB-D sequence (folder with depth.txt), a plain
// folder of depth PNGs (core/io/png_folder.h), or a robot recording (ROS 1 .bag, MCAP, rosbag2
// sqlite3 or folder; core/recordings/recording_dataset.h).
#include <cstddef>
#include <functional>
#include <memory>
#include <string>

#include "core/frame/depth_frame.h"
#include "core/io/dataset.h"
#include "core/io/read_options.h"

namespace tunnelmap {

class FrameSource {
 public:
  virtual ~FrameSource();
  virtual std::size_t size() const = 0;
  virtual DepthFrame load(std::size_t i) const = 0;           // InputError on bad data
  virtual std::string describe(std::size_t i) const = 0;      // e.g. "frame 3/120 (depth/000003.png)"
  virtual const Dataset* dataset() const { return nullptr; }  // non-null for dataset inputs
};

// Chooses the reader by extension (.png, .pcd, .json, folder), else by the file's first bytes.
// A dataset is read and validated here; its own depth_scale and intrinsics win over `opt`
// (opt.world_up still replaces its up). A TUM sequence takes all of `opt` (read_tum_sequence).
// InputError for a missing input or an unknown type.
std::unique_ptr<FrameSource> open_input(const std::string& input, const ReadOptions& opt);

// Optional input types live outside the core (e.g. ".oni" recordings in tunnelmap_openni, which
// registers itself at start-up): open_input() asks a registered factory first, by extension
// (lower case, with the dot). Registering an extension again replaces its factory.
using FrameSourceFactory =
    std::function<std::unique_ptr<FrameSource>(const std::string& path, const ReadOptions& opt)>;
void register_frame_source(const std::string& extension, FrameSourceFactory factory);

}  // namespace tunnelmap
