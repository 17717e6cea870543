#pragma once
// The candidate the sparse TSDF was measured against: the same truncation-band allocation and
// per-voxel update (core/fusion/truncation_band.h, tsdf_update.h) on OpenVDB trees (8^3
// leaves, as VDBFusion does), depth only. Kept in bench/ only (docs/fusion.md).
#include <Eigen/Geometry>
#include <cstddef>
#include <memory>

#include "core/frame/depth_frame.h"
#include "core/fusion/tsdf_update.h"

namespace tunnelmap::bench {

class OpenVdbTsdf {
 public:
  OpenVdbTsdf(double voxel_m, const TsdfOptions& options);
  ~OpenVdbTsdf();
  void integrate(const DepthFrame& frame, const Eigen::Isometry3d& camera_to_world);
  std::size_t leaf_count() const;
  std::size_t memory_bytes() const;

 private:
  struct Grids;
  double voxel_m_;
  TsdfOptions options_;
  std::unique_ptr<Grids> grids_;
};

}  // namespace tunnelmap::bench
