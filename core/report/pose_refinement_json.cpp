#include "core/report/pose_refinement_json.h"

namespace tunnelmap {

nlohmann::json pose_refinement_json(const PoseRefinement& r) {
  nlohmann::json evidence = nullptr;
  if (r.ran)
    evidence = {{"chi2_gain", r.evidence.chi2_gain},
                {"dof", r.evidence.dof},
                {"threshold", r.evidence.threshold},
                {"significant", r.evidence.significant}};
  return {{"ran", r.ran},
          {"iterations", r.iterations},
          {"ms", r.ms},
          {"given_poses_kept", r.ran ? nlohmann::json(r.given_poses_kept) : nlohmann::json(nullptr)},
          {"evidence", evidence}};
}

}  // namespace tunnelmap
