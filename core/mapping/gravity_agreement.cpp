#include "core/mapping/gravity_agreement.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace tunnelmap {

GravityAgreement gravity_agreement(const std::vector<Eigen::Isometry3d>& camera_to_world,
                                   const std::vector<std::optional<Eigen::Vector3d>>& gravity,
                                   const Eigen::Vector3d& world_up) {
  GravityAgreement a;
  const Eigen::Vector3d down = -world_up.normalized();
  double sum = 0.0;
  const std::size_t n = std::min(camera_to_world.size(), gravity.size());
  for (std::size_t k = 0; k < n; ++k) {
    if (!gravity[k] || !(gravity[k]->norm() > 0.0)) continue;
    const Eigen::Vector3d g = camera_to_world[k].linear() * gravity[k]->normalized();
    const double angle = std::atan2(g.cross(down).norm(), g.dot(down));
    sum += angle * angle;
    ++a.frames;
  }
  if (a.frames > 0) a.rms_deg = std::sqrt(sum / a.frames) * 180.0 / M_PI;
  return a;
}

std::string gravity_noise_note(const GravityAgreement& agreement, double gravity_deg) {
  const std::optional<double> per_axis = agreement.per_axis_deg();
  if (agreement.frames < 5 || !per_axis || gravity_deg <= 0.0 || *per_axis <= 3.0 * gravity_deg) return {};
  char text[360];
  std::snprintf(text, sizeof text,
                "the frames' gravity lies %.2f deg per tilt axis (RMS over %d frames) from the mapped poses' down, "
                "more than 3 x slam.gravity_deg = %g: if the IMU is that noisy, slam.gravity_deg set to %.2g "
                "weighs it as it is",
                *per_axis, agreement.frames, gravity_deg, *per_axis);
  return text;
}

}  // namespace tunnelmap
