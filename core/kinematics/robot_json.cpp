#include "core/kinematics/robot_json.h"

#include <cmath>

#include "core/util/error.h"

namespace tunnelmap {

using nlohmann::json;

namespace {
constexpr double kDeg = M_PI / 180.0;

double number(const json& j, const std::string& source, const std::string& key) {
  if (!j.is_number()) throw InputError(source, key + " must be a number");
  const double v = j.get<double>();
  if (!std::isfinite(v)) throw InputError(source, key + " must be finite");
  return v;
}
}  // namespace

Eigen::Isometry3d isometry_from_json(const json& j, const std::string& source,
                                     const std::string& key) {
  std::vector<double> v;
  if (j.is_array() && j.size() == 4 && j[0].is_array()) {
    for (const json& row : j) {
      if (!row.is_array() || row.size() != 4) throw InputError(source, key + " must be 4x4");
      for (const json& x : row) v.push_back(number(x, source, key));
    }
  } else if (j.is_array() && j.size() == 16) {
    for (const json& x : j) v.push_back(number(x, source, key));
  } else {
    throw InputError(source, key + " must be a 4x4 matrix (16 numbers, row-major)");
  }
  Eigen::Matrix4d m;
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c) m(r, c) = v[static_cast<std::size_t>(r * 4 + c)];
  const Eigen::Matrix3d R = m.topLeftCorner<3, 3>();
  if ((R.transpose() * R - Eigen::Matrix3d::Identity()).cwiseAbs().maxCoeff() > 1e-4 ||
      R.determinant() < 0 || (m.row(3) - Eigen::RowVector4d(0, 0, 0, 1)).cwiseAbs().maxCoeff() > 1e-9)
    throw InputError(source, key + " is not a rigid transform");
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  T.linear() = R;
  T.translation() = m.topRightCorner<3, 1>();
  return T;
}

json isometry_to_json(const Eigen::Isometry3d& T) {
  json a = json::array();
  const Eigen::Matrix4d m = T.matrix();
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c) a.push_back(m(r, c));
  return a;
}

RobotModel robot_from_json(const json& j, const std::string& source) {
  if (!j.is_object()) throw InputError(source, "robot must be a JSON object");
  RobotModel r;
  if (j.contains("preset")) {
    if (!j["preset"].is_string()) throw InputError(source, "robot.preset must be a string");
    try {
      r = robot_preset(j["preset"].get<std::string>());
    } catch (const ParameterError& e) {
      throw InputError(source, e.what());
    }
  }
  if (j.contains("name") && j["name"].is_string()) r.name = j["name"].get<std::string>();
  if (j.contains("dh_convention")) {
    const std::string c = j["dh_convention"].is_string() ? j["dh_convention"].get<std::string>() : "";
    if (c == "standard") r.convention = DhConvention::Standard;
    else if (c == "modified") r.convention = DhConvention::Modified;
    else throw InputError(source, "robot.dh_convention must be \"standard\" or \"modified\"");
  }
  if (j.contains("joints")) {
    const json& js = j["joints"];
    if (!js.is_array() || js.empty()) throw InputError(source, "robot.joints must be a non-empty array");
    r.joints.clear();
    for (std::size_t i = 0; i < js.size(); ++i) {
      const json& e = js[i];
      const std::string key = "robot.joints[" + std::to_string(i) + "]";
      if (!e.is_object()) throw InputError(source, key + " must be an object");
      DhJoint d;
      d.name = e.value("name", "J" + std::to_string(i + 1));
      const std::string type = e.value("type", std::string("revolute"));
      if (type == "revolute") d.type = JointType::Revolute;
      else if (type == "prismatic") d.type = JointType::Prismatic;
      else throw InputError(source, key + ".type must be \"revolute\" or \"prismatic\"");
      for (const char* k : {"a_m", "alpha_deg", "d_m", "theta_deg"})
        if (!e.contains(k)) throw InputError(source, key + " lacks " + k);
      d.a_m = number(e["a_m"], source, key + ".a_m");
      d.alpha_rad = number(e["alpha_deg"], source, key + ".alpha_deg") * kDeg;
      d.d_m = number(e["d_m"], source, key + ".d_m");
      d.theta_rad = number(e["theta_deg"], source, key + ".theta_deg") * kDeg;
      const bool rev = d.type == JointType::Revolute;
      const char* kmin = rev ? "min_deg" : "min_m";
      const char* kmax = rev ? "max_deg" : "max_m";
      if (!e.contains(kmin) || !e.contains(kmax))
        throw InputError(source, key + " lacks " + kmin + "/" + kmax + " (joint limits)");
      const double s = rev ? kDeg : 1.0;
      d.min = number(e[kmin], source, key + "." + kmin) * s;
      d.max = number(e[kmax], source, key + "." + kmax) * s;
      if (d.min > d.max) throw InputError(source, key + ": joint limit min > max");
      r.joints.push_back(d);
    }
  }
  if (r.joints.empty()) throw InputError(source, "robot needs \"joints\" (a DH table) or a \"preset\"");
  if (j.contains("base")) r.base = isometry_from_json(j["base"], source, "robot.base");
  if (j.contains("tool_to_camera"))
    r.tool_to_camera = isometry_from_json(j["tool_to_camera"], source, "robot.tool_to_camera");
  return r;
}

json robot_to_json(const RobotModel& r) {
  json joints = json::array();
  for (const DhJoint& d : r.joints) {
    const bool rev = d.type == JointType::Revolute;
    const double s = rev ? 1.0 / kDeg : 1.0;
    joints.push_back({{"name", d.name},
                      {"type", rev ? "revolute" : "prismatic"},
                      {"a_m", d.a_m},
                      {"alpha_deg", d.alpha_rad / kDeg},
                      {"d_m", d.d_m},
                      {"theta_deg", d.theta_rad / kDeg},
                      {rev ? "min_deg" : "min_m", d.min * s},
                      {rev ? "max_deg" : "max_m", d.max * s}});
  }
  return {{"name", r.name},
          {"dh_convention", r.convention == DhConvention::Standard ? "standard" : "modified"},
          {"joint_units", "rad (revolute), m (prismatic)"},
          {"joints", joints},
          {"base", isometry_to_json(r.base)},
          {"tool_to_camera", isometry_to_json(r.tool_to_camera)}};
}

}  // namespace tunnelmap
