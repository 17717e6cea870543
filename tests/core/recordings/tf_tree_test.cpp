// The TF tree of the rosbag.js turtlesim recordings gives back the bag's own transforms,
// composes /tf_static with /tf, and interpolates between samples.
#include <gtest/gtest.h>

#include "core/recordings/recording.h"
#include "core/recordings/ros_messages.h"
#include "core/recordings/tf_tree.h"
#include "tests/core/recordings/recordings_fixture.h"

namespace tunnelmap {
namespace {

using namespace recordings;

struct TurtleTf {
  TfTree tree;
  std::vector<RosTransform> dynamic;  // every /tf transform, as recorded
  RosTransform carrot;                // the /tf_static one
};

TurtleTf read_turtles(const std::string& file) {
  TurtleTf out;
  const auto rec = open_recording(testing::recording(file));
  rec->read_messages({"/tf", "/tf_static"}, [&](const MessageView& m) {
    const bool is_static = m.topic == "/tf_static";
    for (const RosTransform& t : decode_tf_message(m, MessageEncoding::Ros1)) {
      out.tree.add(t, is_static);
      (is_static ? out.carrot : out.dynamic.emplace_back()) = t;
    }
    return true;
  });
  return out;
}

TEST(TfTree, TurtlesimTransformsAreTheBagsOwn) {
  SKIP_WITHOUT_RECORDINGS();
  for (const char* file : {"ros1_bag/rosbagjs_example.bag", "ros1_bag/rosbagjs_example-lz4.bag"}) {
    SCOPED_TRACE(file);
    const TurtleTf tf = read_turtles(file);
    ASSERT_EQ(tf.dynamic.size(), 2688u);
    std::size_t checked = 0;
    for (const RosTransform& t : tf.dynamic) {
      const auto got = tf.tree.lookup(t.header.frame_id, t.child_frame_id, t.header.stamp_ns);
      ASSERT_TRUE(got.has_value()) << t.child_frame_id << " at " << t.header.stamp_ns;
      EXPECT_LT((got->matrix() - t.transform.matrix()).cwiseAbs().maxCoeff(), 1e-12);
      ++checked;
    }
    EXPECT_EQ(checked, 2688u);
  }
}

TEST(TfTree, StaticCarrotComposesWithTheTurtle) {
  SKIP_WITHOUT_RECORDINGS();
  const TurtleTf tf = read_turtles("ros1_bag/rosbagjs_example.bag");
  ASSERT_EQ(tf.carrot.header.frame_id, "turtle1");
  ASSERT_EQ(tf.carrot.child_frame_id, "carrot");
  std::size_t checked = 0;
  for (const RosTransform& t : tf.dynamic) {
    if (t.child_frame_id != "turtle1") continue;
    const auto world_carrot = tf.tree.lookup("world", "carrot", t.header.stamp_ns);
    ASSERT_TRUE(world_carrot.has_value());
    const Eigen::Isometry3d expected = t.transform * tf.carrot.transform;
    EXPECT_LT((world_carrot->matrix() - expected.matrix()).cwiseAbs().maxCoeff(), 1e-12);
    ++checked;
  }
  EXPECT_GT(checked, 1000u);
  EXPECT_FALSE(tf.tree.lookup("world", "no_such_frame", tf.dynamic.front().header.stamp_ns).has_value());
}

TEST(TfTree, InterpolatesBetweenSamplesAndRefusesToExtrapolate) {
  RosTransform a, b;
  a.header.frame_id = b.header.frame_id = "odom";
  a.child_frame_id = b.child_frame_id = "camera";
  a.header.stamp_ns = 1000;
  b.header.stamp_ns = 3000;
  a.transform = Eigen::Translation3d(0, 0, 0) * Eigen::AngleAxisd(0.0, Eigen::Vector3d::UnitZ());
  b.transform = Eigen::Translation3d(2, 4, 0) * Eigen::AngleAxisd(1.0, Eigen::Vector3d::UnitZ());
  TfTree tree;
  tree.add(b, false);  // out of order on purpose
  tree.add(a, false);
  const auto mid = tree.lookup("odom", "camera", 2000);
  ASSERT_TRUE(mid.has_value());
  EXPECT_NEAR(mid->translation().x(), 1.0, 1e-12);
  EXPECT_NEAR(mid->translation().y(), 2.0, 1e-12);
  EXPECT_NEAR(Eigen::AngleAxisd(mid->rotation()).angle(), 0.5, 1e-12);  // slerp halfway
  EXPECT_FALSE(tree.lookup("odom", "camera", 3001).has_value());
  EXPECT_TRUE(tree.lookup("odom", "camera", 3001, 5).has_value());  // within the tolerance
  const auto inverse = tree.lookup("camera", "odom", 3000);
  ASSERT_TRUE(inverse.has_value());
  EXPECT_LT((inverse->matrix() - b.transform.inverse().matrix()).cwiseAbs().maxCoeff(), 1e-12);
}

}  // namespace
}  // namespace tunnelmap
