#pragma once
// The incremental plane model of PG&C (paper eq. 3-4). The running means p*_N and n*_N of
// eq. 4 are kept as the sums N p*_N and N n*_N (the same numbers, one division later), so an
// update is a few additions and the model used by the growing tests is refreshed once per
// added point. Second moments ride along so that the least-squares normal and RMS come for
// free, without a second pass over the region's points.
#include <Eigen/Core>
#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>

namespace tunnelmap {

class PlaneModel {
 public:
  void add(const Eigen::Vector3f& p, const Eigen::Vector3f& n) {
    const double x = p.x(), y = p.y(), z = p.z();
    ++count_;
    sum_p_ += Eigen::Vector3d(x, y, z);
    sum_n_ += n.cast<double>();
    // Upper triangle of sum p p^T: xx, xy, xz, yy, yz, zz.
    sum_pp_[0] += x * x, sum_pp_[1] += x * y, sum_pp_[2] += x * z;
    sum_pp_[3] += y * y, sum_pp_[4] += y * z, sum_pp_[5] += z * z;
    sum_z3_ += z * z * z;
  }

  // Adds `n` points given by their moments (sum p, sum p p^T as xx xy xz yy yz zz, sum z^3),
  // each with the normal `normal`: a cell of the cell-based growing order joining at once.
  void add_moments(long n, const Eigen::Vector3d& sum_p, const double sum_pp[6], double sum_z3,
                   const Eigen::Vector3d& normal) {
    count_ += n;
    sum_p_ += sum_p;
    sum_n_ += static_cast<double>(n) * normal;
    for (int k = 0; k < 6; ++k) sum_pp_[k] += sum_pp[k];
    sum_z3_ += sum_z3;
  }

  // Adds another model's points (the model of the union of both point sets).
  void merge(const PlaneModel& o) {
    count_ += o.count_;
    sum_p_ += o.sum_p_;
    sum_n_ += o.sum_n_;
    for (int k = 0; k < 6; ++k) sum_pp_[k] += o.sum_pp_[k];
    sum_z3_ += o.sum_z3_;
  }

  long count() const { return count_; }
  const Eigen::Vector3d& sum_point() const { return sum_p_; }    // N p*_N
  const Eigen::Vector3d& sum_normal() const { return sum_n_; }   // N n*_N
  Eigen::Vector3d mean_point() const { return sum_p_ / static_cast<double>(count_); }    // p*
  Eigen::Vector3d mean_normal() const { return sum_n_ / static_cast<double>(count_); }   // n*, not unit
  double sum_z_cubed() const { return sum_z3_; }

  // Mean point and unit mean normal as floats, for the growing tests.
  void growth_model(Eigen::Vector3f& point, Eigen::Vector3f& unit_normal) const {
    point = (sum_p_ / static_cast<double>(count_)).cast<float>();
    unit_normal = sum_n_.normalized().cast<float>();
  }

  // Covariance of the points about their mean.
  Eigen::Matrix3d covariance() const {
    const double inv = 1.0 / static_cast<double>(count_);
    const Eigen::Vector3d m = sum_p_ * inv;
    Eigen::Matrix3d c;
    c << sum_pp_[0], sum_pp_[1], sum_pp_[2], sum_pp_[1], sum_pp_[3], sum_pp_[4], sum_pp_[2], sum_pp_[4], sum_pp_[5];
    return c * inv - m * m.transpose();
  }

  // Least-squares normal (smallest eigenvector of the covariance), oriented like the mean
  // normal; `rms` receives the RMS point-to-plane distance.
  Eigen::Vector3d least_squares_normal(double* rms) const {
    Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(covariance());
    Eigen::Vector3d n = eig.eigenvectors().col(0);
    if (n.dot(sum_n_) < 0) n = -n;
    if (rms) *rms = std::sqrt(std::max(0.0, eig.eigenvalues()(0)));
    return n;
  }

 private:
  long count_ = 0;
  Eigen::Vector3d sum_p_ = Eigen::Vector3d::Zero();
  Eigen::Vector3d sum_n_ = Eigen::Vector3d::Zero();
  double sum_pp_[6] = {0, 0, 0, 0, 0, 0};
  double sum_z3_ = 0.0;
};

}  // namespace tunnelmap
