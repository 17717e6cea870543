#include "core/solvers/correction_evidence.h"

#include <algorithm>
#include <cmath>

namespace tunnelmap {

CorrectionEvidence correction_evidence(double given_cost, double refined_cost, int free_poses, double sigmas) {
  CorrectionEvidence e;
  e.dof = 6 * std::max(0, free_poses);
  e.chi2_gain = std::max(0.0, 2.0 * (given_cost - refined_cost));
  e.threshold = e.dof + std::max(0.0, sigmas) * std::sqrt(2.0 * e.dof);
  e.significant = sigmas <= 0.0 ? e.dof > 0 : e.chi2_gain > e.threshold;
  return e;
}

}  // namespace tunnelmap
