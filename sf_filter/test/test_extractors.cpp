// Input extractors (sf_filter/config/extractors): quaternion to roll, pitch and yaw against
// closed forms (the +-pi seam, gimbal lock), differential poses against hand-integrated paths,
// covariance entries with ROS's "unknown" conventions.
#include <array>
#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "sf_filter/config/extractors/message_covariance.hpp"
#include "sf_filter/config/extractors/pose_difference.hpp"
#include "sf_filter/config/extractors/quaternion_angles.hpp"

namespace {

using sf_config::extractors::absoluteValue;
using sf_config::extractors::covarianceEntry;
using sf_config::extractors::differentialSample;
using sf_config::extractors::eulerAngles;
using sf_config::extractors::Pose;
using sf_config::extractors::PoseMemory;
using sf_config::extractors::PoseQuantity;
using sf_config::extractors::Quaternion;
using sf_config::extractors::Sample;

constexpr double kTol = 1e-12;

/// Rz(yaw) Ry(pitch) Rx(roll) as a quaternion, by the closed form of the half angles.
Quaternion fromEuler(double roll, double pitch, double yaw) {
  const double cr = std::cos(roll / 2), sr = std::sin(roll / 2);
  const double cp = std::cos(pitch / 2), sp = std::sin(pitch / 2);
  const double cy = std::cos(yaw / 2), sy = std::sin(yaw / 2);
  return {sr * cp * cy - cr * sp * sy, cr * sp * cy + sr * cp * sy, cr * cp * sy - sr * sp * cy,
          cr * cp * cy + sr * sp * sy};
}

Quaternion aboutZ(double yaw) { return {0.0, 0.0, std::sin(yaw / 2), std::cos(yaw / 2)}; }

Pose planarPose(double x, double y, double yaw) {
  Pose p;
  p.position[0] = x;
  p.position[1] = y;
  p.orientation = aboutZ(yaw);
  return p;
}

TEST(QuaternionAngles, YawAboutZClosedForm) {
  // q = (0, 0, sin(psi/2), cos(psi/2)) has yaw psi, roll and pitch 0.
  for (double psi : {0.0, 0.1, -0.7, 1.5, 2.0, -2.5, 3.0, -3.1}) {
    const auto a = eulerAngles(aboutZ(psi));
    EXPECT_NEAR(a.yaw, psi, kTol) << psi;
    EXPECT_NEAR(a.roll, 0.0, kTol);
    EXPECT_NEAR(a.pitch, 0.0, kTol);
  }
}

TEST(QuaternionAngles, YawAtThePiSeam) {
  // Yaw pi: q = (0, 0, 1, 0), and -q the same rotation: both give +pi ((-pi, pi]).
  EXPECT_NEAR(eulerAngles({0, 0, 1, 0}).yaw, M_PI, kTol);
  EXPECT_NEAR(eulerAngles({0, 0, -1, 0}).yaw, M_PI, kTol);
  EXPECT_GT(eulerAngles({0, 0, 1, 0}).yaw, 0.0);
  // Just either side of the seam: pi - e and -pi + e (q for 2 pi - e is -q of -e... the sign of
  // q must not matter).
  const double e = 1e-6;
  EXPECT_NEAR(eulerAngles(aboutZ(M_PI - e)).yaw, M_PI - e, 1e-12);
  EXPECT_NEAR(eulerAngles(aboutZ(M_PI + e)).yaw, -M_PI + e, 1e-12);
  EXPECT_NEAR(eulerAngles(aboutZ(-M_PI - e)).yaw, M_PI - e, 1e-12);
  const Quaternion q = aboutZ(2.5);
  EXPECT_NEAR(eulerAngles({-q.x, -q.y, -q.z, -q.w}).yaw, 2.5, kTol);
}

TEST(QuaternionAngles, NotNormalizedIsNormalized) {
  const Quaternion q = fromEuler(0.2, -0.3, 1.1);
  const auto a = eulerAngles({3 * q.x, 3 * q.y, 3 * q.z, 3 * q.w});
  EXPECT_NEAR(a.roll, 0.2, kTol);
  EXPECT_NEAR(a.pitch, -0.3, kTol);
  EXPECT_NEAR(a.yaw, 1.1, kTol);
}

TEST(QuaternionAngles, ZeroOrNonFiniteIsNaN) {
  EXPECT_TRUE(std::isnan(eulerAngles({0, 0, 0, 0}).yaw));
  EXPECT_TRUE(std::isnan(eulerAngles({0, 0, NAN, 1}).roll));
  EXPECT_TRUE(std::isnan(eulerAngles({0, INFINITY, 0, 1}).pitch));
}

TEST(QuaternionAngles, RollPitchYawRoundTrip) {
  for (double roll : {-3.0, -1.0, 0.0, 0.4, 2.9})
    for (double pitch : {-1.5, -0.6, 0.0, 0.3, 1.5})
      for (double yaw : {-3.1, -2.0, 0.0, 0.5, 3.1}) {
        const auto a = eulerAngles(fromEuler(roll, pitch, yaw));
        EXPECT_NEAR(a.roll, roll, 1e-9) << roll << " " << pitch << " " << yaw;
        EXPECT_NEAR(a.pitch, pitch, 1e-9);
        EXPECT_NEAR(a.yaw, yaw, 1e-9);
      }
}

TEST(QuaternionAngles, RollAndPitchAloneClosedForm) {
  // About x by phi: (sin(phi/2), 0, 0, cos(phi/2)); about y by theta: (0, sin(theta/2), 0, ...).
  const auto r = eulerAngles({std::sin(0.35), 0, 0, std::cos(0.35)});
  EXPECT_NEAR(r.roll, 0.7, kTol);
  EXPECT_NEAR(r.pitch, 0.0, kTol);
  EXPECT_NEAR(r.yaw, 0.0, kTol);
  const auto p = eulerAngles({0, std::sin(-0.4), 0, std::cos(-0.4)});
  EXPECT_NEAR(p.pitch, -0.8, kTol);
  EXPECT_NEAR(p.roll, 0.0, kTol);
  EXPECT_NEAR(p.yaw, 0.0, kTol);
  // Roll pi (upside down): +pi, not -pi.
  EXPECT_NEAR(eulerAngles({1, 0, 0, 0}).roll, M_PI, kTol);
}

TEST(QuaternionAngles, GimbalLockGivesTheAngleToYaw) {
  // Pitch +pi/2: R = Rz(psi) Ry(pi/2) Rx(phi) depends on psi - phi only; pitch -pi/2 on
  // psi + phi. The extractor reports roll 0 and that angle as yaw.
  const auto up = eulerAngles(fromEuler(0.1, M_PI / 2, 0.3));
  EXPECT_NEAR(up.pitch, M_PI / 2, kTol);
  EXPECT_EQ(up.roll, 0.0);
  EXPECT_NEAR(up.yaw, 0.3 - 0.1, 1e-9);
  const auto down = eulerAngles(fromEuler(0.1, -M_PI / 2, 0.3));
  EXPECT_NEAR(down.pitch, -M_PI / 2, kTol);
  EXPECT_EQ(down.roll, 0.0);
  EXPECT_NEAR(down.yaw, 0.3 + 0.1, 1e-9);
  // Pure pitch +-pi/2: (0, +-sin(pi/4), 0, cos(pi/4)).
  const auto pure = eulerAngles({0, std::sqrt(0.5), 0, std::sqrt(0.5)});
  EXPECT_NEAR(pure.pitch, M_PI / 2, kTol);
  EXPECT_NEAR(pure.yaw, 0.0, kTol);
  EXPECT_EQ(pure.roll, 0.0);
  // At the seam of the combined angle: psi - phi = pi.
  const auto seam = eulerAngles(fromEuler(-1.5, M_PI / 2, M_PI - 1.5));
  EXPECT_NEAR(std::abs(seam.yaw), M_PI, 1e-9);
  EXPECT_GT(seam.yaw, 0.0);
  // Close to the lock but outside the tolerance the three angles are still recovered.
  const auto near = eulerAngles(fromEuler(0.1, M_PI / 2 - 1e-3, 0.3));
  EXPECT_NEAR(near.pitch, M_PI / 2 - 1e-3, 1e-9);
  EXPECT_NEAR(near.roll, 0.1, 1e-6);
  EXPECT_NEAR(near.yaw, 0.3, 1e-6);
}

TEST(PoseDifference, AbsoluteValues) {
  Pose p = planarPose(1.5, -2.0, 0.4);
  p.position[2] = 0.25;
  EXPECT_EQ(absoluteValue(PoseQuantity::X, p), 1.5);
  EXPECT_EQ(absoluteValue(PoseQuantity::Y, p), -2.0);
  EXPECT_EQ(absoluteValue(PoseQuantity::Z, p), 0.25);
  EXPECT_NEAR(absoluteValue(PoseQuantity::Yaw, p), 0.4, kTol);
  EXPECT_NEAR(absoluteValue(PoseQuantity::Roll, p), 0.0, kTol);
}

TEST(PoseDifference, HandIntegratedPlanarPath) {
  // A robot drives with forward steps s_k and turns w_k; its pose is integrated by hand:
  //   x += s cos(yaw), y += s sin(yaw), then yaw += w.
  // The differential X must give back s_k, Y zero (no sideways motion), YAW w_k (wrapped), and
  // the variance the sum of the two messages'.
  const double steps[] = {0.5, 0.2, 1.0, 0.3, 0.7};
  const double turns[] = {0.3, 1.2, 2.0, -2.9, 0.1};  // crosses the +-pi seam
  double x = 10.0, y = -4.0, yaw = 2.8;
  PoseMemory mx, my, myaw;
  const double variances[] = {0.01, 0.02, 0.04, 0.08, 0.16, 0.32};
  EXPECT_FALSE(differentialSample(PoseQuantity::X, planarPose(x, y, yaw), variances[0], 0.0, mx));
  EXPECT_FALSE(differentialSample(PoseQuantity::Y, planarPose(x, y, yaw), variances[0], 0.0, my));
  EXPECT_FALSE(
      differentialSample(PoseQuantity::Yaw, planarPose(x, y, yaw), variances[0], 0.0, myaw));
  for (int k = 0; k < 5; ++k) {
    x += steps[k] * std::cos(yaw);
    y += steps[k] * std::sin(yaw);
    yaw += turns[k];  // not wrapped: the quaternion does not care
    const Pose p = planarPose(x, y, yaw);
    const double stamp = 0.1 * (k + 1);
    const auto sx = differentialSample(PoseQuantity::X, p, variances[k + 1], stamp, mx);
    const auto sy = differentialSample(PoseQuantity::Y, p, variances[k + 1], stamp, my);
    const auto syaw = differentialSample(PoseQuantity::Yaw, p, variances[k + 1], stamp, myaw);
    ASSERT_TRUE(sx && sy && syaw);
    EXPECT_NEAR(sx->value, steps[k], 1e-12) << k;
    EXPECT_NEAR(sy->value, 0.0, 1e-12) << k;
    EXPECT_NEAR(syaw->value, turns[k], 1e-12) << k;
    ASSERT_TRUE(sx->variance);
    EXPECT_DOUBLE_EQ(*sx->variance, variances[k] + variances[k + 1]);
  }
}

TEST(PoseDifference, SidewaysStepInThePreviousFrame) {
  // Facing +y (yaw pi/2), a world step of (-1, 0) is 1 m to the robot's left: X 0, Y +1.
  PoseMemory mx, my;
  differentialSample(PoseQuantity::X, planarPose(2, 3, M_PI / 2), std::nullopt, 1.0, mx);
  differentialSample(PoseQuantity::Y, planarPose(2, 3, M_PI / 2), std::nullopt, 1.0, my);
  const auto sx = differentialSample(PoseQuantity::X, planarPose(1, 3, 0.0), std::nullopt, 2.0, mx);
  const auto sy = differentialSample(PoseQuantity::Y, planarPose(1, 3, 0.0), std::nullopt, 2.0, my);
  ASSERT_TRUE(sx && sy);
  EXPECT_NEAR(sx->value, 0.0, kTol);
  EXPECT_NEAR(sy->value, 1.0, kTol);
  EXPECT_FALSE(sx->variance);  // no variance from the messages: the header's R
}

TEST(PoseDifference, VarianceOnlyWhenBothMessagesHaveOne) {
  PoseMemory m;
  differentialSample(PoseQuantity::X, planarPose(0, 0, 0), std::nullopt, 1.0, m);
  auto s = differentialSample(PoseQuantity::X, planarPose(1, 0, 0), 0.5, 2.0, m);
  ASSERT_TRUE(s);
  EXPECT_FALSE(s->variance);
  s = differentialSample(PoseQuantity::X, planarPose(3, 0, 0), 0.25, 3.0, m);
  ASSERT_TRUE(s);
  EXPECT_NEAR(s->value, 2.0, kTol);
  EXPECT_DOUBLE_EQ(*s->variance, 0.75);
}

TEST(PoseDifference, StampNotAdvancingRestarts) {
  PoseMemory m;
  EXPECT_FALSE(differentialSample(PoseQuantity::X, planarPose(0, 0, 0), 0.1, 5.0, m));
  EXPECT_TRUE(differentialSample(PoseQuantity::X, planarPose(1, 0, 0), 0.1, 6.0, m));
  // The recording restarts at stamp 1 from another place: no jump of 99 m.
  EXPECT_FALSE(differentialSample(PoseQuantity::X, planarPose(100, 0, 0), 0.1, 1.0, m));
  EXPECT_FALSE(differentialSample(PoseQuantity::X, planarPose(100, 0, 0), 0.1, 1.0, m));
  const auto s = differentialSample(PoseQuantity::X, planarPose(100.5, 0, 0), 0.1, 1.5, m);
  ASSERT_TRUE(s);
  EXPECT_NEAR(s->value, 0.5, kTol);
  // Messages without a header (stamp NaN) difference every message.
  PoseMemory n;
  EXPECT_FALSE(differentialSample(PoseQuantity::X, planarPose(0, 0, 0), 0.1, NAN, n));
  EXPECT_TRUE(differentialSample(PoseQuantity::X, planarPose(1, 0, 0), 0.1, NAN, n));
}

TEST(PoseDifference, NonFinitePoseIsNaNAndKeepsThePrevious) {
  PoseMemory m;
  differentialSample(PoseQuantity::Yaw, planarPose(0, 0, 0.5), 0.1, 1.0, m);
  Pose bad = planarPose(0, 0, 0.7);
  bad.orientation = {0, 0, 0, 0};
  const auto s = differentialSample(PoseQuantity::Yaw, bad, 0.1, 2.0, m);
  ASSERT_TRUE(s);
  EXPECT_TRUE(std::isnan(s->value));
  const auto t = differentialSample(PoseQuantity::Yaw, planarPose(0, 0, 0.9), 0.1, 3.0, m);
  ASSERT_TRUE(t);
  EXPECT_NEAR(t->value, 0.4, kTol);
}

TEST(PoseDifference, ThreeDimensionalStepInThePreviousFrame) {
  // Pitched up by 90 deg (nose up: x axis along world +z), a world step of +z is forward.
  Pose p0;
  p0.orientation = {0, -std::sqrt(0.5), 0, std::sqrt(0.5)};  // pitch -pi/2: x along +z
  Pose p1 = p0;
  p1.position[2] = 2.0;
  PoseMemory m;
  differentialSample(PoseQuantity::X, p0, std::nullopt, 1.0, m);
  const auto s = differentialSample(PoseQuantity::X, p1, std::nullopt, 2.0, m);
  ASSERT_TRUE(s);
  EXPECT_NEAR(s->value, 2.0, kTol);
}

TEST(MessageCovariance, EntryOfAKnownCovariance) {
  double imu[9] = {0.1, 0, 0, 0, 0.2, 0, 0, 0, 0.3};
  EXPECT_EQ(*covarianceEntry(imu, 8), 0.3);
  std::array<double, 36> pose{};
  pose[0] = 0.5;
  pose[35] = 0.05;
  EXPECT_EQ(*covarianceEntry(pose, 35), 0.05);
  EXPECT_EQ(*covarianceEntry(pose, 1), 0.0);  // a zero entry of a known matrix is passed on
}

TEST(MessageCovariance, UnknownFallsBack) {
  double zero[9] = {};
  EXPECT_FALSE(covarianceEntry(zero, 8));
  double unknown[9] = {-1, 0, 0, 0, 0, 0, 0, 0, 0.3};
  EXPECT_FALSE(covarianceEntry(unknown, 8));
  EXPECT_FALSE(covarianceEntry(std::vector<double>{}, 0));
  EXPECT_FALSE(covarianceEntry(std::vector<double>{0.1, 0.2}, 2));  // too short
}

}  // namespace
