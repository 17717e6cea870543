#pragma once
// The dataset.json "robot" object <-> RobotModel. Format: docs/kinematics.md.
#include <nlohmann/json.hpp>
#include <string>

#include "core/kinematics/robot_model.h"

namespace tunnelmap {

// {"preset": "inchworm7"} alone gives the preset; explicit keys override it. InputError naming
// `source` and the key on any problem (unknown convention, missing DH entry, min > max, ...).
RobotModel robot_from_json(const nlohmann::json& j, const std::string& source);
nlohmann::json robot_to_json(const RobotModel& robot);

// 4x4 row-major (16 numbers or 4 rows of 4) <-> isometry; InputError when not rigid.
Eigen::Isometry3d isometry_from_json(const nlohmann::json& j, const std::string& source,
                                     const std::string& key);
nlohmann::json isometry_to_json(const Eigen::Isometry3d& T);

}  // namespace tunnelmap
