#pragma once
// A recording's depth sequence written as a "tunnelmap-dataset/1" folder (depth/NNNNNN.png
// 16-bit millimetres, rgb/NNNNNN.png, dataset.json with intrinsics, up, poses and
// timestamps), so that every command reading datasets reads recordings the same way, frame
// by frame from disk: memory stays bounded however long the recording.
#include <Eigen/Core>
#include <filesystem>
#include <functional>
#include <memory>
#include <string>

#include "core/io/frame_source.h"
#include "core/io/read_options.h"
#include "core/recordings/recording_frames.h"

namespace tunnelmap::recordings {

struct RecordingExport {
  std::size_t frames = 0, posed = 0, coloured = 0, with_gravity = 0;
  std::size_t depth_out_of_range = 0;  // pixels past 65.535 m, written as no measurement
};

// Writes into `dir` (an existing empty folder). `up`: the world up stored in dataset.json.
// InputError when the recording yields no depth frame in the chosen window.
RecordingExport write_recording_dataset(const RecordingFrames& frames, const std::string& recording_path,
                                        const std::filesystem::path& dir, const Eigen::Vector3d& up,
                                        const std::function<void(std::size_t)>& progress = {});

// open_input() for a recording: extracts it to a temporary dataset folder (removed with the
// source) and reads that. The chosen topics go to opt.note.
std::unique_ptr<FrameSource> open_recording_input(const std::string& path, const ReadOptions& opt);

// The same for a recording already open (the GUI indexes it once, then lets the user choose
// the topics). `progress` gets the number of frames written so far; an exception it throws
// (a cancel) leaves nothing behind and propagates.
std::unique_ptr<FrameSource> extract_recording(const Recording& rec, const std::string& path, const ReadOptions& opt,
                                               const std::function<void(std::size_t)>& progress = {});

}  // namespace tunnelmap::recordings
