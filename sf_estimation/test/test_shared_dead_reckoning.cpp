// Tests of the dead-reckoned states (dead_reckoned_states.hpp) and of the particle filter's
// shared dead reckoning (particle_filter.hpp): which states a model leaves unweighed, the shared
// block against the Kalman recursion on a linear model, a planar pose against ground truth and
// against the track of the filter's own velocities, its covariance against the EKF's, and a
// rejected step.
#include <cmath>
#include <iostream>
#include <limits>
#include <random>

#include <gtest/gtest.h>

#include "sf_estimation/dead_reckoned_states.hpp"
#include "sf_estimation/errors.hpp"
#include "sf_estimation/extended_kalman_filter.hpp"
#include "sf_estimation/particle_filter.hpp"
#include "statistical_steps.hpp"

// Named, not anonymous: compiled in a unity group (sf_estimation/CMakeLists.txt).
namespace shared_dead_reckoning_test {

using estimation::Index;
using estimation::Mask;
using estimation::Matrix;
using estimation::Measurement;
using estimation::ParticleFilterParameters;
using estimation::ParticleFilterSIR;
using estimation::Vector;

constexpr double kT = 0.1;

/// x = (px, py, theta, v, omega): a pose integrated from a speed and a turn rate, which are
/// measured. `fix` adds a position fix (h reads px, py); `slope` makes the speed's transition
/// read the heading (so the heading is weighed through it).
struct Unicycle {
  static constexpr int StateSize = 5, MeasurementSize = 2, ControlSize = 0;
  bool fix = false;
  bool slope = false;
  bool poison = false;
  Index stateSize() const { return 5; }
  Index measurementSize() const { return 2; }
  Index controlSize() const { return 0; }
  template <class S>
  void transition(const Eigen::Matrix<S, 5, 1>& x, const Vector<0>&,
                  Eigen::Matrix<S, 5, 1>& next) const {
    using std::cos;
    using std::sin;
    next << x(0) + kT * x(3) * cos(x(2)), x(1) + kT * x(3) * sin(x(2)), x(2) + kT * x(4),
        x(3) - (slope ? S(0.01) * sin(x(2)) : S(0)), x(4);
    if (poison) next(0) = S(std::numeric_limits<double>::quiet_NaN());
  }
  template <class S>
  void observation(const Eigen::Matrix<S, 5, 1>& x, Eigen::Matrix<S, 2, 1>& z) const {
    if (fix) {
      z << x(0), x(1);
    } else {
      z << x(3), x(4);
    }
  }
};

Mask<5> maskOf(bool a, bool b, bool c, bool d, bool e) {
  Mask<5> m;
  m << a, b, c, d, e;
  return m;
}

TEST(DeadReckonedStates, FoundFromTheModelsFunctions) {
  const Vector<5> x0 = Vector<5>::Zero();
  Unicycle model;
  // Velocities measured: the pose is dead-reckoned.
  EXPECT_EQ(estimation::deadReckonedStates(model, x0, 0), maskOf(true, true, true, false, false));
  // The speed's transition reads the heading: the heading is weighed through the speed.
  model.slope = true;
  EXPECT_EQ(estimation::deadReckonedStates(model, x0, 0), maskOf(true, true, false, false, false));
  // A position fix weighs the position and, through its transition, everything else.
  model = Unicycle{};
  model.fix = true;
  EXPECT_EQ(estimation::deadReckonedStates(model, x0, 0),
            maskOf(false, false, false, false, false));
}

/// x = (p, q, v): p' = p + T q, q' = q + T v, v' = v, z = v. p and q are dead-reckoned and
/// linear, so with v known exactly (no spread of v among the particles) the shared block follows
/// the Kalman recursion m' = F m + (0, T v), P' = F P F^T + Q exactly.
struct DoubleIntegrator {
  static constexpr int StateSize = 3, MeasurementSize = 1, ControlSize = 0;
  Index stateSize() const { return 3; }
  Index measurementSize() const { return 1; }
  Index controlSize() const { return 0; }
  template <class S>
  void transition(const Eigen::Matrix<S, 3, 1>& x, const Vector<0>&,
                  Eigen::Matrix<S, 3, 1>& next) const {
    next << x(0) + kT * x(1), x(1) + kT * x(2), x(2);
  }
  template <class S>
  void observation(const Eigen::Matrix<S, 3, 1>& x, Eigen::Matrix<S, 1, 1>& z) const {
    z << x(2);
  }
};

TEST(SharedDeadReckoning, LinearBlockFollowsTheKalmanRecursion) {
  ParticleFilterParameters params;
  params.particles = 200;
  params.sharedDeadReckoning = true;
  Matrix<3, 3> Q = Matrix<3, 3>::Zero(), P0 = Matrix<3, 3>::Zero();
  Q.topLeftCorner<2, 2>() << 0.01, 0.002, 0.002, 0.02;
  P0.topLeftCorner<2, 2>() << 0.5, 0.1, 0.1, 0.2;
  const Vector<3> x0(1.0, -0.5, 0.8);
  ParticleFilterSIR<DoubleIntegrator> pf(DoubleIntegrator{}, Q, Matrix<1, 1>::Identity(), x0, P0,
                                         params);
  ASSERT_EQ(pf.deadReckonedStates(), (Mask<3>() << true, true, false).finished());
  Matrix<2, 2> F;
  F << 1, kT, 0, 1;
  Vector<2> m = x0.head<2>();
  Matrix<2, 2> P = P0.topLeftCorner<2, 2>();
  Measurement<1> z(1);
  z.value << 0.8;
  for (int k = 0; k < 50; ++k) {
    pf.estimate(z);
    m = F * m + Vector<2>(0.0, kT * 0.8);
    P = F * P * F.transpose() + Q.topLeftCorner<2, 2>();
  }
  EXPECT_LT((pf.state().head<2>() - m).norm(), 1e-12 * m.norm());
  EXPECT_LT((pf.covariance().topLeftCorner<2, 2>() - P).norm(), 1e-12 * P.norm());
  // v: the weighted mean of 200 equal values, equal to rounding.
  EXPECT_NEAR(pf.state()(2), 0.8, 1e-14);
  EXPECT_LT(pf.covariance()(2, 2), 1e-28);
}

struct DriveResult {
  double poseRmse = 0.0;        // the filter's own pose against the truth
  double integratedRmse = 0.0;  // its speed and turn rate integrated offline
  double finalVariance = 0.0;   // px's variance at the end
};

/// 60 s of a drive with a varying speed and turn rate, both measured (sigma 0.05 m/s and
/// 0.01 rad/s, accurate enough that the particles are resampled in most steps).
template <class Filter>
DriveResult drive(Filter& filter) {
  std::mt19937_64 engine(5);
  std::normal_distribution<double> normal;
  Vector<5> truth(0, 0, 0, 0.5, 0);
  double px = 0.0, py = 0.0, theta = 0.0, poseSum = 0.0, integratedSum = 0.0;
  Measurement<2> z(2);
  const int steps = sftest::statisticalSteps(600, 40);  // 60 s; 4 s under the sanitizers
  for (int k = 0; k < steps; ++k) {
    const double t = kT * (k + 1);
    const Vector<5> before = truth;
    Unicycle{}.transition(before, Vector<0>(), truth);
    truth(3) = 0.5 + 0.2 * std::sin(0.3 * t);
    truth(4) = 0.3 * std::sin(0.2 * t);
    z.value << truth(3) + 0.05 * normal(engine), truth(4) + 0.01 * normal(engine);
    const double v = filter.state()(3), w = filter.state()(4);
    filter.estimate(z);
    px += kT * v * std::cos(theta);
    py += kT * v * std::sin(theta);
    theta += kT * w;
    poseSum +=
        std::pow(filter.state()(0) - truth(0), 2) + std::pow(filter.state()(1) - truth(1), 2);
    integratedSum += std::pow(px - truth(0), 2) + std::pow(py - truth(1), 2);
  }
  return {std::sqrt(poseSum / steps), std::sqrt(integratedSum / steps), filter.covariance()(0, 0)};
}

const Matrix<5, 5> kQ = Vector<5>(1e-4, 1e-4, 1e-4, 0.01, 0.01).asDiagonal();
const Matrix<2, 2> kR = Vector<2>(0.05 * 0.05, 0.01 * 0.01).asDiagonal();
const Matrix<5, 5> kP0 = Vector<5>(0, 0, 0, 0.01, 0.01).asDiagonal();
const Vector<5> kX0(0, 0, 0, 0.5, 0);

DriveResult particleDrive(bool shared) {
  ParticleFilterParameters params;
  params.particles = 500;
  params.seed = 3;
  params.sharedDeadReckoning = shared;
  ParticleFilterSIR<Unicycle> pf(Unicycle{}, kQ, kR, kX0, kP0, params,
                                 estimation::AngularComponents{{2}, {}});
  return drive(pf);
}

TEST(SharedDeadReckoning, PoseFollowsTheParticlesVelocitiesAndItsCovarianceTheEkfs) {
  const DriveResult own = particleDrive(false);
  const DriveResult shared = particleDrive(true);
  estimation::ExtendedKalmanFilter<Unicycle> ekf(Unicycle{}, kQ, kR, kX0, kP0,
                                                 estimation::AngularComponents{{2}, {}});
  const DriveResult reference = drive(ekf);
  std::cout << "[ measured ] 60 s drive, pose RMSE against the truth: particles' own pose "
            << own.poseRmse << " m (their velocities integrated: " << own.integratedRmse
            << " m); shared " << shared.poseRmse << " m (integrated: " << shared.integratedRmse
            << " m); EKF " << reference.poseRmse << " m. Final px variance: own "
            << own.finalVariance << ", shared " << shared.finalVariance << ", EKF "
            << reference.finalVariance << " m^2\n";
  for (const DriveResult& r : {own, shared, reference}) {
    EXPECT_TRUE(std::isfinite(r.poseRmse) && std::isfinite(r.finalVariance));
  }
  if (!sftest::kStatisticsAsserted) return;
  // The criterion: the filter's pose within 20 % of its velocities' integration.
  EXPECT_LT(std::abs(shared.poseRmse - shared.integratedRmse), 0.2 * shared.integratedRmse);
  EXPECT_GT(own.poseRmse, 2.0 * shared.poseRmse);
  // The shared covariance is the EKF's linearised propagation, up to the particles' spread.
  EXPECT_GT(shared.finalVariance, 0.5 * reference.finalVariance);
  EXPECT_LT(shared.finalVariance, 2.0 * reference.finalVariance);
}

TEST(SharedDeadReckoning, RejectedStepChangesNothing) {
  ParticleFilterParameters params;
  params.particles = 50;
  params.sharedDeadReckoning = true;
  ParticleFilterSIR<Unicycle> pf(Unicycle{}, kQ, kR, kX0, kP0, params,
                                 estimation::AngularComponents{{2}, {}});
  Measurement<2> z(2);
  z.value << 0.5, 0.1;
  for (int k = 0; k < 5; ++k) pf.estimate(z);
  const Vector<5> x = pf.state();
  const Matrix<5, 5> P = pf.covariance();
  pf.model().poison = true;
  EXPECT_THROW(pf.estimate(z), estimation::NumericalError);
  EXPECT_EQ(pf.state(), x);
  EXPECT_EQ(pf.covariance(), P);
  pf.model().poison = false;
  ParticleFilterSIR<Unicycle> twin(Unicycle{}, kQ, kR, kX0, kP0, params,
                                   estimation::AngularComponents{{2}, {}});
  for (int k = 0; k < 6; ++k) twin.estimate(z);
  pf.estimate(z);
  EXPECT_EQ(pf.state(), twin.state());  // the engine was restored too
}

}  // namespace shared_dead_reckoning_test
