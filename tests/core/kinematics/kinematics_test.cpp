// Forward kinematics against hand-computed poses, DH JSON, IK round trip, sag model, and the
// pose precedence of dataset frames (explicit pose wins over joints).
#include <gtest/gtest.h>

#include <cmath>

#include "core/kinematics/frame_pose.h"
#include "core/kinematics/inverse_kinematics.h"
#include "core/kinematics/robot_json.h"
#include "core/kinematics/robot_model.h"
#include "core/kinematics/sag_model.h"
#include "core/sim/sim_arm.h"
#include "core/sim/tunnel_simulator.h"
#include "core/util/error.h"

using namespace tunnelmap;

namespace {
constexpr double kPi = 3.14159265358979323846;

DhJoint revolute(double a, double alpha_deg, double d) {
  DhJoint j;
  j.a_m = a;
  j.alpha_rad = alpha_deg * kPi / 180.0;
  j.d_m = d;
  return j;
}
}  // namespace

TEST(Kinematics, PlanarTwoLinkStandardDh) {
  RobotModel r;
  r.joints = {revolute(1.0, 0, 0), revolute(0.5, 0, 0)};
  // q = (90, -90) deg: first link along +y to (0,1,0), second along +x: flange at (0.5, 1, 0).
  const Eigen::Isometry3d T = r.flange_pose({kPi / 2, -kPi / 2});
  EXPECT_NEAR((T.translation() - Eigen::Vector3d(0.5, 1.0, 0.0)).norm(), 0.0, 1e-12);
  EXPECT_NEAR((T.linear() - Eigen::Matrix3d::Identity()).norm(), 0.0, 1e-12);
  // q = (30, 60) deg: (cos30 + 0.5 cos90, sin30 + 0.5 sin90) = (0.866025, 1.0).
  const Eigen::Isometry3d U = r.flange_pose({kPi / 6, kPi / 3});
  EXPECT_NEAR(U.translation().x(), std::sqrt(3.0) / 2.0, 1e-12);
  EXPECT_NEAR(U.translation().y(), 1.0, 1e-12);
}

TEST(Kinematics, ModifiedDhGivesTheSameArm) {
  // Craig's convention puts a link's length on the next joint: a_1 = 0, a_2 = 1, tool Tx(0.5).
  RobotModel m;
  m.convention = DhConvention::Modified;
  m.joints = {revolute(0.0, 0, 0), revolute(1.0, 0, 0)};
  m.tool_to_camera.translation() = Eigen::Vector3d(0.5, 0, 0);
  const Eigen::Isometry3d T = m.camera_pose({kPi / 6, kPi / 3});
  EXPECT_NEAR(T.translation().x(), std::sqrt(3.0) / 2.0, 1e-12);
  EXPECT_NEAR(T.translation().y(), 1.0, 1e-12);
  // Modified alpha acts before the joint: alpha_1 = 90 deg turns joint 1's axis to -y.
  RobotModel t;
  t.convention = DhConvention::Modified;
  t.joints = {revolute(0.2, 90, 0.3)};
  const Eigen::Isometry3d A = t.flange_pose({0.0});
  // Rx(90) Tx(0.2) Rz(0) Tz(0.3): origin at (0.2, 0, 0) + Rx(90)*(0,0,0.3) = (0.2, -0.3, 0).
  EXPECT_NEAR((A.translation() - Eigen::Vector3d(0.2, -0.3, 0.0)).norm(), 0.0, 1e-12);
}

TEST(Kinematics, PrismaticJointExtendsAlongZ) {
  RobotModel r;
  DhJoint j = revolute(0.1, 0, 0.2);
  j.type = JointType::Prismatic;
  j.min = 0.0;
  j.max = 0.5;
  r.joints = {j};
  EXPECT_NEAR((r.flange_pose({0.3}).translation() - Eigen::Vector3d(0.1, 0, 0.5)).norm(), 0, 1e-12);
  EXPECT_EQ(r.first_joint_out_of_limits({0.6}), 0);
  EXPECT_EQ(r.first_joint_out_of_limits({0.4}), -1);
}

TEST(Kinematics, Inchworm7StraightAndKneeBentByHand) {
  RobotModel r = robot_preset("inchworm7");
  ASSERT_EQ(r.dof(), 7);
  r.base.translation() = Eigen::Vector3d(1.0, 2.0, 0.0);
  // q = 0: all links stacked up: 0.15 + 0.55 + 0.55 + 0.15 + 0.06 (camera) = 1.46 m.
  const Eigen::Isometry3d S = r.camera_pose(std::vector<double>(7, 0.0));
  EXPECT_NEAR((S.translation() - Eigen::Vector3d(1.0, 2.0, 1.46)).norm(), 0.0, 1e-12);
  EXPECT_NEAR((S.linear() - Eigen::Matrix3d::Identity()).norm(), 0.0, 1e-12);
  // Knee +90 deg: T = Tz(0.70) Rx(-90) Rz(90) Rx(90) Tz(0.76). By hand Rx(-90)Rz(90)Rx(90) maps
  // x -> -z, y -> y, z -> x: the camera at (0.76, 0, 0.70) from the base, looking along +x.
  std::vector<double> q(7, 0.0);
  q[3] = kPi / 2;
  const Eigen::Isometry3d K = r.camera_pose(q);
  EXPECT_NEAR((K.translation() - Eigen::Vector3d(1.76, 2.0, 0.70)).norm(), 0.0, 1e-12);
  Eigen::Matrix3d R;
  R << 0, 0, 1,
       0, 1, 0,
      -1, 0, 0;
  EXPECT_NEAR((K.linear() - R).norm(), 0.0, 1e-12);
  // Foot roll +90 deg turns the whole bent arm about the vertical: camera to (0, 0.76) from base.
  q[0] = kPi / 2;
  EXPECT_NEAR((r.camera_pose(q).translation() - Eigen::Vector3d(1.0, 2.76, 0.70)).norm(), 0, 1e-12);
  EXPECT_EQ(r.joint_frames(q).size(), 8u);
  EXPECT_THROW(r.camera_pose({0.0, 0.0}), ParameterError);
}

