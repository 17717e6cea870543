#include "core/planes/region_grower.h"

#include <emmintrin.h>

#include <algorithm>
#include <cmath>

#include "core/planes/grazing_growth.h"
#include "core/planes/plane_growing.h"

namespace tunnelmap {

namespace {

// The eq. 4 model (mean point p*, mean normal n*) in the form the eq. 2 tests use without a
// division: with S = N n*_N (the sum of normals, not unit) and |S| its length,
//   |n*.q - n*.p*| <= eps   <=>  |S.q - d0| <= eps |S|,     d0 = S.p*
//   nq.n* >= cos(lambda)    <=>  nq.S >= cos(lambda) |S|
// so a refresh costs one square root and one reciprocal, which run in parallel.
struct GrowthModel {
  float sx, sy, sz, d0, tol_d, tol_n;
  void refresh(const PlaneModel& m, float eps, float cos_angle) {
    const Eigen::Vector3d& sn = m.sum_normal();
    const Eigen::Vector3d& sp = m.sum_point();
    const float inv_n = 1.0f / static_cast<float>(m.count());
    sx = static_cast<float>(sn.x()), sy = static_cast<float>(sn.y()), sz = static_cast<float>(sn.z());
    const float len = std::sqrt(sx * sx + sy * sy + sz * sz);
    d0 = (sx * static_cast<float>(sp.x()) + sy * static_cast<float>(sp.y()) + sz * static_cast<float>(sp.z())) * inv_n;
    tol_d = eps * len;
    tol_n = cos_angle * len;
  }
};

// Bit (dv + 2) * 5 + (du + 2) is set when the pixel at (du, dv) from `c` is free: four labels
// of each window row in one SSE2 compare, the fifth by hand.
inline std::uint32_t free_mask_5x5(const std::int32_t* c, int pw) {
  const __m128i zero = _mm_setzero_si128();
  std::uint32_t mask = 0;
  for (int r = 0; r < 5; ++r) {
    const std::int32_t* row = c + (r - 2) * pw - 2;
    const __m128i a = _mm_loadu_si128(reinterpret_cast<const __m128i*>(row));
    std::uint32_t bits = static_cast<std::uint32_t>(_mm_movemask_ps(_mm_castsi128_ps(_mm_cmpeq_epi32(a, zero))));
    bits |= static_cast<std::uint32_t>(row[4] == 0) << 4;
    mask |= bits << (5 * r);
  }
  return mask;
}

// The same for a 3x3 window: bit (dv + 1) * 3 + (du + 1).
inline std::uint32_t free_mask_3x3(const std::int32_t* c, int pw) {
  const __m128i zero = _mm_setzero_si128();
  std::uint32_t mask = 0;
  for (int r = 0; r < 3; ++r) {
    const std::int32_t* row = c + (r - 1) * pw - 1;
    const __m128i a = _mm_loadu_si128(reinterpret_cast<const __m128i*>(row));
    const std::uint32_t bits = static_cast<std::uint32_t>(_mm_movemask_ps(_mm_castsi128_ps(_mm_cmpeq_epi32(a, zero))));
    mask |= (bits & 7u) << (3 * r);
  }
  return mask;
}

}  // namespace

void RegionGrower::configure(const OrganizedCloud& cloud, const GrowOptions& o) {
  cloud_ = &cloud;
  w_ = cloud.width, h_ = cloud.height;
  half_ = std::max(1, o.neighbourhood_n / 2);
  pad_ = std::max(half_, 2);  // the SIMD window reads two labels right of the centre
  pw_ = w_ + 2 * pad_;
  cos_angle_ = static_cast<float>(std::cos(o.angle_deg * M_PI / 180.0));
  eps_ = static_cast<float>(o.distance_m);
  cand2_ = static_cast<float>(o.candidate_distance_m * o.candidate_distance_m);
  offsets_.clear(), step_u_.clear(), step_v_.clear();
  for (int dv = -half_; dv <= half_; ++dv)
    for (int du = -half_; du <= half_; ++du) {
      offsets_.push_back(dv * pw_ + du);
      step_u_.push_back(du);
      step_v_.push_back(dv);
    }
  const std::size_t padded_size = static_cast<std::size_t>(pw_) * (h_ + 2 * pad_);
  // Only the padding is set here: reset() and reset_unlabelled() write every interior label
  // (and reset_unlabelled every interior "tried" mark), so the frame is not written twice.
  labels_.resize(padded_size);
  tried_.resize(padded_size);
  std::int32_t* const lab = labels_.data();
  const std::size_t band = static_cast<std::size_t>(pad_) * pw_;
  std::fill(lab, lab + band, kNoNormal);
  std::fill(lab + padded_size - band, lab + padded_size, kNoNormal);
  for (int v = 0; v < h_; ++v) {
    std::int32_t* row = lab + padded(0, v);
    std::fill(row - pad_, row, kNoNormal);
    std::fill(row + w_, row + w_ + pad_, kNoNormal);
  }
  queue_.reserve(static_cast<std::size_t>(w_) * h_);
  rejected_.reserve(static_cast<std::size_t>(w_) * h_);
}

void RegionGrower::reset(const OrganizedCloud& cloud, const GrowOptions& o) {
  configure(cloud, o);
  std::fill(tried_.begin(), tried_.end(), 0);
  packed_valid_ = true;
  const float* n = cloud.normals.data()->data();
  const float* pt = cloud.points.data()->data();
  packed_.resize(static_cast<std::size_t>(w_) * h_ * 8);
  float* pk = packed_.data();
  for (int v = 0; v < h_; ++v) {
    std::int32_t* row = labels_.data() + padded(0, v);
    const std::size_t base = static_cast<std::size_t>(v) * w_;
    const float* nr = n + base * 3;
    const float* pr = pt + base * 3;
    float* kr = pk + base * 8;
    for (int u = 0; u < w_; ++u) {
      row[u] = nr[3 * u] == nr[3 * u] ? kFree : kNoNormal;
      kr[8 * u] = pr[3 * u], kr[8 * u + 1] = pr[3 * u + 1], kr[8 * u + 2] = pr[3 * u + 2], kr[8 * u + 3] = 0;
      kr[8 * u + 4] = nr[3 * u], kr[8 * u + 5] = nr[3 * u + 1], kr[8 * u + 6] = nr[3 * u + 2], kr[8 * u + 7] = 0;
    }
  }
}

void RegionGrower::reset_unlabelled(const OrganizedCloud& cloud, const GrowOptions& o,
                                    const std::vector<std::uint8_t>& states) {
  configure(cloud, o);
  packed_valid_ = false;
  for (int v = 0; v < h_; ++v) {
    std::int32_t* row = labels_.data() + padded(0, v);
    std::uint8_t* tried = tried_.data() + padded(0, v);
    const std::size_t base = static_cast<std::size_t>(v) * w_;
    const std::uint8_t* sr = states.data() + base;
    for (int u = 0; u < w_; ++u) {
      // "Tried" pixels never seed, but may still join.
      row[u] = sr[u] != kEdgeOnTaken ? kFree : kNoNormal;
      tried[u] = sr[u] != kEdgeOnSeed;
    }
  }
}

bool RegionGrower::seed(int u, int v, PlaneModel& model) const {
  if (u + 1 >= w_ || v + 1 >= h_) return false;
  if (!seedable(u + 1, v) || !seedable(u, v + 1) || !seedable(u + 1, v + 1)) return false;
  const std::size_t idx[4] = {cloud_->index(u, v), cloud_->index(u + 1, v), cloud_->index(u, v + 1),
                              cloud_->index(u + 1, v + 1)};
  const Eigen::Vector3f& n0 = cloud_->normals[idx[0]];
  for (int k = 1; k < 4; ++k)
    if (cloud_->normals[idx[k]].dot(n0) < cos_angle_) return false;
  for (std::size_t i : idx) model.add(cloud_->points[i], cloud_->normals[i]);
  const Eigen::Vector3f p = model.mean_point().cast<float>();
  const Eigen::Vector3f n = model.sum_normal().normalized().cast<float>();
  for (std::size_t i : idx)
    if (std::abs(n.dot(cloud_->points[i] - p)) > eps_) return false;
  return true;
}

void RegionGrower::grow(int u, int v, std::int32_t id, PlaneModel& model) {
  queue_.clear();
  for (int dv = 0; dv < 2; ++dv)
    for (int du = 0; du < 2; ++du) {
      const std::size_t p = padded(u + du, v + dv);
      labels_[p] = id;
      queue_.push_back({static_cast<std::int32_t>(p), u + du, v + dv});
    }
  bbox_u0 = u, bbox_v0 = v, bbox_u1 = u + 1, bbox_v1 = v + 1;
  if (packed_valid_) {
    const float* pk = packed_.data();
    switch (half_) {
      case 1: grow_window<1, 8>(id, model, pk, pk + 4); break;
      case 2: grow_window<2, 8>(id, model, pk, pk + 4); break;
      default: grow_generic(id, model); break;
    }
  } else {  // straight from the cloud's xyz arrays
    const float* pts = cloud_->points.data()->data();
    const float* nrm = cloud_->normals.data()->data();
    switch (half_) {
      case 1: grow_window<1, 3>(id, model, pts, nrm); break;
      case 2: grow_window<2, 3>(id, model, pts, nrm); break;
      default: grow_generic(id, model); break;
    }
  }
  // The pixels this region rejected are free for the next one.
  for (const std::int32_t p : rejected_) labels_[p] = kFree;
  rejected_.clear();
}

// The hot loop. Visits the window's free pixels in row-major order (the order of the bits),
// exactly like a plain double loop over the window would.
// Points and normals are read `S` floats apart: the packed copy (S = 8) or the cloud (S = 3).
template <int H, int S>
void RegionGrower::grow_window(std::int32_t id, PlaneModel& model, const float* pts, const float* nrm) {
  constexpr int side = 2 * H + 1;
  std::int32_t* const labels = labels_.data();
  const int pw = pw_, w = w_;
  const float eps = eps_, cos_angle = cos_angle_, cand2 = cand2_;
  GrowthModel g;
  g.refresh(model, eps, cos_angle);
  int u0 = bbox_u0, v0 = bbox_v0, u1 = bbox_u1, v1 = bbox_v1;
  for (std::size_t head = 0; head < queue_.size(); ++head) {
    const Member m = queue_[head];
    const std::int32_t* c = labels + m.padded;
    std::uint32_t mask = H == 2 ? free_mask_5x5(c, pw) : free_mask_3x3(c, pw);
    if (!mask) continue;
    const float* pi = pts + S * (static_cast<std::size_t>(m.v) * w + m.u);
    const float pix = pi[0], piy = pi[1], piz = pi[2];
    while (mask) {
      const int bit = __builtin_ctz(mask);
      mask &= mask - 1;
      const int du = bit % side - H, dv = bit / side - H;  // constants folded: side is 3 or 5
      const int qu = m.u + du, qv = m.v + dv;
      const std::size_t qi = S * (static_cast<std::size_t>(qv) * w + qu);
      const float qx = pts[qi], qy = pts[qi + 1], qz = pts[qi + 2];
      const float ex = qx - pix, ey = qy - piy, ez = qz - piz;
      if (ex * ex + ey * ey + ez * ez > cand2) continue;  // candidate distance: depends on m, retest
      const std::int32_t qp = m.padded + dv * pw + du;
      const float nx = nrm[qi], ny = nrm[qi + 1], nz = nrm[qi + 2];
      if (std::abs(g.sx * qx + g.sy * qy + g.sz * qz - g.d0) > g.tol_d ||  // eq. 2, distance
          g.sx * nx + g.sy * ny + g.sz * nz < g.tol_n) {                   // eq. 2, angle
        if (model.count() >= kSettledModel) reject(qp);
        continue;
      }
      labels[qp] = id;
      model.add(Eigen::Vector3f(qx, qy, qz), Eigen::Vector3f(nx, ny, nz));  // eq. 4
      g.refresh(model, eps, cos_angle);
      queue_.push_back({qp, qu, qv});
      u0 = std::min(u0, qu), u1 = std::max(u1, qu);
      v0 = std::min(v0, qv), v1 = std::max(v1, qv);
    }
  }
  bbox_u0 = u0, bbox_v0 = v0, bbox_u1 = u1, bbox_v1 = v1;
}

// Any other window size: the same tests over the offsets table.
void RegionGrower::grow_generic(std::int32_t id, PlaneModel& model) {
  GrowthModel g;
  g.refresh(model, eps_, cos_angle_);
  const int n_off = static_cast<int>(offsets_.size());
  for (std::size_t head = 0; head < queue_.size(); ++head) {
    const Member m = queue_[head];
    const Eigen::Vector3f& pi = cloud_->points[cloud_->index(m.u, m.v)];
    for (int k = 0; k < n_off; ++k) {
      const std::int32_t qp = m.padded + offsets_[k];
      if (labels_[qp] != kFree) continue;
      const int qu = m.u + step_u_[k], qv = m.v + step_v_[k];
      const Eigen::Vector3f& q = cloud_->points[cloud_->index(qu, qv)];
      if ((q - pi).squaredNorm() > cand2_) continue;
      const Eigen::Vector3f& nq = cloud_->normals[cloud_->index(qu, qv)];
      if (std::abs(g.sx * q.x() + g.sy * q.y() + g.sz * q.z() - g.d0) > g.tol_d ||
          g.sx * nq.x() + g.sy * nq.y() + g.sz * nq.z() < g.tol_n) {
        if (model.count() >= kSettledModel) reject(qp);
        continue;
      }
      labels_[qp] = id;
      model.add(q, nq);
      g.refresh(model, eps_, cos_angle_);
      queue_.push_back({qp, qu, qv});
      bbox_u0 = std::min(bbox_u0, qu), bbox_u1 = std::max(bbox_u1, qu);
      bbox_v0 = std::min(bbox_v0, qv), bbox_v1 = std::max(bbox_v1, qv);
    }
  }
}

void RegionGrower::release() {
  for (const Member& m : queue_) {
    labels_[m.padded] = kFree;
    tried_[m.padded] = 1;
  }
}

void RegionGrower::export_labels(std::vector<std::int32_t>& labels) const {
  labels.resize(static_cast<std::size_t>(w_) * h_);
  for (int v = 0; v < h_; ++v) {
    const std::int32_t* src = labels_.data() + padded(0, v);
    std::int32_t* dst = labels.data() + static_cast<std::size_t>(v) * w_;
    for (int u = 0; u < w_; ++u) dst[u] = std::max(src[u], 0);
  }
}

}  // namespace tunnelmap
