#pragma once
// A family of random box girders for the whole-girder evaluation (`evaluate --protocol
// girders`): geometry, manholes, alignment, depth noise, odometry drift and the robot's walk are
// drawn from ranges wider than any single case the mapping was tuned on.
#include <string>
#include <vector>

#include "core/sim/sim_config.h"

namespace tunnelmap {

struct GirderRanges {
  double min_length_m = 30.0, max_length_m = 40.0;
  double min_spacing_m = 3.0, max_spacing_m = 5.0;      // between diaphragms
  double min_width_m = 0.70, max_width_m = 1.10;
  double min_height_m = 1.00, max_height_m = 1.50;
  double sectioned_fraction = 0.3;  // girders whose cross-section changes (2-3 sections)
  double curved_fraction = 0.3;     // girders on a horizontal curve with gradient and cross-fall
  double min_radius_m = 150.0, max_radius_m = 1000.0;
  double max_gradient_pct = 6.0, max_cross_fall_deg = 3.0;
  // Of the curved girders: those that run straight and then into the curve along a transition
  // curve that starts inside the girder (it may end beyond it), and those on a vertical curve (the gradient changes, staying
  // within max_gradient_pct). Drawn from a stream of their own: the other girders are the
  // same whatever these are.
  double transition_fraction = 0.5;
  double min_transition_m = 15.0, max_transition_m = 60.0;
  double vertical_curve_fraction = 0.5;
  double min_vertical_radius_m = 1500.0, max_vertical_radius_m = 15000.0;
  double drifted_fraction = 0.5;    // walks whose poses drift
  double drift_translation_mm_per_sqrt_m = 10.0, drift_rotation_deg_per_sqrt_m = 0.2;
  // Above 0: every walk carries an IMU's gravity per frame, this good (SimConfig::imu_gravity_deg).
  // It draws nothing: the girders are the same with it or without.
  double imu_gravity_deg = 0.0;
  // Walks that turn the camera round once per compartment past a plate (SimWalk::look_back).
  // Drawn from a stream of their own: the girders are the same whatever this is.
  double look_back_fraction = 0.0;
  double min_stop_spacing_m = 0.5, max_stop_spacing_m = 0.8;
  int frames_per_stop = 2;
};

// One girder of the family: what was drawn (for the report) and the simulator's config.
struct GirderDraw {
  int index = 0;
  SimConfig config;
  std::string summary;  // e.g. "34.2 m, 0.86 x 1.24 m, plates every 4.1 m, R 320 m, drift"
  bool constant_section = true;
  bool drifted = false;
};

std::vector<GirderDraw> draw_girders(int count, unsigned seed, const GirderRanges& ranges = {});

}  // namespace tunnelmap
