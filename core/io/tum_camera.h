#pragma once
// The published intrinsics of the TUM RGB-D benchmark's Kinect cameras (freiburg1/2/3, 640x480
// depth), picked by the sequence folder's name, e.g. "rgbd_dataset_freiburg1_desk".
#include <optional>
#include <string>

#include "core/frame/intrinsics.h"

namespace tunnelmap {

struct TumCamera {
  std::string name;  // "freiburg1", "freiburg2" or "freiburg3"
  Intrinsics intrinsics;
};

// The camera named in `folder_name` (the folder's own name, not its path), if any.
std::optional<TumCamera> tum_camera_from_folder_name(const std::string& folder_name);

}  // namespace tunnelmap
