#pragma once
// Options shared by all input readers (from --depth-scale, --intrinsics and the sequence flags).
#include <Eigen/Core>
#include <functional>
#include <optional>
#include <string>

#include "core/frame/intrinsics.h"
#include "core/io/input_options.h"
#include "core/recordings/recording_options.h"

namespace tunnelmap {

struct ReadOptions {
  double depth_units_per_m = 1000.0;     // depth PNG units per metre (millimetres by default)
  // True when the user gave --depth-scale: readers with a default of their own (a TUM
  // sequence's 5000) use depth_units_per_m only then.
  bool depth_scale_given = false;
  std::optional<Intrinsics> intrinsics;  // FX,FY,CX,CY given by the user; width/height from the image
  double max_time_diff_s = 0.02;         // TUM sequences: depth/colour/ground-truth pairing limit
  std::optional<Eigen::Vector3d> world_up;  // replaces a dataset's world up (unit) when set
  // One-line notes a reader wants the user to see (e.g. unmatched TUM frames); null = silent.
  std::function<void(const std::string&)> note;
  // Robot recordings (ROS bags): topics, world frame and time window (core/recordings).
  recordings::RecordingOptions recording;
  // Images with more pixels are refused from their header, before decoding (input.max_image_pixels).
  long long max_image_pixels = input_keys::max_image_pixels.default_value;
};

// PrimeSense VGA intrinsics scaled to an image of the given size (used when none are given).
Intrinsics default_intrinsics(int width, int height);

// The user's intrinsics (if any) with width/height taken from the image, else the default.
Intrinsics intrinsics_for_image(const ReadOptions& opt, int width, int height);

}  // namespace tunnelmap
