#pragma once
// Where the frames of a simulated girder saw the walls that step at each true joint: how well any
// map of those frames could place the joint. A roof that rises just past a plate is out of every
// frame's view for a metre or more: the plate hides it from the frames behind, and the field of
// view leaves it out from those just past the plate. Such a joint can be placed anywhere in
// that stretch, and no map of these frames can do better than its middle.
#include <limits>
#include <vector>

#include "core/evaluation/girder_scoring.h"
#include "core/evaluation/truth_line.h"
#include "core/io/dataset.h"

namespace tunnelmap {

struct JointSighting {
  double joint_m = 0.0;  // the joint's truth station
  // The truth stations nearest the joint where frames saw a stepping wall of the section before
  // it and of the section after it; NaN when no frame saw one.
  double seen_before_m = std::numeric_limits<double>::quiet_NaN();
  double seen_after_m = std::numeric_limits<double>::quiet_NaN();
  // Both sides seen within `reach` of the joint: a map of these frames can place it within `reach`.
  bool seen_within(double reach) const { return joint_m - seen_before_m <= reach && seen_after_m - joint_m <= reach; }
};

// The sightings of the joints at `joint_m` (truth stations, ascending: one per change of section
// in the dataset's "ground_truth.sections"), from each frame's ground-truth surface labels, depth
// and "pose_true". Empty when the dataset lacks labels or true poses, or its sections do not
// match the joints.
std::vector<JointSighting> joint_sightings(const Dataset& ds, const TruthLine& line, const std::vector<double>& joint_m);

// Sets `g.joints_seen` and `g.joints_found_of_seen` from the sightings of g's true joints.
void score_joint_sightings(const Dataset& ds, const GirderScoringOptions& options, GirderScore& g);

}  // namespace tunnelmap
