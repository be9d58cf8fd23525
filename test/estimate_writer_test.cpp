// The one writer of a node's outputs (sf_filter/io/estimate_writer.hpp), used by the online node
// and the replay's output bag: which messages an estimate becomes, on which topics, in which
// order, and ACCEL_OUT's acceleration entry by entry against a hand-made state and covariance.
#include <cmath>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "sf_filter/io/estimate_writer.hpp"
#include "writer_recorder.hpp"

namespace {

using sf_test::Estimate;

/// State (x, y, yaw, v, omega, a) = (1, 2, 0.5, 0.8, -0.3, 0.25); covariance entry (r, c) =
/// 10 min(r, c) + max(r, c) + 1, so that every entry names its position.
Estimate handMade() {
  Estimate e;
  e.time = 12.5;
  e.state.resize(6);
  e.state << 1.0, 2.0, 0.5, 0.8, -0.3, 0.25;
  e.covariance.resize(6, 6);
  for (int r = 0; r < 6; ++r)
    for (int c = 0; c < 6; ++c) e.covariance(r, c) = 10 * std::min(r, c) + std::max(r, c) + 1;
  return e;
}

sf_filter::NodeDescription description(bool accel) {
  sf_filter::NodeDescription d;
  d.method = "KALMAN_FILTER";
  d.outputs = {{"speed", 3}, {"/heading", 2}};
  d.pose = std::array<int, 3>{0, 1, 2};
  d.twist = std::array<int, 2>{3, 4};
  if (accel) d.accel = 5;
  return d;
}

using Recorder =
    sf_test::WriterRecorder<geometry_msgs::AccelWithCovarianceStamped, nav_msgs::Odometry>;

TEST(EstimateWriter, DeclaresEveryOutputInWriteOrder) {
  const sf_filter::EstimateWriter writer(description(true), {"odom", "base_link"});
  Recorder r;
  writer.declare(r);
  EXPECT_EQ(r.declared, (std::vector<std::string>{"0 speed", "1 /heading", "2 state private",
                                                  "3 odometry/filtered", "4 accel/filtered"}));
  writer.write(handMade(), true, r);
  EXPECT_EQ(r.written, (std::vector<std::string>{"0 speed", "1 /heading", "2 state",
                                                 "3 odometry/filtered", "4 accel/filtered"}));
}

TEST(EstimateWriter, AccelerationFromTheState) {
  const sf_filter::EstimateWriter writer(description(true), {"odom", "base_link"});
  Recorder r;
  writer.write(handMade(), true, r);
  ASSERT_EQ(r.of<geometry_msgs::AccelWithCovarianceStamped>().size(), 1u);
  const geometry_msgs::AccelWithCovarianceStamped& a =
      r.of<geometry_msgs::AccelWithCovarianceStamped>()[0];
  EXPECT_EQ(a.header.stamp, ros::Time(12.5));
  EXPECT_EQ(a.header.frame_id, "base_link");  // the robot's frame, as robot_localization's
  EXPECT_EQ(a.accel.accel.linear.x, 0.25);
  EXPECT_EQ(a.accel.accel.linear.y, 0.0);
  EXPECT_EQ(a.accel.accel.angular.z, 0.0);
  EXPECT_EQ(a.accel.covariance[0], 56.0);  // P(5,5) = 10 * 5 + 5 + 1
  for (int k : {1, 2, 3, 4, 5}) EXPECT_EQ(a.accel.covariance[static_cast<std::size_t>(k * 7)], 1e6);
  EXPECT_EQ(a.accel.covariance[1], 0.0);  // unknown components uncorrelated
  EXPECT_EQ(a.accel.covariance[6], 0.0);
  // The odometry of the same estimate is the one makeOdometry builds.
  ASSERT_EQ(r.of<nav_msgs::Odometry>().size(), 1u);
  EXPECT_EQ(r.of<nav_msgs::Odometry>()[0].twist.twist.linear.x, 0.8);
  EXPECT_EQ(r.of<nav_msgs::Odometry>()[0].child_frame_id, "base_link");
}

TEST(EstimateWriter, NoMotionBeforeAMeasurementNoAccelerationWithoutAccelOut) {
  Recorder before;
  sf_filter::EstimateWriter(description(true), {}).write(handMade(), false, before);
  EXPECT_EQ(before.written, (std::vector<std::string>{"0 speed", "1 /heading", "2 state"}));
  Recorder without;
  const sf_filter::EstimateWriter plain(description(false), {});
  plain.write(handMade(), true, without);
  EXPECT_TRUE(without.of<geometry_msgs::AccelWithCovarianceStamped>().empty());
  EXPECT_EQ(without.written.back(), "3 odometry/filtered");
  plain.declare(without);
  EXPECT_EQ(without.declared.back(), "3 odometry/filtered");
}

}  // namespace
