#pragma once
// One mapped girder against the simulator's truth (dataset.json "ground_truth.girder" and each
// frame's "pose_true"): station errors, phantom and found sections, plates placed, missed and
// invented, manhole sizes, pose corrections and the poses' remaining error.
#include <nlohmann/json.hpp>
#include <optional>
#include <vector>

#include "core/mapping/dataset_mapping.h"

namespace tunnelmap {

// One frame's pose against the truth after the alignment, in the truth girder's frame at the
// frame's truth station: position along, across (positive to the left) and vertically, and
// the rotation's parts about those three axes (roll, pitch, heading); signed.
struct FramePoseError {
  int frame = 0;
  double station_m = 0.0;
  double error_mm = 0.0, along_mm = 0.0, across_mm = 0.0, vertical_mm = 0.0;
  double rotation_deg = 0.0, roll_deg = 0.0, pitch_deg = 0.0, heading_deg = 0.0;
  bool split = false;  // the parts are known (not where the centre line runs vertically)
};

struct GirderScore {
  std::vector<double> width_error_mm, height_error_mm;  // per measured station, signed
  int sections_true = 0, sections_found = 0;
  int phantom_sections = 0;          // sections the truth does not have
  int joints_true = 0, joints_found = 0;  // joints found within joint_tolerance_m
  std::vector<double> joint_station_m;    // per true joint: its truth station
  std::vector<bool> joint_found;          // per true joint: found within joint_tolerance_m
  // True joints whose stepping walls the frames saw within joint_tolerance_m on both sides (the
  // rest lie in a stretch no frame saw: core/evaluation/joint_sightings.h), and of those, how
  // many were found; unset when the sightings were not taken.
  std::optional<int> joints_seen, joints_found_of_seen;
  std::vector<double> joint_seen_before_m, joint_seen_after_m;  // per true joint, when taken; NaN unseen
  // Per true joint, the nearest joint the map placed (signed, mm along the truth's centre line),
  // and how many of those lie within the uncertainty the map stated for them.
  std::vector<double> joint_error_mm;
  int joints_within_stated = 0;
  int plates_true = 0, plates_matched = 0, plates_missed = 0, plates_invented = 0;
  std::vector<double> plate_error_mm;                   // along the axis, signed
  std::vector<double> manhole_width_error_mm, manhole_height_error_mm;
  int manholes_unmeasured = 0;       // matched plates with an opening whose manhole is null
  std::vector<double> correction_mm, correction_deg;    // per pose group
  std::optional<bool> poses_kept;    // the evidence test kept the given poses (unset: not refined)
  std::vector<double> pose_error_mm, pose_error_deg;    // per frame, after one rigid alignment
  // The same position error split in the truth girder's frame at the frame's station: along
  // its centre line, across it (horizontal, positive to the left) and vertical; signed.
  std::vector<double> pose_error_along_mm, pose_error_across_mm, pose_error_vertical_mm;
  std::vector<FramePoseError> frame_pose_errors;  // every frame, in order
  double ms_per_frame = 0.0;
};

struct GirderScoringOptions {
  double skip_near_change_m = 0.15;  // stations this close to a plate or a joint are not scored
  double joint_tolerance_m = 0.2;
  double plate_tolerance_m = 0.02;
};

// `truth`: the dataset's "ground_truth"; `frames_json`: its "frames" (for "pose_true").
GirderScore score_girder(const DatasetMapping& mapped, const nlohmann::json& truth,
                         const nlohmann::json& frames_json, const GirderScoringOptions& options = {});

}  // namespace tunnelmap
