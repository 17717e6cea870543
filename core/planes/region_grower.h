#pragma once
// The PG&C growing loop (paper section 2.1, eq. 2-4) over an organised cloud, built for speed:
// a padded flat label image (no border tests), one index queue that doubles as the region's
// member list, the n*n window's free pixels found with SIMD compares, and the eq. 4 model
// refreshed after every join in a division-free form. Reused across frames: no allocation per
// frame in the steady state.
#include <cstdint>
#include <vector>

#include "core/frame/organized_cloud.h"
#include "core/planes/plane_model.h"

namespace tunnelmap {

struct GrowOptions;

class RegionGrower {
 public:
  static constexpr std::int32_t kNoNormal = -1;  // can never join a plane (also the padding)
  static constexpr std::int32_t kFree = 0;
  // A pixel that failed the eq. 2 plane tests of the region growing now: the model of a settled
  // region moves too little for a retest from the next member to pass, so it is not retried
  // (region growing's "visited" mark; a third fewer tests on the real cape frame).
  static constexpr std::int32_t kRejected = -2;
  // Until then the model is young (a 2x2 seed's normal can be degrees off): failures are retried.
  static constexpr long kSettledModel = 64;

  struct Member {
    std::int32_t padded;  // index in the padded label image
    std::int32_t u, v;    // pixel
  };

  // Prepares the label image for `cloud` (pixels without a normal can never join).
  void reset(const OrganizedCloud& cloud, const GrowOptions& options);

  // For the edge-on pass after coarse-to-fine growing (grazing_growth.h): only pixels whose
  // state is kEdgeOnJoinable or kEdgeOnSeed can join a plane, only kEdgeOnSeed ones can seed.
  // Growth reads the cloud directly: the pass touches few pixels, and packing the whole frame
  // would cost more than it saves.
  void reset_unlabelled(const OrganizedCloud& cloud, const GrowOptions& options,
                        const std::vector<std::uint8_t>& states);

  // Tries to seed at (u, v): a 2x2 block of free, never-tried pixels whose normals agree within
  // lambda and whose points lie within epsilon of the plane through their mean (the paper's
  // "three or four adjacent points"). On success `model` holds the block.
  bool seed(int u, int v, PlaneModel& model) const;

  // Breadth-first growth from the seed block with the eq. 2 tests and eq. 4 updates; the region's
  // pixels are then members(), labelled `id`; their bounding box is in bbox.
  void grow(int u, int v, std::int32_t id, PlaneModel& model);

  const std::vector<Member>& members() const { return queue_; }
  int bbox_u0 = 0, bbox_v0 = 0, bbox_u1 = 0, bbox_v1 = 0;

  // A rejected region's pixels become free again but never seed again.
  void release();

  // Copies the labels (kNoNormal -> 0) into a width*height image.
  void export_labels(std::vector<std::int32_t>& labels) const;

  bool seedable(int u, int v) const {
    const std::size_t p = padded(u, v);
    return labels_[p] == kFree && !tried_[p];
  }

 private:
  std::size_t padded(int u, int v) const {
    return static_cast<std::size_t>(v + pad_) * pw_ + static_cast<std::size_t>(u + pad_);
  }
  void configure(const OrganizedCloud& cloud, const GrowOptions& options);
  template <int H, int S>
  void grow_window(std::int32_t id, PlaneModel& model, const float* pts, const float* nrm);
  void grow_generic(std::int32_t id, PlaneModel& model);
  void reject(std::int32_t padded_index) {
    labels_[padded_index] = kRejected;
    rejected_.push_back(padded_index);
  }

  const OrganizedCloud* cloud_ = nullptr;
  int w_ = 0, h_ = 0, pad_ = 0, pw_ = 0, half_ = 2;
  bool packed_valid_ = false;  // false after reset_unlabelled: growth reads the cloud
  float cos_angle_ = 0, eps_ = 0, cand2_ = 0;
  std::vector<std::int32_t> labels_;  // padded
  std::vector<std::uint8_t> tried_;   // padded
  std::vector<Member> queue_;
  std::vector<std::int32_t> rejected_;  // padded indices marked kRejected by the current region
  std::vector<float> packed_;  // per pixel x, y, z, -, nx, ny, nz, -: one cache line half per candidate
  std::vector<int> offsets_;                   // padded index steps of the window
  std::vector<int> step_u_, step_v_;  // the same steps in pixels
};

}  // namespace tunnelmap
