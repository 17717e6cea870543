#pragma once
// Whether a pose graph's data demand a correction of the given poses at all. The given poses
// are the null hypothesis: the landmarks are refitted to them (poses held), and the drop of
// the cost from there to the full optimum is compared with what the measurements' noise alone
// would give. Under the null hypothesis twice the drop follows a chi-square distribution with
// as many degrees of freedom as the free poses have parameters; only a drop beyond its mean by
// `sigmas` standard deviations is evidence of a pose error. Below it, the optimum only fits the
// measurements' own systematic errors (depth quantisation, calibration), which average away
// within a frame but not along a walk, and moving exact poses would make them worse.
namespace tunnelmap {

struct CorrectionEvidence {
  double chi2_gain = 0.0;   // 2 (cost at the given poses - cost at the optimum)
  int dof = 0;              // 6 per free pose
  double threshold = 0.0;   // dof + sigmas * sqrt(2 dof)
  bool significant = false; // chi2_gain > threshold: apply the correction
};

// `given_cost`, `refined_cost`: Ceres's costs (half the sum of squared weighted residuals).
// `sigmas` <= 0 makes every correction significant.
CorrectionEvidence correction_evidence(double given_cost, double refined_cost, int free_poses, double sigmas);

}  // namespace tunnelmap
