#pragma once
// How far each frame's gravity (an IMU's, in its camera frame) lies from the down of the pose it
// was mapped with. The estimate weighs gravity by `slam.gravity_deg`; where the structure holds
// the tilt, an IMU that is noisier than that shows as this spread, and pulls the tilt off by it.
#include <Eigen/Geometry>
#include <cmath>
#include <optional>
#include <string>
#include <vector>

namespace tunnelmap {

struct GravityAgreement {
  int frames = 0;                 // frames with a gravity
  std::optional<double> rms_deg;  // the angles' root mean square; empty without frames
  // The same per tilt axis (roll, pitch), as slam.gravity_deg counts the IMU's noise: rms / sqrt 2.
  std::optional<double> per_axis_deg() const {
    return rms_deg ? std::optional<double>(*rms_deg / std::sqrt(2.0)) : std::nullopt;
  }
};

GravityAgreement gravity_agreement(const std::vector<Eigen::Isometry3d>& camera_to_world,
                                   const std::vector<std::optional<Eigen::Vector3d>>& gravity,
                                   const Eigen::Vector3d& world_up);

// A line for the user when the spread per axis is more than three times `gravity_deg` over at
// least five frames (the estimate then trusts the IMU more than it deserves); empty otherwise.
std::string gravity_noise_note(const GravityAgreement& agreement, double gravity_deg);

}  // namespace tunnelmap
