// An IMU topic's accelerometer as each frame's gravity: the mean of the samples near the stamp,
// turned round, and nothing when the robot was not still; decoded from CDR and from a real ROS 1
// recording (a walking backpack).
#include "core/recordings/imu_gravity.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "core/recordings/byte_cursor.h"
#include "core/recordings/recording.h"
#include "core/recordings/ros_messages.h"
#include "tests/core/recordings/recordings_fixture.h"
#include "tests/support/cdr_writer.h"

namespace tunnelmap {
namespace {

using recordings::ImuGravityTrack;
constexpr std::int64_t kMs = 1'000'000;
constexpr double kG = 9.80665;

double angle_deg(const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  return std::acos(std::clamp(a.normalized().dot(b.normalized()), -1.0, 1.0)) * 180.0 / M_PI;
}

TEST(ImuGravityTrack, TheMeanOfTheSamplesNearTheStampTurnedRoundIsWhereThingsFall) {
  const Eigen::Vector3d falling = Eigen::Vector3d(0.1, 0.9, -0.2).normalized();
  std::mt19937 rng(3);
  std::normal_distribution<double> noise(0.0, 0.05);  // m/s², a consumer accelerometer at 200 Hz
  ImuGravityTrack track;
  for (std::int64_t t = 0; t <= 1000 * kMs; t += 5 * kMs) {
    Eigen::Vector3d n;
    for (int k = 0; k < 3; ++k) n[k] = noise(rng);  // in order: arguments' order is the compiler's
    track.add(t, -kG * falling + n);
  }
  for (std::int64_t stamp : {100 * kMs, 433 * kMs, 900 * kMs}) {
    const auto g = track.falling_at(stamp);
    ASSERT_TRUE(g.has_value()) << stamp;
    EXPECT_NEAR(g->norm(), 1.0, 1e-12);
    // 11 samples: the mean's noise is 0.05/sqrt(11) m/s² on each axis across gravity, 0.088
    // degrees; the angle, over two axes, exceeds 0.38 degrees once in ten thousand.
    EXPECT_LT(angle_deg(*g, falling), 0.38) << stamp;
  }
  EXPECT_FALSE(track.falling_at(1100 * kMs).has_value());  // no sample within 25 ms
  EXPECT_FALSE(track.falling_at(-40 * kMs).has_value());
}

TEST(ImuGravityTrack, OnlyTheSamplesWithinTheWindowCount) {
  ImuGravityTrack track;
  track.add(0, Eigen::Vector3d(0, 0, kG));          // at rest, z up
  track.add(200 * kMs, Eigen::Vector3d(kG, 0, 0));  // tipped over 0.2 s later
  EXPECT_LT(angle_deg(*track.falling_at(10 * kMs), -Eigen::Vector3d::UnitZ()), 1e-9);
  EXPECT_LT(angle_deg(*track.falling_at(190 * kMs), -Eigen::Vector3d::UnitX()), 1e-9);
  EXPECT_FALSE(track.falling_at(100 * kMs).has_value());
}

TEST(ImuGravityTrack, SamplesOutOfOrderAreAveragedAsInOrder) {
  ImuGravityTrack in_order, shuffled;
  const std::vector<std::pair<std::int64_t, Eigen::Vector3d>> samples = {
      {0, {0.3, 0, kG}}, {7 * kMs, {-0.3, 0, kG}}, {12 * kMs, {0, 0.2, kG}}, {21 * kMs, {0, -0.2, kG}}};
  for (const auto& [t, a] : samples) in_order.add(t, a);
  for (int i : {2, 0, 3, 1}) shuffled.add(samples[i].first, samples[i].second);
  EXPECT_LT(angle_deg(*shuffled.falling_at(10 * kMs), *in_order.falling_at(10 * kMs)), 1e-9);
  EXPECT_LT(angle_deg(*in_order.falling_at(10 * kMs), -Eigen::Vector3d::UnitZ()), 1e-9);
}

TEST(ImuGravityTrack, AMeanThatIsNotGravitysLengthIsNoGravity) {
  for (const double length : {kG + 0.8, kG - 0.8, 1.0 /* in g, not m/s² */, 0.0 /* a gyro-only topic's zeros */}) {
    ImuGravityTrack track;
    track.add(0, Eigen::Vector3d(0, 0, length));
    EXPECT_FALSE(track.falling_at(0).has_value()) << length;
  }
  ImuGravityTrack still;
  still.add(0, Eigen::Vector3d(0, 0, kG + 0.3));  // within the tolerance: gravity
  EXPECT_TRUE(still.falling_at(0).has_value());
}

TEST(ImuMessages, CdrImuDecodesItsAccelerometerAndAGyroOnlyMessageHasNone) {
  const Eigen::Vector3d a(0.25, -9.7, 1.5);
  const std::vector<std::uint8_t> with = testing::cdr_imu(1'700'000'000'123'000'000LL, "imu_link", a);
  const recordings::RosImu imu =
      recordings::decode_imu(recordings::MessageView{"/imu", 0, with.data(), with.size()}, recordings::MessageEncoding::Cdr);
  EXPECT_EQ(imu.header.frame_id, "imu_link");
  EXPECT_EQ(imu.header.stamp_ns, 1'700'000'000'123'000'000LL);
  ASSERT_TRUE(imu.linear_acceleration.has_value());
  EXPECT_EQ(*imu.linear_acceleration, a);
  const std::vector<std::uint8_t> gyro_only = testing::cdr_imu(0, "imu_link", a, false);
  EXPECT_FALSE(recordings::decode_imu(recordings::MessageView{"/imu", 0, gyro_only.data(), gyro_only.size()},
                                      recordings::MessageEncoding::Cdr)
                   .linear_acceleration.has_value());
  const std::vector<std::uint8_t> cut(with.begin(), with.end() - 8);
  EXPECT_THROW(recordings::decode_imu(recordings::MessageView{"/imu", 0, cut.data(), cut.size()},
                                      recordings::MessageEncoding::Cdr),
               recordings::TruncatedData);
}

// A backpack carried through a museum (Cartographer's test bag): 1243 samples over 6.3 s. The
// IMU's z points up; the carrier's gait tilts it and shakes it.
TEST(ImuMessages, ARealWalkingRecordingGivesGravityNearItsUpAndRefusesTheJolts) {
  SKIP_WITHOUT_RECORDINGS();
  const auto rec = recordings::open_recording(testing::recording("ros1_bag/cartographer_b0-2014-07-21-12-42-53-tiny.bag"));
  ImuGravityTrack track;
  std::int64_t first = 0, last = 0;
  std::size_t samples = 0;
  rec->read_messages({"imu"}, [&](const recordings::MessageView& m) {
    const recordings::RosImu imu = recordings::decode_imu(m, rec->summary().encoding);
    EXPECT_EQ(imu.header.frame_id, "imu_link");
    if (!imu.linear_acceleration) return true;
    if (samples++ == 0) first = imu.header.stamp_ns;
    last = imu.header.stamp_ns;
    track.add(imu.header.stamp_ns, *imu.linear_acceleration);
    return true;
  });
  EXPECT_EQ(samples, 1243u);
  std::size_t asked = 0, given = 0;
  double worst_tilt_deg = 0.0;
  for (std::int64_t t = first; t <= last; t += 100 * kMs) {
    ++asked;
    if (const auto g = track.falling_at(t)) {
      ++given;
      worst_tilt_deg = std::max(worst_tilt_deg, angle_deg(*g, -Eigen::Vector3d::UnitZ()));
    }
  }
  EXPECT_EQ(asked, 63u);
  EXPECT_GE(given, 55u);       // measured: 60; the rest are jolts of the gait
  EXPECT_LT(given, asked);     // and some are refused
  EXPECT_LT(worst_tilt_deg, 15.0);  // measured: 11.3 degrees, the backpack's sway
}

}  // namespace
}  // namespace tunnelmap
