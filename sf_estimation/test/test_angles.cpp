// Angles: wrapping, circular means against hand computations, wrapped innovations in every
// Kalman filter, the particle filter and the Mahalanobis distance, and a long run with a
// heading integrated from a gyro alone (variance past 3 rad^2) in which the UKF must follow
// the EKF; without the angle declaration the same UKF goes wrong.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <iostream>
#include <optional>
#include <random>

#include <gtest/gtest.h>

#include "scalar_models.hpp"
#include "sf_estimation/angles.hpp"
#include "sf_estimation/errors.hpp"
#include "sf_estimation/estimator_factory.hpp"
#include "sf_estimation/extended_kalman_filter.hpp"
#include "sf_estimation/kalman_filter.hpp"
#include "sf_estimation/measurement_prediction.hpp"
#include "sf_estimation/particle_filter.hpp"
#include "sf_estimation/unscented_kalman_filter.hpp"
#include "sf_estimation/unscented_transform.hpp"

namespace {

using estimation::AngularComponents;
using estimation::Index;
using estimation::Matrix;
using estimation::Measurement;
using estimation::Vector;
using estimation::wrapAngle;

constexpr double kPi = 3.14159265358979323846;

TEST(AngleWrap, HandValues) {
  EXPECT_EQ(wrapAngle(kPi), kPi);   // (-pi, pi]: pi stays
  EXPECT_EQ(wrapAngle(-kPi), kPi);  // -pi becomes pi
  EXPECT_DOUBLE_EQ(wrapAngle(1.5 * kPi), -0.5 * kPi);
  EXPECT_DOUBLE_EQ(wrapAngle(-1.5 * kPi), 0.5 * kPi);
  EXPECT_EQ(wrapAngle(0.25), 0.25);
  EXPECT_DOUBLE_EQ(wrapAngle(2.0 * kPi + 0.25), 0.25);
  // Far away: 1e6 = 159154 * 2 pi + r; r from the integer count, computed independently.
  const double r = 1e6 - 159155.0 * 2.0 * kPi;
  EXPECT_NEAR(wrapAngle(1e6), r, 1e-9);
  EXPECT_TRUE(std::isnan(wrapAngle(std::nan(""))));
  EXPECT_TRUE(std::isnan(wrapAngle(INFINITY)));
}

TEST(CircularMean, WeightedAnglesAcrossPi) {
  // pi - 0.1 and -pi + 0.1 with equal weights: the mean is pi (a linear mean gives 0).
  Eigen::Vector2d a(kPi - 0.1, -kPi + 0.1), w(0.5, 0.5);
  EXPECT_NEAR(wrapAngle(estimation::circularMean(a, w) - kPi), 0.0, 1e-12);
  // 3 and -3 with weights 0.75, 0.25: s = 0.5 sin 3, c = cos 3, atan2(s, c) = 3.07043970...
  a << 3.0, -3.0;
  w << 0.75, 0.25;
  EXPECT_NEAR(estimation::circularMean(a, w), 3.0704397020756757, 1e-12);
}

TEST(CircularMean, MeanAroundReferenceAcrossPi) {
  // Reference 3.0, points 3.0, -3.0 (= 3.0 + (2 pi - 6)), 2.9 with weights 0.5, 0.25, 0.25:
  // 3.0 + 0.25 (2 pi - 6) - 0.25 * 0.1 = 3.04579632679...; the linear mean would be 1.475.
  Eigen::Vector3d a(3.0, -3.0, 2.9), w(0.5, 0.25, 0.25);
  EXPECT_NEAR(estimation::meanAround(3.0, a, w), 3.0457963267948966, 1e-12);
  EXPECT_NEAR(a.dot(w), 1.475, 1e-12);
  // Negative weights (a small alpha) are fine.
  Eigen::Vector3d b(kPi - 0.01, -kPi + 0.01, kPi - 0.03), v(-2.0, 1.5, 1.5);
  // deviations from pi - 0.01: 0, +0.02, -0.02 -> mean pi - 0.01 + 1.5 * 0 = pi - 0.01
  EXPECT_NEAR(estimation::meanAround(kPi - 0.01, b, v), kPi - 0.01, 1e-12);
}

TEST(UnscentedTransformAngles, SigmaPointsStraddlingPi) {
  // One angle, mean 3.1, variance 0.04, alpha = 1, kappa = 2: n + lambda = 3, points 3.1 and
  // 3.1 +- sqrt(3) * 0.2, the upper one wrapped to -2.8367... as a wrapping model gives it.
  // Weights 2/3, 1/6, 1/6; the mean is 3.1 and the variance 2 * (1/6) * 3 * 0.04 = 0.04.
  estimation::UnscentedParameters p;
  p.alpha = 1.0;
  p.beta = 0.0;  // Wc0 = Wm0, so the central point adds nothing either way
  p.kappa = 2.0;
  estimation::UnscentedTransform<1> ut(1, p);
  Eigen::Matrix<double, 1, 3> points;
  ut.sigmaPoints(Vector<1>::Constant(3.1), Matrix<1, 1>::Constant(0.04), points);
  const double spread = std::sqrt(3.0) * 0.2;
  EXPECT_NEAR(points(0, 1), 3.1 + spread, 1e-15);
  points(0, 1) = wrapAngle(points(0, 1));
  EXPECT_LT(points(0, 1), 0.0);

  const estimation::AngleMask<1> angle({0}, 1, "test", "state");
  Vector<1> mean;
  ut.mean(points, mean, angle);
  EXPECT_NEAR(mean(0), 3.1, 1e-14);
  Matrix<1, 1> P;
  ut.crossCovariance(points, mean, points, mean, P, angle, angle);
  EXPECT_NEAR(P(0, 0), 0.04, 1e-14);

  // Without the declaration: (2/3) 3.1 + (1/6)(3.1 + s - 2 pi) + (1/6)(3.1 - s) = 3.1 - pi/3.
  Vector<1> linear;
  ut.mean(points, linear);
  EXPECT_NEAR(linear(0), 3.1 - kPi / 3.0, 1e-12);
}

TEST(UnscentedTransformAngles, ResultantOfSigmaPointsFlipsPastTwoRadSquared) {
  // Why sigma points are averaged around the central point and not by atan2: with the
  // default alpha = 1e-3 the weighted resultant sum w (cos, sin) is 1 - sigma^2 / 2 to second
  // order; at sigma^2 = 3.2 it points backwards and atan2 returns the mean + pi.
  estimation::UnscentedTransform<1> ut(1, estimation::UnscentedParameters{});
  Eigen::Matrix<double, 1, 3> points;
  const double mu = 1.0, variance = 3.2;
  ut.sigmaPoints(Vector<1>::Constant(mu), Matrix<1, 1>::Constant(variance), points);
  const Eigen::RowVector3d angles = points.row(0);
  const Eigen::Vector3d w = ut.meanWeights();
  double c = 0.0;
  for (Index i = 0; i < 3; ++i) c += w(i) * std::cos(angles(i) - mu);
  EXPECT_NEAR(c, 1.0 - variance / 2.0, 1e-6);
  EXPECT_NEAR(std::abs(wrapAngle(estimation::circularMean(angles, w) - mu)), kPi, 1e-6);
  EXPECT_NEAR(estimation::meanAround(angles(0), angles, w), mu, 1e-9);
}

// -------------------------------------------------------------------------------------------
// Innovations of angle measurements.
// -------------------------------------------------------------------------------------------

using Compass = sftest::IdentityModel;

const AngularComponents kCompassAngles{{0}, {0}};

template <class Filter>
void expectCompassUpdate(Filter& withAngles, Filter& without) {
  // x = 3.1, P = 1, R = 1, z = -3.1: the wrapped innovation is 2 pi - 6.2, K = 1/2, so
  // x = 3.1 + pi - 3.1 = pi. Linearly the innovation is -6.2 and x = 0.
  const Measurement<1> z = Measurement<1>::complete(Vector<1>::Constant(-3.1));
  withAngles.estimate(z);
  without.estimate(z);
  EXPECT_NEAR(wrapAngle(withAngles.state()(0) - kPi), 0.0, 1e-12);
  EXPECT_NEAR(withAngles.covariance()(0, 0), 0.5, 1e-12);
  EXPECT_NEAR(without.state()(0), 0.0, 1e-12);
}

TEST(AngleInnovation, KalmanFilters) {
  const Matrix<1, 1> one = Matrix<1, 1>::Identity(), zero = Matrix<1, 1>::Zero();
  const Vector<1> x0 = Vector<1>::Constant(3.1);
  estimation::KalmanFilter<1, 1> kfA(one, Matrix<1, 0>(), one, zero, one, x0, one, kCompassAngles);
  estimation::KalmanFilter<1, 1> kf(one, Matrix<1, 0>(), one, zero, one, x0, one);
  expectCompassUpdate(kfA, kf);
  estimation::ExtendedKalmanFilter<Compass> ekfA(Compass{}, zero, one, x0, one, kCompassAngles);
  estimation::ExtendedKalmanFilter<Compass> ekf(Compass{}, zero, one, x0, one);
  expectCompassUpdate(ekfA, ekf);
  estimation::UnscentedKalmanFilter<Compass> ukfA(Compass{}, zero, one, x0, one, {},
                                                  kCompassAngles);
  estimation::UnscentedKalmanFilter<Compass> ukf(Compass{}, zero, one, x0, one);
  expectCompassUpdate(ukfA, ukf);
}

TEST(AngleInnovation, MahalanobisDistanceIsWrapped) {
  // KF prediction z^ = 3.1, covariance 1, R = 1: z = -3.1 is 2 pi - 6.2 away,
  // d^2 = (2 pi - 6.2)^2 / 2; linearly 6.2^2 / 2 = 19.22.
  const Matrix<1, 1> one = Matrix<1, 1>::Identity(), zero = Matrix<1, 1>::Zero();
  const Vector<1> x0 = Vector<1>::Constant(3.1);
  estimation::KalmanFilter<1, 1> kfA(one, Matrix<1, 0>(), one, zero, one, x0, one, kCompassAngles);
  estimation::KalmanFilter<1, 1> kf(one, Matrix<1, 0>(), one, zero, one, x0, one);
  estimation::MeasurementPrediction<1> pA, p;
  kfA.predictMeasurement(pA);
  kf.predictMeasurement(p);
  const double y = 2.0 * kPi - 6.2;
  EXPECT_NEAR(estimation::squaredMahalanobisDistance(pA, 0, -3.1), y * y / 2.0, 1e-12);
  EXPECT_NEAR(estimation::squaredMahalanobisDistance(
                  pA, Measurement<1>::complete(Vector<1>::Constant(-3.1))),
              y * y / 2.0, 1e-12);
  EXPECT_NEAR(estimation::squaredMahalanobisDistance(p, 0, -3.1), 19.22, 1e-12);
}

TEST(AngleParticles, CircularMeanOfParticlesAcrossPi) {
  // Particles of N(pi - 0.05, 0.01) straddle pi; a compass reading near -pi + 0.05
  // (= pi + 0.05) pulls them towards pi. With the declaration the estimate stays near pi
  // and its variance small; without, the linear mean of wrapped particles lands near 0.
  const Matrix<1, 1> q = Matrix<1, 1>::Constant(1e-4), r = Matrix<1, 1>::Constant(0.01);
  const Vector<1> x0 = Vector<1>::Constant(kPi - 0.05);
  const Matrix<1, 1> P0 = Matrix<1, 1>::Constant(0.01);
  estimation::ParticleFilterParameters params{2000, 5, 0.5, std::nullopt};
  estimation::ParticleFilterSIR<Compass> pf(Compass{}, q, r, x0, P0, params, kCompassAngles);
  const Measurement<1> z = Measurement<1>::complete(Vector<1>::Constant(-kPi + 0.05));
  for (int k = 0; k < 5; ++k) pf.estimate(z);
  // Product of N(pi - 0.05, ~0.01) and 5 readings of pi + 0.05 with variance 0.01: the
  // posterior mean is pi + 0.05 * (5 - 1) / 6 = pi + 0.0333, variance about 0.01 / 6.
  EXPECT_NEAR(wrapAngle(pf.state()(0) - (kPi + 0.0333)), 0.0, 0.01);
  EXPECT_LT(pf.covariance()(0, 0), 0.003);
  EXPECT_GT(pf.particles().cwiseAbs().minCoeff(), 2.5);  // wrapped, all near +-pi
  EXPECT_LE(pf.particles().maxCoeff(), kPi);

  // The same particles without the declaration (angle states wrapped by hand): the linear
  // mean and variance are those of values near +pi and -pi.
  Eigen::VectorXd w = (pf.logWeights().array()).exp();
  const double linear = pf.particles().row(0).dot(w);
  EXPECT_LT(std::abs(linear), 2.5);
}

// -------------------------------------------------------------------------------------------
// A heading integrated from a gyro alone.
// -------------------------------------------------------------------------------------------

/// State (theta, omega): theta' = theta + omega T wrapped to (-pi, pi] (atan2 of sin and cos,
/// as a user's model keeps a heading in range), omega' = omega; the gyro measures omega.
struct GyroHeading {
  static constexpr int StateSize = 2, MeasurementSize = 1, ControlSize = 0;
  double T = 0.1;
  Index stateSize() const { return 2; }
  Index measurementSize() const { return 1; }
  Index controlSize() const { return 0; }
  template <class S>
  void transition(const Eigen::Matrix<S, 2, 1>& x, const Vector<0>&,
                  Eigen::Matrix<S, 2, 1>& next) const {
    using std::atan2;
    using std::cos;
    using std::sin;
    const S theta = x(0) + x(1) * T;
    next(0) = atan2(sin(theta), cos(theta));
    next(1) = x(1);
  }
  template <class S>
  void observation(const Eigen::Matrix<S, 2, 1>& x, Eigen::Matrix<S, 1, 1>& z) const {
    z(0) = x(1);
  }
};

struct GyroRun {
  double maxHeadingDifference = 0.0;  // max |wrap(theta_ukf - theta_ekf)|
  double maxVarianceRelDiff = 0.0;    // max |P_ukf(0,0) - P_ekf(0,0)| / P_ekf(0,0)
  double maxHeadingVariance = 0.0;    // of the EKF
  bool finite = true;
  bool failed = false;  // the UKF threw NumericalError
  int steps = 0;
};

/// 10 minutes at 10 Hz: omega a slow random walk around 0.3 rad/s (the heading crosses +-pi
/// about every 20 s), a gyro with sigma 0.01 rad/s, no heading measurement. The heading's
/// process noise of 1e-3 rad^2 per step takes its variance to 6 rad^2.
GyroRun runGyroOnly(const estimation::UnscentedParameters& ut, const AngularComponents& angles) {
  const Matrix<2, 2> Q = Eigen::Vector2d(1e-3, 1e-6).asDiagonal();
  const Matrix<1, 1> R = Matrix<1, 1>::Constant(1e-4);
  const Vector<2> x0(0.0, 0.3);
  const Matrix<2, 2> P0 = Eigen::Vector2d(0.01, 0.01).asDiagonal();
  estimation::ExtendedKalmanFilter<GyroHeading> ekf(GyroHeading{}, Q, R, x0, P0);
  estimation::UnscentedKalmanFilter<GyroHeading> ukf(GyroHeading{}, Q, R, x0, P0, ut, angles);
  std::mt19937_64 rng(11);
  std::normal_distribution<double> normal(0.0, 1.0);
  double omega = 0.3;
  GyroRun run;
  for (int k = 0; k < 6000; ++k) {
    omega += 1e-3 * normal(rng);
    const Measurement<1> z =
        Measurement<1>::complete(Vector<1>::Constant(omega + 0.01 * normal(rng)));
    ekf.estimate(z);
    try {
      ukf.estimate(z);
    } catch (const estimation::NumericalError&) {
      run.failed = true;
      break;
    }
    ++run.steps;
    run.finite = run.finite && ukf.state().allFinite() && ukf.covariance().allFinite();
    if (!run.finite) break;
    run.maxHeadingDifference =
        std::max(run.maxHeadingDifference, std::abs(wrapAngle(ukf.state()(0) - ekf.state()(0))));
    run.maxVarianceRelDiff =
        std::max(run.maxVarianceRelDiff, std::abs(ukf.covariance()(0, 0) - ekf.covariance()(0, 0)) /
                                             ekf.covariance()(0, 0));
    run.maxHeadingVariance = std::max(run.maxHeadingVariance, ekf.covariance()(0, 0));
  }
  return run;
}

TEST(AngleLongRun, GyroOnlyHeadingUkfFollowsEkf) {
  // The model is linear in the chart around the central sigma point: theta + omega T, then a
  // wrap that the angle-aware mean and covariance undo. The unscented transform of a linear
  // map is exact, so the UKF equals the EKF up to rounding; the bound 1e-6 rad (and 1e-6
  // relative on the variance) leaves six orders of magnitude for the rounding of 6000 steps
  // and is a million times smaller than any averaging error (those are of order 1 rad).
  const AngularComponents heading{{0}, {}};
  for (const double alpha : {1e-3, 0.5}) {
    estimation::UnscentedParameters ut;
    ut.alpha = alpha;
    const GyroRun run = runGyroOnly(ut, heading);
    std::cout << "[ measured ] alpha " << alpha << ": " << run.steps
              << " steps, heading variance up to " << run.maxHeadingVariance
              << " rad^2, max |UKF - EKF| heading " << run.maxHeadingDifference
              << " rad, variance rel. " << run.maxVarianceRelDiff << "\n";
    EXPECT_FALSE(run.failed);
    EXPECT_TRUE(run.finite);
    EXPECT_EQ(run.steps, 6000);
    EXPECT_GT(run.maxHeadingVariance, 3.0);
    EXPECT_LT(run.maxHeadingDifference, 1e-6);
    EXPECT_LT(run.maxVarianceRelDiff, 1e-6);
  }
}

TEST(AngleLongRun, GyroOnlyHeadingWithoutDeclarationGoesWrong) {
  // The same run without declaring the heading: the first time the sigma points straddle
  // +-pi their linear mean and covariance are wrong by about 2 pi times the huge weights of
  // alpha = 1e-3; the UKF leaves the EKF by far more than a radian, or fails.
  const GyroRun run = runGyroOnly(estimation::UnscentedParameters{}, AngularComponents{});
  std::cout << "[ measured ] without the declaration: " << run.steps << " steps, failed "
            << run.failed << ", finite " << run.finite << ", max |UKF - EKF| heading "
            << run.maxHeadingDifference << " rad, variance rel. " << run.maxVarianceRelDiff << "\n";
  EXPECT_TRUE(run.failed || !run.finite || run.maxHeadingDifference > 1.0 ||
              run.maxVarianceRelDiff > 1.0);
}

// -------------------------------------------------------------------------------------------
// Factory.
// -------------------------------------------------------------------------------------------

TEST(AngleFactory, ParametersReachTheFilterAndAreChecked) {
  using estimation::EstimatorFactory;
  using estimation::ParameterError;
  const Eigen::MatrixXd one = Eigen::MatrixXd::Identity(1, 1);
  const Eigen::MatrixXd zero = Eigen::MatrixXd::Zero(1, 1);
  const Eigen::VectorXd x0 = Eigen::VectorXd::Constant(1, 3.1), index0 = Eigen::VectorXd::Zero(1);
  estimation::ParameterMap kf = {{"A", one},
                                 {"H", one},
                                 {"Q", zero},
                                 {"R", one},
                                 {"x0", x0},
                                 {"angle-states", index0},
                                 {"angle-measurements", index0}};
  auto filter = EstimatorFactory::create("KalmanFilter", kf);
  estimation::Input z;
  z.add(estimation::InputValue(-3.1));
  const estimation::Output out = filter->estimate(z);
  EXPECT_NEAR(wrapAngle(out[0].getValue() - kPi), 0.0, 1e-12);  // as in expectCompassUpdate

  kf["angle-states"] = Eigen::VectorXd(Eigen::VectorXd::Constant(1, 1.0));
  try {
    EstimatorFactory::create("KalmanFilter", kf);
    ADD_FAILURE() << "index 1 of a 1-state filter accepted";
  } catch (const ParameterError& e) {
    EXPECT_NE(std::string(e.what()).find("angle state index 1 is out of range"), std::string::npos)
        << e.what();
  }
  kf["angle-states"] = Eigen::VectorXd(Eigen::VectorXd::Constant(1, 0.5));
  EXPECT_THROW(EstimatorFactory::create("KalmanFilter", kf), ParameterError);
  kf["angle-states"] = Eigen::VectorXd(Eigen::VectorXd::Zero(2));  // listed twice
  EXPECT_THROW(EstimatorFactory::create("KalmanFilter", kf), ParameterError);
  kf["angle-states"] = 0;  // an int, not a vector
  EXPECT_THROW(EstimatorFactory::create("KalmanFilter", kf), ParameterError);
}

}  // namespace
