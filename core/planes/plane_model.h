#pragma once
// The incremental plane model of PG&C (paper eq. 3-4): only N, the running mean point and the
// running mean normal are needed for growing. Second moments ride along so that the final
// least-squares normal and RMS come for free, without a second pass over the points.
#include <Eigen/Core>
#include <Eigen/Eigenvalues>

namespace tunnelmap {

class PlaneModel {
 public:
  void add(const Eigen::Vector3f& p, const Eigen::Vector3f& n) {
    const Eigen::Vector3d pd = p.cast<double>();
    ++count_;
    // eq. 4: p*_{N+1} = (N p*_N + p) / (N + 1), likewise n*.
    const double w = 1.0 / static_cast<double>(count_);
    mean_point_ += (pd - mean_point_) * w;
    mean_normal_ += (n.cast<double>() - mean_normal_) * w;
    sum_pp_ += pd * pd.transpose();
    sum_z3_ += pd.z() * pd.z() * pd.z();
    dirty_ = true;
  }

  long count() const { return count_; }
  const Eigen::Vector3d& mean_point() const { return mean_point_; }
  const Eigen::Vector3d& mean_normal() const { return mean_normal_; }  // not normalised
  double sum_z_cubed() const { return sum_z3_; }

  // Unit mean normal and mean point as floats for the growing tests (cached until the next add).
  void growth_model(Eigen::Vector3f& point, Eigen::Vector3f& unit_normal) const {
    if (dirty_) {
      cached_point_ = mean_point_.cast<float>();
      cached_normal_ = mean_normal_.normalized().cast<float>();
      dirty_ = false;
    }
    point = cached_point_;
    unit_normal = cached_normal_;
  }

  // Covariance of the points about their mean.
  Eigen::Matrix3d covariance() const {
    return sum_pp_ / static_cast<double>(count_) - mean_point_ * mean_point_.transpose();
  }

  // Least-squares normal (smallest eigenvector of the covariance), oriented like the mean
  // normal; `rms` receives the RMS point-to-plane distance.
  Eigen::Vector3d least_squares_normal(double* rms) const {
    Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(covariance());
    Eigen::Vector3d n = eig.eigenvectors().col(0);
    if (n.dot(mean_normal_) < 0) n = -n;
    if (rms) *rms = std::sqrt(std::max(0.0, eig.eigenvalues()(0)));
    return n;
  }

 private:
  long count_ = 0;
  Eigen::Vector3d mean_point_ = Eigen::Vector3d::Zero();
  Eigen::Vector3d mean_normal_ = Eigen::Vector3d::Zero();
  Eigen::Matrix3d sum_pp_ = Eigen::Matrix3d::Zero();
  double sum_z3_ = 0.0;
  mutable bool dirty_ = true;
  mutable Eigen::Vector3f cached_point_, cached_normal_;
};

}  // namespace tunnelmap