TEST(Kinematics, RobotJsonRoundTripAndErrors) {
  RobotModel r = robot_preset("inchworm7");
  r.base.translation() = Eigen::Vector3d(-0.45, 0, 0);
  const RobotModel back = robot_from_json(robot_to_json(r), "d.json");
  std::vector<double> q{0.1, 0.5, -0.2, 1.1, 0.3, 0.4, -0.7};
  EXPECT_NEAR((back.camera_pose(q).matrix() - r.camera_pose(q).matrix()).norm(), 0.0, 1e-12);
  EXPECT_EQ(robot_from_json({{"preset", "inchworm7"}}, "d.json").dof(), 7);
  nlohmann::json bad = robot_to_json(r);
  bad["dh_convention"] = "sideways";
  try {
    robot_from_json(bad, "d.json");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("d.json: robot.dh_convention"), std::string::npos);
  }
  bad = robot_to_json(r);
  bad["joints"][2].erase("max_deg");
  EXPECT_THROW(robot_from_json(bad, "d.json"), InputError);
  bad = robot_to_json(r);
  bad["tool_to_camera"] = {2, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
  EXPECT_THROW(robot_from_json(bad, "d.json"), InputError);
  EXPECT_THROW(robot_from_json({{"preset", "octopus"}}, "d.json"), InputError);
}

TEST(Kinematics, IkReachesSimulatorPoses) {
  SimConfig c = SimConfig::from_preset("lab");
  c.arm_preset = "inchworm7";
  const TunnelSimulator sim(c);
  for (int i : {0, 12, 25}) {
    const SimArmState s = *sim.arm_state(i);
    EXPECT_LT(s.ik_error_m, 1e-4);
    EXPECT_LT((s.fk_pose.matrix() - s.true_pose.matrix()).norm(), 1e-12);  // no sag
    EXPECT_EQ(sim_robot(c, 0.0).first_joint_out_of_limits(s.joints), -1);
  }
}

TEST(Kinematics, SagDroopsAndGrowsWithReach) {
  RobotModel r = robot_preset("inchworm7");
  SagModel sag;
  sag.deg_per_m = 1.0;
  std::vector<double> near{0, 0.3, 0, 1.6, 0, 0.2, 0}, far{0, 0.9, 0, 0.6, 0, 0.1, 0};
  auto drop = [&](const std::vector<double>& q) {
    return r.camera_pose(q).translation().z() - sagged_camera_pose(r, q, sag).translation().z();
  };
  auto reach_h = [&](const std::vector<double>& q) {
    const Eigen::Vector3d d = r.camera_pose(q).translation() - r.joint_frames(q)[1].translation();
    return std::hypot(d.x(), d.y());
  };
  ASSERT_GT(reach_h(far), reach_h(near) + 0.2);
  EXPECT_GT(drop(near), 0.0);
  EXPECT_GT(drop(far), drop(near));
  // Small-angle check: drop = theta * horizontal reach, theta = 1 deg/m * reach_h.
  const double th = reach_h(far) * kPi / 180.0;
  EXPECT_NEAR(drop(far), th * reach_h(far), 0.1 * th * reach_h(far));
  sag.deg_per_m = 0.0;
  EXPECT_NEAR((sagged_camera_pose(r, far, sag).matrix() - r.camera_pose(far).matrix()).norm(), 0, 1e-15);
}

TEST(Kinematics, FramePosePrecedence) {
  Dataset d;
  d.json_path = "/x/dataset.json";
  RobotModel r = robot_preset("inchworm7");
  d.robot = robot_to_json(r);
  DatasetFrameRef f;
  f.joints = {0, 0, 0, kPi / 2, 0, 0, 0};
  d.frames.push_back(f);
  ResolvedPose p = resolve_frame_pose(d, 0);
  ASSERT_TRUE(p.pose);
  EXPECT_EQ(p.source, PoseSource::Kinematics);
  EXPECT_NEAR((p.pose->translation() - Eigen::Vector3d(0.76, 0, 0.70)).norm(), 0, 1e-12);
  // Explicit pose wins over joints, unless joints are preferred.
  d.frames[0].pose = Eigen::Isometry3d::Identity();
  EXPECT_EQ(resolve_frame_pose(d, 0).source, PoseSource::Explicit);
  EXPECT_EQ(resolve_frame_pose(d, 0, true).source, PoseSource::Kinematics);
  // A per-frame robot_base (the inchworm stepped) moves the chain.
  d.frames[0].pose.reset();
  d.frames[0].raw = {{"robot_base", {1, 0, 0, 2, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1}}};
  EXPECT_NEAR(resolve_frame_pose(d, 0).pose->translation().x(), 2.76, 1e-12);
  // Bad joints: wrong count, outside limits, no robot.
  d.frames[0].joints = {0, 0};
  EXPECT_THROW(resolve_frame_pose(d, 0), InputError);
  d.frames[0].joints = {0, 0, 0, 3.0, 0, 0, 0};  // knee limit 150 deg
  try {
    resolve_frame_pose(d, 0);
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("knee_pitch"), std::string::npos);
  }
  d.robot = nullptr;
  EXPECT_THROW(resolve_frame_pose(d, 0), InputError);
}
