// Armesto's 19-state inertial+vision model (models/armesto_inertial_vision.hpp) and its
// multi-rate filter (models/armesto_multi_rate.hpp) on analytic cases: a constant body rate
// and a constant acceleration are predicted exactly; the accelerometer measures gravity (and
// its bias) at rest; the AutoDiff Jacobians of the error-state EKF equal finite differences of
// the model through the retractions; and the fused filter finds the accelerometer's bias of a
// sensor at rest, which the IMU alone cannot.
#include <cmath>

#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include "sf_estimation/manifold_extended_kalman_filter.hpp"
#include "sf_estimation/manifold_unscented_kalman_filter.hpp"
#include "sf_estimation/models/armesto_multi_rate.hpp"
#include "statistical_steps.hpp"

namespace {

namespace am = estimation::armesto;
using estimation::Matrix;
using estimation::Vector;
using Quat = Eigen::Quaterniond;
using V3 = Eigen::Vector3d;
using Full = am::Model<am::InertialVision>;
using Ekf = estimation::ManifoldExtendedKalmanFilter<Full>;

constexpr double kG = 9.81;

Vector<19> stateOf(const V3& p, const V3& v, const V3& a, const V3& b, const Quat& q,
                   const V3& omega) {
  Vector<19> x;
  x << p, v, a, b, q.w(), q.x(), q.y(), q.z(), omega;
  return x;
}

Vector<19> someState() {
  return stateOf(V3(1.0, -2.0, 0.5), V3(0.3, 0.1, -0.2), V3(0.5, -0.4, 0.2), V3(0.05, -0.02, 0.03),
                 Quat(Eigen::AngleAxisd(0.7, V3(1.0, -2.0, 0.5).normalized())), V3(0.4, -0.8, 1.1));
}

Quat quaternionOf(const Vector<19>& x) { return Quat(x(12), x(13), x(14), x(15)); }

TEST(ArmestoModel, PredictsAConstantRateAndAccelerationExactly) {
  const Vector<19> x0 = someState();
  const Full model;
  Vector<19> x = x0, next;
  const Vector<1> T = Vector<1>::Constant(0.01);
  for (int k = 0; k < 500; ++k) {
    model.transition(x, T, Vector<9>::Zero().eval(), next);
    x = next;
  }
  const double t = 5.0;
  const V3 p0 = x0.head<3>(), v0 = x0.segment<3>(3), a0 = x0.segment<3>(6);
  EXPECT_LT((x.head<3>() - (p0 + v0 * t + a0 * t * t / 2.0)).norm(), 1e-11);
  EXPECT_LT((x.segment<3>(3) - (v0 + a0 * t)).norm(), 1e-12);
  EXPECT_EQ(x.segment<3>(6), a0);
  EXPECT_EQ(x.segment<3>(9), x0.segment<3>(9));
  const V3 omega = x0.tail<3>();
  const Quat expected =
      quaternionOf(x0) * Quat(Eigen::AngleAxisd(omega.norm() * t, omega.normalized()));
  EXPECT_LT(quaternionOf(x).angularDistance(expected), 1e-11);
  EXPECT_EQ(x.tail<3>(), omega);
}

TEST(ArmestoModel, TheJerkAndAngularAccelerationEnterAsThePaperIntegratesThem) {
  const Full model;
  Vector<19> x = stateOf(V3::Zero(), V3::Zero(), V3::Zero(), V3::Zero(), Quat::Identity(),
                         V3::Zero()),
             next;
  Vector<9> w;
  w << 6.0, 0.0, 0.0, 0.0, 0.0, 2.0, 0.0, 0.0, 1.0;  // jerk x, alpha z, bias rate z
  model.transition(x, Vector<1>::Constant(0.5), w, next);
  EXPECT_NEAR(next(0), 6.0 * 0.125 / 6.0, 1e-15);  // T^3/6 j
  EXPECT_NEAR(next(3), 6.0 * 0.25 / 2.0, 1e-15);   // T^2/2 j
  EXPECT_NEAR(next(6), 3.0, 1e-15);                // T j
  EXPECT_NEAR(next(11), 0.5, 1e-15);               // T b'
  EXPECT_NEAR(next(18), 1.0, 1e-15);               // T alpha
  // Turned by (omega + T/2 alpha) T = 0.25 rad about z.
  EXPECT_NEAR(quaternionOf(next).angularDistance(Quat(Eigen::AngleAxisd(0.25, V3::UnitZ()))), 0.0,
              1e-15);
}

TEST(ArmestoModel, TheAccelerometerMeasuresGravityAtRest) {
  const V3 bias(0.05, -0.02, 0.03);
  const Quat tilt(Eigen::AngleAxisd(0.3, V3::UnitX()));
  const Full model;
  Vector<13> z;
  model.observation(
      stateOf(V3(1, 2, 3), V3::Zero(), V3::Zero(), bias, Quat::Identity(), V3(0.1, 0.2, 0.3)), z);
  EXPECT_LT((z.head<3>() - (V3(0.0, 0.0, kG) + bias)).norm(), 1e-15);
  EXPECT_LT((z.segment<3>(3) - V3(0.1, 0.2, 0.3)).norm(), 1e-15);
  EXPECT_LT((z.segment<3>(6) - V3(1, 2, 3)).norm(), 1e-15);
  model.observation(stateOf(V3::Zero(), V3::Zero(), V3::Zero(), V3::Zero(), tilt, V3::Zero()), z);
  // Rolled by 0.3 rad about x: up seen from the sensor is (0, sin 0.3, cos 0.3).
  EXPECT_LT((z.head<3>() - kG * V3(0.0, std::sin(0.3), std::cos(0.3))).norm(), 1e-14);
  EXPECT_LT((z.tail<4>() - Vector<4>(tilt.w(), tilt.x(), tilt.y(), tilt.z())).norm(), 1e-15);
}

// Central differences of f(x [+] e, u, w) [-] f(x, u, 0) and h(x [+] e) [-] h(x).
TEST(ArmestoModel, JacobiansEqualFiniteDifferences) {
  const Vector<19> x = someState();
  const Vector<1> u = Vector<1>::Constant(0.01);
  Vector<19> next;
  Matrix<18, 18> F;
  Matrix<18, 9> G;
  Ekf::transitionJacobiansAt(Full(), x, u, next, F, G);
  const auto f = [&](const Vector<18>& e, const Vector<9>& w) {
    Vector<19> out;
    Full().transition(am::State::plus<double>(x, e), u, w, out);
    return am::State::minus<double>(out, next);
  };
  const double h = 1e-6;
  for (int j = 0; j < 18; ++j) {
    const Vector<18> e = Vector<18>::Unit(j) * h;
    EXPECT_LT((F.col(j) - (f(e, Vector<9>::Zero()) - f(-e, Vector<9>::Zero())) / (2 * h))
                  .cwiseAbs()
                  .maxCoeff(),
              1e-7)
        << "column " << j;
  }
  for (int j = 0; j < 9; ++j) {
    const Vector<9> w = Vector<9>::Unit(j) * h;
    EXPECT_LT((G.col(j) - (f(Vector<18>::Zero(), w) - f(Vector<18>::Zero(), -w)) / (2 * h))
                  .cwiseAbs()
                  .maxCoeff(),
              1e-7)
        << "noise column " << j;
  }
}

TEST(ArmestoModel, ObservationJacobianEqualsFiniteDifferences) {
  const Vector<19> x = someState();
  const Ekf ekf(Full(), Matrix<9, 9>::Identity(), Matrix<12, 12>::Identity(), x,
                Matrix<18, 18>::Identity());
  Vector<13> expected;
  Matrix<12, 18> H;
  ekf.observationJacobian(expected, H);
  using MSpace = Full::MeasurementSpace;
  const auto h = [&](const Vector<18>& e) {
    Vector<13> z;
    Full().observation(am::State::plus<double>(x, e), z);
    return MSpace::minus<double>(z, expected);
  };
  const double step = 1e-6;
  for (int j = 0; j < 18; ++j) {
    const Vector<18> e = Vector<18>::Unit(j) * step;
    EXPECT_LT((H.col(j) - (h(e) - h(-e)) / (2 * step)).cwiseAbs().maxCoeff(), 1e-7)
        << "column " << j;
  }
}

// A level sensor at rest with an accelerometer bias: the IMU alone reads the bias as an
// acceleration (it cannot tell them apart); with vision holding the position the filter
// attributes it to the bias.
template <template <class> class Filter>
Vector<19> restWithBias(bool withVision) {
  const V3 bias(0.08, -0.05, 0.1);
  Matrix<18, 18> P0 = Matrix<18, 18>::Identity() * 1e-6;
  P0.block<3, 3>(9, 9) = Matrix<3, 3>::Identity() * 0.01;
  const Vector<19> x0 =
      stateOf(V3::Zero(), V3::Zero(), V3::Zero(), V3::Zero(), Quat::Identity(), V3::Zero());
  am::MultiRateFilter<Filter> filter(am::Noise(), x0, P0, 0.01);
  Vector<6> imu;
  imu << V3(0.0, 0.0, kG) + bias, V3::Zero();
  Vector<7> vision;
  vision << 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0;
  // 30 s for the bias to converge; 2.4 s (30 vision frames) under the sanitizers.
  for (int k = 1; k <= sftest::statisticalSteps(3000, 240); ++k) {
    if (withVision && k % 8 == 0) {
      filter.step(imu, vision);
    } else {
      filter.step(imu);
    }
  }
  return filter.state();
}

TEST(ArmestoMultiRate, VisionMakesTheAccelerometerBiasObservable) {
  for (const Vector<19>& x : {restWithBias<estimation::ManifoldExtendedKalmanFilter>(true),
                              restWithBias<estimation::ManifoldUnscentedKalmanFilter>(true)}) {
    EXPECT_TRUE(x.allFinite());
    if (sftest::kStatisticsAsserted) {
      EXPECT_LT((x.segment<3>(9) - V3(0.08, -0.05, 0.1)).norm(), 2e-3);
      EXPECT_LT(x.head<3>().norm(), 1e-3);
    }
  }
  const Vector<19> imuOnly = restWithBias<estimation::ManifoldExtendedKalmanFilter>(false);
  EXPECT_TRUE(imuOnly.allFinite());
  // 30 s of a bias read as acceleration: the position drifts by metres.
  if (sftest::kStatisticsAsserted) {
    EXPECT_GT(imuOnly.head<3>().norm(), 1.0);
  }
}

}  // namespace
