#include "bench/openvdb_peer.h"

#include <openvdb/openvdb.h>

#include <vector>

#include "core/fusion/truncation_band.h"

namespace tunnelmap::bench {

using WeightTree = openvdb::tree::Tree4<std::uint16_t, 5, 4, 3>::Type;

struct OpenVdbTsdf::Grids {
  openvdb::FloatTree tsdf{1.0f};
  WeightTree weight{0};
  std::vector<std::pair<openvdb::FloatTree::LeafNodeType*, WeightTree::LeafNodeType*>> touched;
};

OpenVdbTsdf::OpenVdbTsdf(double voxel_m, const TsdfOptions& options)
    : voxel_m_(voxel_m), options_(options), grids_(std::make_unique<Grids>()) {
  openvdb::initialize();
}

OpenVdbTsdf::~OpenVdbTsdf() = default;

std::size_t OpenVdbTsdf::leaf_count() const { return grids_->tsdf.leafCount(); }

std::size_t OpenVdbTsdf::memory_bytes() const {
  return std::size_t(grids_->tsdf.memUsage() + grids_->weight.memUsage());
}

void OpenVdbTsdf::integrate(const DepthFrame& frame, const Eigen::Isometry3d& camera_to_world) {
  const FrameProjection fp(frame, options_);
  openvdb::tree::ValueAccessor<openvdb::FloatTree> tsdf(grids_->tsdf);
  openvdb::tree::ValueAccessor<WeightTree> weight(grids_->weight);
  // A leaf is new to this frame when it was not touched yet: mark it by its first voxel's
  // active state off -> on (reset after the frame).
  grids_->touched.clear();
  for_each_band_block(fp, camera_to_world, float(voxel_m_ * 8), [&](const Eigen::Vector3i& b) {
    const openvdb::Coord origin(b.x() * 8, b.y() * 8, b.z() * 8);
    auto* leaf = tsdf.touchLeaf(origin);
    if (leaf->isValueOn(0)) return;
    leaf->setActiveState(0, true);
    grids_->touched.emplace_back(leaf, weight.touchLeaf(origin));
  });
  const Eigen::Isometry3d world_to_cam = camera_to_world.inverse();
  const Eigen::Matrix3f R = world_to_cam.linear().cast<float>();
  const float step = float(voxel_m_);
  std::uint8_t rgb[3] = {0, 0, 0}, colour_weight = 0;  // depth only
  for (auto& [t, w] : grids_->touched) {
    const openvdb::Coord o = t->origin();
    const Eigen::Vector3f first =
        (world_to_cam * (Eigen::Vector3d(o.x(), o.y(), o.z()) * voxel_m_)).cast<float>();
    float* tv = t->buffer().data();
    std::uint16_t* wv = w->buffer().data();
    // OpenVDB leaf order: offset = (x << 6) | (y << 3) | z.
    for (int x = 0; x < 8; ++x)
      for (int y = 0; y < 8; ++y) {
        Eigen::Vector3f pc = first + R.col(0) * (step * float(x)) + R.col(1) * (step * float(y));
        const int row = (x << 6) | (y << 3);
        for (int z = 0; z < 8; ++z, pc += R.col(2) * step)
          update_voxel(fp, pc, tv[row | z], wv[row | z], rgb, colour_weight);
      }
    t->setActiveState(0, false);
  }
}

}  // namespace tunnelmap::bench
