#pragma once
// The zones of one wall in one frame (edge bands, middle plate) as parallel layers a plate's
// thickness apart, each block sample on the layer it lies on.
//
// The plane segmentation decides pixel by pixel, and where a pixel's depth noise is as large
// as the plates' step it grows one plane over both zones. The share of each zone in such a
// plane changes with the distance from the camera, so the plane tilts: on a 6 mm step seen
// from 1.5 m, by 0.1 deg, which turns the map's heading at every diaphragm. A block sample
// averages 64 pixels and tells the zones apart to several metres: each is put on the layer
// its own distance from the wall's outer surface says. That surface is fitted on the samples
// themselves, the nearest first (their planes' zones are the surest, their noise the least),
// with a curvature along the girder (a horizontal curve bends a wall by 13 mm over 4 m at a
// 150 m radius). A sample whose noise is too large to tell the layers apart, or that lies
// between them (a block across a zone's edge), is left out: it would pull its layer towards
// the other.
#include <Eigen/Core>
#include <vector>

namespace tunnelmap {

// Zones closer than this are one: plates are several millimetres thick, and a frame's outer
// surface lies within a millimetre.
inline constexpr double kMinZoneStepM = 0.0025;

struct LayerSample {
  Eigen::Vector3d point = Eigen::Vector3d::Zero();  // camera frame
  double sigma_m = 0.0;  // its noise along the wall's normal (the block's mean)
  double inset_m = 0.0;  // what its plane's zone says: how far inside the outer surface
};

struct WallLayerOptions {
  double min_gap_m = kMinZoneStepM;     // insets closer than this are one layer
  double resolve_fraction = 1.0 / 6.0;  // a sample resolves layers `gap` apart when sigma <= this * gap
  double between_fraction = 1.0 / 3.0;  // farther than this * gap from its layer: between two
  int iterations = 3;
};

// Per sample: the inset of the layer it lies on, or NaN when it is left out. `outward`: the
// wall's normal pointing out of the tunnel, `axis`: along the girder (camera frame). With one
// layer, each sample keeps its plane's inset.
std::vector<double> wall_zone_layers(const std::vector<LayerSample>& samples, const Eigen::Vector3d& outward,
                                     const Eigen::Vector3d& axis,
                                     const WallLayerOptions& options = WallLayerOptions());

}  // namespace tunnelmap
