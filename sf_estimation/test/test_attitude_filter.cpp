// The IMU attitude filter (attitude_filter.hpp) on analytic cases: a constant rotation is
// integrated exactly; a static tilt is recovered from the accelerometer, the heading from the
// magnetometer; a constant gyro bias of a level sensor is estimated on its horizontal axes;
// the earth-frame low-pass of the accelerometer holds the tilt of a shaken sensor; a sample
// past the acceleration gate leaves the belief untouched; and the manifold filters' noise
// setters refuse what is not a covariance.
#include <algorithm>
#include <cmath>

#include <gtest/gtest.h>

#include "sf_estimation/attitude_filter.hpp"
#include "sf_estimation/errors.hpp"
#include "statistical_steps.hpp"

namespace {

using estimation::AttitudeFilter;
using estimation::AttitudeParameters;
using estimation::Matrix;
using Quat = Eigen::Quaterniond;
using V3 = Eigen::Vector3d;

constexpr double kG = 9.81;
constexpr double kDt = 0.01;
constexpr double kPi = 3.14159265358979323846;

Matrix<6, 6> initialCovariance(double angle, double bias) {
  Matrix<6, 6> P0 = Matrix<6, 6>::Zero();
  P0.diagonal() << V3::Constant(angle * angle), V3::Constant(bias * bias);
  return P0;
}

double angleBetween(const Quat& a, const Quat& b) { return a.angularDistance(b); }

// What a sensor at rest with orientation q (sensor to ENU) measures: the specific force (up,
// of size g) and a field pointing north and down (dip -60 deg), in the sensor frame.
V3 accelerometerAt(const Quat& q) { return q.conjugate() * V3(0.0, 0.0, kG); }
V3 fieldAt(const Quat& q) { return q.conjugate() * V3(0.0, 20.0, -34.64); }

TEST(AttitudeFilter, IntegratesAConstantRotationExactly) {
  const Quat q0(Eigen::AngleAxisd(0.4, V3(1.0, 2.0, -1.0).normalized()));
  AttitudeFilter filter(AttitudeParameters(), q0, initialCovariance(0.1, 0.01));
  const V3 rate(0.3, -0.5, 0.8);  // rad/s, body frame
  for (int k = 0; k < 1000; ++k) filter.predict(rate, kDt);
  // q0 exp(rate t): a constant body rate is one rotation about a fixed body axis.
  const Quat expected = q0 * Quat(Eigen::AngleAxisd(rate.norm() * 10.0, rate.normalized()));
  EXPECT_LT(angleBetween(filter.orientation(), expected), 1e-11);
  EXPECT_EQ(filter.bias(), V3::Zero());
}

TEST(AttitudeFilter, RecoversAStaticTiltFromTheAccelerometer) {
  AttitudeParameters parameters;
  parameters.useMagnetometer = false;
  // Roll 0.3, pitch -0.2 rad; the filter starts level.
  const Quat truth =
      Quat(Eigen::AngleAxisd(-0.2, V3::UnitY())) * Quat(Eigen::AngleAxisd(0.3, V3::UnitX()));
  AttitudeFilter filter(parameters, Quat::Identity(), initialCovariance(0.5, 1e-6));
  for (int k = 0; k < 2000; ++k) {
    filter.predict(V3::Zero(), kDt);
    ASSERT_TRUE(filter.correctGravity(accelerometerAt(truth)));
  }
  // The estimated up direction in the sensor frame is the measured one; the tilt (the angle
  // between the estimated and true up in the earth frame) vanishes.
  const V3 up = filter.orientation().conjugate() * V3::UnitZ();
  EXPECT_LT((up - accelerometerAt(truth) / kG).norm(), 1e-6);
  const V3 upOfTruthSeenByEstimate = filter.orientation() * (truth.conjugate() * V3::UnitZ());
  EXPECT_LT(std::acos(std::min(1.0, upOfTruthSeenByEstimate.z())), 1e-6);
}

TEST(AttitudeFilter, RecoversTheHeadingFromTheMagnetometer) {
  const Quat truth =
      Quat(Eigen::AngleAxisd(1.2, V3::UnitZ())) * Quat(Eigen::AngleAxisd(0.25, V3::UnitX()));
  // The first field sample defines the field; start 0.5 rad off in heading.
  const Quat start =
      Quat(Eigen::AngleAxisd(0.7, V3::UnitZ())) * Quat(Eigen::AngleAxisd(0.25, V3::UnitX()));
  AttitudeFilter filter(AttitudeParameters(), start, initialCovariance(0.5, 1e-6));
  EXPECT_FALSE(filter.correctField(fieldAt(start)));
  for (int k = 0; k < 3000; ++k) {
    filter.predict(V3::Zero(), kDt);
    filter.correctGravity(accelerometerAt(truth));
    ASSERT_TRUE(filter.correctField(fieldAt(truth))) << "step " << k;
  }
  EXPECT_LT(angleBetween(filter.orientation(), truth), 1e-5);
}

TEST(AttitudeFilter, EstimatesTheHorizontalGyroBiasOfALevelSensor) {
  AttitudeParameters parameters;
  parameters.useMagnetometer = false;
  parameters.biasWalk = 1e-3;
  AttitudeFilter filter(parameters, Quat::Identity(), initialCovariance(0.01, 0.02));
  const V3 bias(0.01, -0.02, 0.005);
  for (int k = 0; k < 4000; ++k) {  // 40 s; within 1e-4 after 20 s already
    filter.predict(bias, kDt);      // at rest: the gyro reads its bias
    filter.correctGravity(V3(0.0, 0.0, kG));
  }
  // Gravity observes the rotation about the horizontal axes only: x and y of the bias.
  EXPECT_NEAR(filter.bias().x(), 0.01, 1e-4);
  EXPECT_NEAR(filter.bias().y(), -0.02, 1e-4);
}

// A level sensor shaken along x: a = (A sin(w t), 0, g). The low-pass of time constant tau
// passes A / sqrt(1 + (w tau)^2) < A / (w tau) of the shaking, so the measured direction, and
// with it the tilt, stays within A / (g w tau); the raw samples swing by A / g.
double largestTiltWhenShaken(double timeConstant) {
  AttitudeParameters parameters;
  parameters.useMagnetometer = false;
  parameters.accelerationGate = 1.0;
  parameters.accelerationTimeConstant = timeConstant;
  AttitudeFilter filter(parameters, Quat::Identity(), initialCovariance(0.01, 1e-6));
  const double amplitude = 2.0, omega = 2.0 * kPi;
  double largest = 0.0;
  // 50 s of shaking after 10 s to settle; 1 s after them under the sanitizers.
  for (int k = 0; k < sftest::statisticalSteps(6000, 1100); ++k) {
    filter.predict(V3::Zero(), kDt);
    filter.correctGravity(V3(amplitude * std::sin(omega * k * kDt), 0.0, kG), kDt);
    const V3 up = filter.orientation() * V3::UnitZ();
    if (k >= 1000) largest = std::max(largest, std::acos(std::min(1.0, up.z())));
  }
  return largest;
}

TEST(AttitudeFilter, TheEarthFrameLowPassHoldsTheTiltOfAShakenSensor) {
  const double bound = 2.0 / (kG * 2.0 * kPi * 3.0);  // A / (g w tau), 0.0108 rad
  const double lowPass = largestTiltWhenShaken(3.0), raw = largestTiltWhenShaken(0.0);
  EXPECT_TRUE(std::isfinite(lowPass) && std::isfinite(raw));
  if (!sftest::kStatisticsAsserted) return;
  EXPECT_LT(lowPass, bound);
  EXPECT_GT(raw, bound);  // the raw samples do not stay within it
}

TEST(AttitudeFilter, SkipsAnAccelerationPastTheGateAndKeepsTheBelief) {
  AttitudeParameters parameters;
  parameters.accelerationGate = 0.25;
  AttitudeFilter filter(parameters, Quat::Identity(), initialCovariance(0.1, 0.01));
  filter.predict(V3(0.1, 0.0, 0.0), kDt);
  const auto x = filter.ekf().state();
  const auto P = filter.ekf().covariance();
  EXPECT_FALSE(filter.correctGravity(V3(0.0, 3.0, 1.3 * kG)));
  EXPECT_EQ(filter.ekf().state(), x);
  EXPECT_EQ(filter.ekf().covariance(), P);
  EXPECT_TRUE(filter.correctGravity(V3(0.0, 0.5, kG)));
  EXPECT_NE(filter.ekf().state(), x);
}

TEST(AttitudeFilter, NoiseSettersRefuseANonCovarianceAndKeepTheOldOne) {
  AttitudeFilter filter(AttitudeParameters(), Quat::Identity(), initialCovariance(0.1, 0.01));
  AttitudeFilter::Ekf ekf = filter.ekf();
  const auto R = ekf.measurementNoise();
  const auto Q = ekf.processNoise();
  EXPECT_THROW(ekf.setMeasurementNoise(-R), estimation::ParameterError);
  EXPECT_THROW(ekf.setMeasurementNoise(Matrix<3, 3>::Zero()),
               estimation::ParameterError);  // not definite
  EXPECT_EQ(ekf.measurementNoise(), R);
  Matrix<6, 6> asymmetric = Q;
  asymmetric(0, 1) = 1.0;
  EXPECT_THROW(ekf.setProcessNoise(asymmetric), estimation::ParameterError);
  EXPECT_EQ(ekf.processNoise(), Q);
  ekf.setMeasurementNoise(2.0 * R);
  EXPECT_EQ(ekf.measurementNoise(), 2.0 * R);
}

}  // namespace
