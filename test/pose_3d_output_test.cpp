// POSE_OUT_3D and TWIST_OUT_3D's messages (sf_filter/io/pose_3d_messages.hpp) through the one
// writer of the node and the replay (io/estimate_writer.hpp), against a hand-made estimate of
// config/imu_odometry_3d.h's layout: the position, the quaternion, the 6x6 pose and twist
// covariance blocks entry by entry, the Euler angles of known rotations against hand values,
// and the orientation block's axes (the state's error about the odom frame's fixed axes).
#include <cmath>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <sf_estimation/manifold/so3_world_block.hpp>

#include "sf_filter/io/estimate_writer.hpp"
#include "writer_recorder.hpp"

namespace {

using sf_test::Estimate;

/// The quaternion (w, x, y, z) of roll, pitch, yaw (Z-Y-X), written out by hand.
std::array<double, 4> quaternionOf(double roll, double pitch, double yaw) {
  const double cr = std::cos(roll / 2), sr = std::sin(roll / 2);
  const double cp = std::cos(pitch / 2), sp = std::sin(pitch / 2);
  const double cy = std::cos(yaw / 2), sy = std::sin(yaw / 2);
  return {cr * cp * cy + sr * sp * sy, sr * cp * cy - cr * sp * sy, cr * sp * cy + sr * cp * sy,
          cr * cp * sy - sr * sp * cy};
}

/// P(r, c) = 100 min(r, c) + max(r, c) + 1, so that every entry names its position; the
/// quaternion's w row and column (3) zero, as the node's n x n covariance has them.
double entry(int r, int c) {
  return (r == 3 || c == 3) ? 0.0 : 100 * std::min(r, c) + std::max(r, c) + 1;
}

/// imu_odometry_3d.h's state: p x[0..2] = (1, 2, 3), q x[3..6] (roll 0.1, pitch -0.2, yaw
/// 0.3), v x[7..9], omega x[10..12], a x[13..15].
Estimate handMade(double roll = 0.1, double pitch = -0.2, double yaw = 0.3) {
  Estimate e;
  e.time = 7.25;
  e.state.resize(16);
  const auto q = quaternionOf(roll, pitch, yaw);
  e.state << 1, 2, 3, q[0], q[1], q[2], q[3], 0.5, -0.25, 0.125, 0.01, -0.02, 0.03, 0, 0, 0;
  e.covariance.resize(16, 16);
  for (int r = 0; r < 16; ++r)
    for (int c = 0; c < 16; ++c) e.covariance(r, c) = entry(r, c);
  return e;
}

sf_filter::NodeDescription description(bool position, bool twist) {
  sf_filter::NodeDescription d;
  d.method = "EXTENDED_KALMAN_FILTER";
  d.outputs = {{"fused/position/z", 2}};
  d.pose3d = sf_filter::Pose3dIndices{{0, 1, 2}, 3};
  if (!position) d.pose3d->position = {-1, -1, -1};
  if (twist) d.twist3d = std::array<int, 6>{7, 8, 9, 10, 11, 12};
  return d;
}

using Recorder = sf_test::WriterRecorder<nav_msgs::Odometry, geometry_msgs::Vector3Stamped>;

Recorder written(const sf_filter::NodeDescription& d, const Estimate& e, bool measured = true) {
  Recorder r;
  sf_filter::EstimateWriter(d, {"odom", "base_link"}).write(e, measured, r);
  return r;
}

TEST(Pose3dOutput, OdometryAndEulerInWriteOrder) {
  const sf_filter::EstimateWriter writer(description(true, true), {"odom", "base_link"});
  Recorder r;
  writer.declare(r);
  writer.declareSmoothed(r);
  EXPECT_EQ(r.declared, (std::vector<std::string>{
                            "0 fused/position/z", "1 state private", "2 odometry/filtered",
                            "3 fused/euler", "4 state/smoothed private", "5 odometry/smoothed"}));
  writer.write(handMade(), true, r);
  EXPECT_EQ(r.written, (std::vector<std::string>{"0 fused/position/z", "1 state",
                                                 "2 odometry/filtered", "3 fused/euler"}));
  // No pose before a measured value, as the planar odometry.
  EXPECT_EQ(written(description(true, true), handMade(), false).written,
            (std::vector<std::string>{"0 fused/position/z", "1 state"}));
}

TEST(Pose3dOutput, PoseAndItsCovarianceFromTheState) {
  const Estimate e = handMade();
  const Recorder r = written(description(true, false), e);
  ASSERT_EQ(r.of<nav_msgs::Odometry>().size(), 1u);
  const nav_msgs::Odometry& o = r.of<nav_msgs::Odometry>()[0];
  EXPECT_EQ(o.header.frame_id, "odom");
  EXPECT_EQ(o.child_frame_id, "base_link");
  EXPECT_EQ(o.header.stamp, ros::Time(7.25));
  EXPECT_EQ(o.pose.pose.position.x, 1.0);
  EXPECT_EQ(o.pose.pose.position.y, 2.0);
  EXPECT_EQ(o.pose.pose.position.z, 3.0);
  EXPECT_EQ(o.pose.pose.orientation.w, e.state(3));
  EXPECT_EQ(o.pose.pose.orientation.x, e.state(4));
  EXPECT_EQ(o.pose.pose.orientation.y, e.state(5));
  EXPECT_EQ(o.pose.pose.orientation.z, e.state(6));
  // Rows x, y, z, rotation about x, y, z: the state's p and the quaternion's x, y, z rows.
  const std::array<int, 6> index = {0, 1, 2, 4, 5, 6};
  for (int r = 0; r < 6; ++r)
    for (int c = 0; c < 6; ++c)
      EXPECT_EQ(o.pose.covariance[static_cast<std::size_t>(r * 6 + c)], entry(index[r], index[c]))
          << r << ", " << c;
  EXPECT_EQ(o.pose.covariance[3], 5.0);     // x with the rotation about x: P(0, 4)
  EXPECT_EQ(o.pose.covariance[35], 607.0);  // the rotation about z: P(6, 6)
  // Without TWIST_OUT_3D: a zero twist of unknown variance, uncorrelated.
  EXPECT_EQ(o.twist.twist.linear.x, 0.0);
  for (int k = 0; k < 36; ++k)
    EXPECT_EQ(o.twist.covariance[static_cast<std::size_t>(k)], k % 7 == 0 ? 1e6 : 0.0) << k;
}

TEST(Pose3dOutput, TwistAndItsCovarianceFromTheState) {
  const Recorder r = written(description(true, true), handMade());
  ASSERT_EQ(r.of<nav_msgs::Odometry>().size(), 1u);
  const auto& t = r.of<nav_msgs::Odometry>()[0].twist;
  EXPECT_EQ(t.twist.linear.x, 0.5);
  EXPECT_EQ(t.twist.linear.y, -0.25);
  EXPECT_EQ(t.twist.linear.z, 0.125);
  EXPECT_EQ(t.twist.angular.x, 0.01);
  EXPECT_EQ(t.twist.angular.y, -0.02);
  EXPECT_EQ(t.twist.angular.z, 0.03);
  for (int r = 0; r < 6; ++r)
    for (int c = 0; c < 6; ++c)
      EXPECT_EQ(t.covariance[static_cast<std::size_t>(r * 6 + c)], entry(7 + r, 7 + c));
  EXPECT_EQ(t.covariance[5], 713.0);  // v x with omega z: P(7, 12) = 700 + 12 + 1
}

TEST(Pose3dOutput, OrientationOnlyMarksThePositionUnknown) {
  const Recorder r = written(description(false, false), handMade());
  ASSERT_EQ(r.of<nav_msgs::Odometry>().size(), 1u);
  const nav_msgs::Odometry& o = r.of<nav_msgs::Odometry>()[0];
  EXPECT_EQ(o.pose.pose.position.x, 0.0);
  EXPECT_EQ(o.pose.pose.position.z, 0.0);
  for (int r = 0; r < 6; ++r) {
    for (int c = 0; c < 6; ++c) {
      const double expected = (r >= 3 && c >= 3) ? entry(r + 1, c + 1) : (r == c ? 1e6 : 0.0);
      EXPECT_EQ(o.pose.covariance[static_cast<std::size_t>(r * 6 + c)], expected) << r << c;
    }
  }
}

TEST(Pose3dOutput, EulerAnglesOfKnownRotations) {
  // roll, pitch, yaw: small, a yaw past pi/2 and a negative one, a pitch near the limit.
  for (const std::array<double, 3> rpy :
       {std::array<double, 3>{0.1, -0.2, 0.3}, std::array<double, 3>{-0.4, 0.3, 2.5},
        std::array<double, 3>{2.0, 1.2, -3.0}}) {
    const Recorder r = written(description(true, false), handMade(rpy[0], rpy[1], rpy[2]));
    ASSERT_EQ(r.of<geometry_msgs::Vector3Stamped>().size(), 1u);
    const geometry_msgs::Vector3Stamped& m = r.of<geometry_msgs::Vector3Stamped>()[0];
    EXPECT_EQ(m.header.frame_id, "odom");
    EXPECT_EQ(m.header.stamp, ros::Time(7.25));
    EXPECT_NEAR(m.vector.x, rpy[0], 1e-12);
    EXPECT_NEAR(m.vector.y, rpy[1], 1e-12);
    EXPECT_NEAR(m.vector.z, rpy[2], 1e-12);
  }
}

TEST(Pose3dOutput, OrientationErrorIsAboutTheOdomFramesAxes) {
  // nav_msgs/Odometry's orientation block is about the fixed axes of header.frame_id: a
  // rotation error about its z moves the yaw alone, whatever the roll and pitch. The state's
  // error (So3WorldBlock's [+]) is that rotation: its third tangent row is the yaw's.
  const Estimate e = handMade(0.4, -0.3, 1.0);
  Eigen::Matrix<double, 4, 1> turned;
  estimation::manifold::So3WorldBlock::plus(e.state.segment<4>(3), Eigen::Vector3d(0.0, 0.0, 0.05),
                                            turned);
  Estimate f = e;
  f.state.segment<4>(3) = turned;
  const auto euler =
      written(description(true, false), f).of<geometry_msgs::Vector3Stamped>().at(0).vector;
  EXPECT_NEAR(euler.x, 0.4, 1e-12);
  EXPECT_NEAR(euler.y, -0.3, 1e-12);
  EXPECT_NEAR(euler.z, 1.05, 1e-12);
}

}  // namespace
