#pragma once
// The depth sensor's error model (see docs/simulator.md for the sources):
//  - axial and lateral noise vs depth and incidence angle: Nguyen, Izadi, Lovell 2012,
//    "Modeling Kinect Sensor Noise for Improved 3D Reconstruction and Tracking", 3DIMPVT;
//  - disparity quantisation of a structured-light sensor: Khoshelham & Elberink 2012,
//    "Accuracy and Resolution of Kinect Depth Data for Indoor Mapping Applications",
//    Sensors 12:1437.
// Angles in radians, depths in metres.

namespace tunnelmap::sim {

// Incidence angles beyond this are evaluated here (the model diverges at 90 deg).
constexpr double kMaxModelAngleRad = 88.0 * 3.14159265358979323846 / 180.0;

// Axial (along the optical axis) standard deviation in metres, Nguyen et al. eq. for
// theta <= 60 deg plus the angular term for theta > 60 deg.
double axial_sigma_m(double depth_m, double incidence_rad);

// Lateral standard deviation in pixels, Nguyen et al.
double lateral_sigma_px(double incidence_rad);

// Quantises depth through the disparity d = fx*b/z rounded to 1/steps pixel.
// Returns 0 when the disparity rounds to 0 (out of range).
double quantize_depth_m(double depth_m, double fx, double baseline_m, int steps);

// Depth step between two adjacent quantised disparities at this depth (z^2 / (fx b steps)).
double quantization_step_m(double depth_m, double fx, double baseline_m, int steps);

// Time-of-flight axial standard deviation in metres: (base + per_m * z) / sqrt(cos theta), cos
// clamped at 0.1 (the returned amplitude falls with the incidence; noise ~ 1/sqrt(amplitude)).
double tof_sigma_m(double depth_m, double incidence_rad, double base_m, double per_m);

// Dropout probability from the incidence angle alone: 0 below start, rising as the square of
// the normalised angle to 1 at full.
double grazing_dropout_probability(double incidence_rad, double start_deg, double full_deg);

}  // namespace tunnelmap::sim
