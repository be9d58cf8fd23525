// The nav_msgs/Odometry an estimate is published as (sf_filter/io/estimate_messages.hpp):
// with TWIST_OUT the twist and its covariance block come from the state, every component the
// state does not hold has the variance 1e6; without it the whole twist is unknown (1e6), never
// a certain zero. Checked entry by entry against a hand-made state and covariance.
#include <array>
#include <cmath>
#include <optional>

#include <gtest/gtest.h>

#include "sf_filter/io/estimate_messages.hpp"

namespace {

struct Estimate {
  double time = 12.5;
  Eigen::VectorXd state;
  Eigen::MatrixXd covariance;
};

/// State (x, y, yaw, v, omega) = (1, 2, 0.5, 0.8, -0.3); covariance entry (r, c) = 10 r + c + 1
/// symmetrised, so that every entry names its position.
Estimate handMade() {
  Estimate e;
  e.state.resize(5);
  e.state << 1.0, 2.0, 0.5, 0.8, -0.3;
  e.covariance.resize(5, 5);
  for (int r = 0; r < 5; ++r)
    for (int c = 0; c < 5; ++c) e.covariance(r, c) = 10 * std::min(r, c) + std::max(r, c) + 1;
  return e;
}

TEST(OdometryTwist, FromTheStateWithTwistOut) {
  const Estimate e = handMade();
  const nav_msgs::Odometry odom =
      sf_filter::makeOdometry(e, {0, 1, 2}, "odom", "base_link", std::array<int, 2>{3, 4});
  EXPECT_EQ(odom.twist.twist.linear.x, 0.8);
  EXPECT_EQ(odom.twist.twist.angular.z, -0.3);
  EXPECT_EQ(odom.twist.twist.linear.y, 0.0);
  const auto& c = odom.twist.covariance;
  EXPECT_EQ(c[0], 34.0);          // P(3,3) = 10 * 3 + 3 + 1
  EXPECT_EQ(c[0 * 6 + 5], 35.0);  // P(3,4) = 10 * 3 + 4 + 1
  EXPECT_EQ(c[5 * 6 + 0], 35.0);  // P(4,3)
  EXPECT_EQ(c[35], 45.0);         // P(4,4) = 10 * 4 + 4 + 1
  for (int k : {1, 2, 3, 4}) EXPECT_EQ(c[static_cast<std::size_t>(k * 7)], 1e6) << k;
  // Off-diagonal entries of the unknown components stay 0 (uncorrelated).
  EXPECT_EQ(c[1], 0.0);
  EXPECT_EQ(c[1 * 6 + 5], 0.0);
  // The pose part is unchanged: (x, y, yaw) block, z, roll, pitch unknown.
  EXPECT_EQ(odom.pose.covariance[0], 1.0);
  EXPECT_EQ(odom.pose.covariance[1], 2.0);    // P(0,1) = 0 + 1 + 1
  EXPECT_EQ(odom.pose.covariance[35], 23.0);  // P(2,2) = 20 + 2 + 1
  EXPECT_EQ(odom.pose.covariance[14], 1e6);
  EXPECT_NEAR(odom.pose.pose.orientation.z, std::sin(0.25), 1e-15);
}

TEST(OdometryTwist, UnknownWithoutTwistOut) {
  const nav_msgs::Odometry odom = sf_filter::makeOdometry(handMade(), {0, 1, 2}, "odom", "base");
  EXPECT_EQ(odom.twist.twist.linear.x, 0.0);
  EXPECT_EQ(odom.twist.twist.angular.z, 0.0);
  for (int r = 0; r < 6; ++r)
    for (int c = 0; c < 6; ++c)
      EXPECT_EQ(odom.twist.covariance[static_cast<std::size_t>(r * 6 + c)], r == c ? 1e6 : 0.0);
}

}  // namespace
