// Tests of UnscentedKalmanFilter (thesis Algorithm 3.3): on linear models it must be the
// Kalman filter for any alpha; one nonlinear step is checked against the closed-form
// unscented moments of z = x^2; and on nav3ctrl the gyro and wheels must correct omega even
// though the transition sets omega = u1.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <iostream>
#include <ostream>
#include <vector>

#include <gtest/gtest.h>

#include "filter_test_utils.hpp"
#include "sf_estimation/extended_kalman_filter.hpp"
#include "sf_estimation/kalman_filter.hpp"
#include "sf_estimation/models/moving_train.hpp"
#include "sf_estimation/models/navigation.hpp"
#include "sf_estimation/unscented_kalman_filter.hpp"

namespace {

using estimation::ExtendedKalmanFilter;
using estimation::KalmanFilter;
using estimation::Matrix;
using estimation::Measurement;
using estimation::UnscentedKalmanFilter;
using estimation::UnscentedParameters;
using estimation::Vector;
using estimation::models::MovingTrain;
using estimation::models::Nav3Ctrl;
using estimation::models::Nav3Reduced;
using sftest::relDiff;

using sftest::alphaOne;

/// Differences of UKF and KF over a run: per step relative to that step's KF values, and
/// relative to the largest KF values of the whole run (the scale of the data).
struct Differences {
  double stateStep = 0.0, covarianceStep = 0.0, stateRun = 0.0, covarianceRun = 0.0;
};

std::ostream& operator<<(std::ostream& os, const Differences& d) {
  return os << "state " << d.stateStep << " (run scale " << d.stateRun << "), covariance "
            << d.covarianceStep << " (run scale " << d.covarianceRun << ")";
}

template <class Model, int N = Model::StateSize, int M = Model::MeasurementSize,
          int L = Model::ControlSize>
Differences compareWithKalman(const Model& model, const Matrix<N, N>& A, const Matrix<N, L>& B,
                              const Matrix<M, N>& H, const Matrix<N, N>& Q, const Matrix<M, M>& R,
                              const Vector<N>& x0, const Matrix<N, N>& P0,
                              const UnscentedParameters& params,
                              const std::vector<sftest::Step<M, L>>& run) {
  KalmanFilter<N, M, L> kf(A, B, H, Q, R, x0, P0);
  UnscentedKalmanFilter<Model> ukf(model, Q, R, x0, P0, params);
  Differences d;
  double stateAbs = 0.0, covAbs = 0.0, stateScale = 0.0, covScale = 0.0;
  for (const auto& step : run) {
    kf.setControl(step.u);
    ukf.setControl(step.u);
    kf.estimate(step.z);
    ukf.estimate(step.z);
    d.stateStep = std::max(d.stateStep, relDiff(ukf.state(), kf.state()));
    d.covarianceStep = std::max(d.covarianceStep, relDiff(ukf.covariance(), kf.covariance()));
    stateAbs = std::max(stateAbs, sftest::maxAbsDiff(ukf.state(), kf.state()));
    covAbs = std::max(covAbs, sftest::maxAbsDiff(ukf.covariance(), kf.covariance()));
    stateScale = std::max(stateScale, sftest::scaleOf(kf.state()));
    covScale = std::max(covScale, sftest::scaleOf(kf.covariance()));
  }
  d.stateRun = stateAbs / stateScale;
  d.covarianceRun = covAbs / covScale;
  return d;
}

// The default alpha = 1e-3 (kappa = 0) is mathematically equal to any other alpha on a linear
// model, but not numerically. Rounding argument: the mean weights are W0 = 1 - 1/alpha^2 =
// -999999 and W1..W2n = 1/(2 alpha^2), so sum |W_i| = 2/alpha^2 = 2e6 and each weighted mean
// (predicted state, predicted measurement) cancels terms 2e6 times larger than its result.
// Summing 2n+1 terms then carries an error up to 2n * u * 2e6 * |terms| (u = 1.1e-16 unit
// rounding). The error of a predicted measurement reaches the state through the gain, so
// per step
//   |error of x| <~ 2n * u * 2e6 * G * |x|,  G = max |K| |z| / |x|
// (the covariances are hardly affected: the pairwise symmetric points cancel a mean error in
// the centred differences). The filter damps errors of earlier steps, so they do not add up.
//   * moving train (n = 2, z = x, |K| <= 1, G ~ 1):  4 * 1.1e-16 * 2e6 = 8.8e-10 -> 1e-9.
//   * nav3red (n = 3): the wheels report 1000 |v| mm/s and the gain of the acceleration
//     a' = (u0 - v)/T on a wheel is ~(1/T)/2000 = 5e-3 s^-2 per mm/s, G ~ 1000 * 5e-3 = 5:
//     6 * 1.1e-16 * 2e6 * 5 = 6.6e-9 -> 1e-8, relative to the scale of the run (the error is
//     absolute, set by the magnitudes the filter averages, not by the state of one step, so
//     the per-step relative difference is larger when the state passes near zero).
// Measured (printed below): train ~4e-10; nav3red ~3e-9 per step and ~1e-9 on the run scale,
// i.e. the default alpha does NOT reach 1e-9 on nav3red; alpha = 1 reaches ~1e-13.
constexpr double kTrainDefaultAlphaTolerance = 1e-9;
constexpr double kNav3DefaultAlphaTolerance = 1e-8;

TEST(UnscentedKalmanFilterLinear, MovingTrainEqualsKalmanFilterForAnyAlpha) {
  const MovingTrain train;
  Matrix<2, 2> Q;
  Q << 0.02, 0.001, 0.001, 0.05;
  Matrix<2, 2> R;
  R << 0.4, 0.02, 0.02, 0.1;
  const Vector<2> x0(1.0, 0.5);
  const Matrix<2, 2> P0 = Matrix<2, 2>::Identity();
  const auto run =
      sftest::simulateLinear<2, 2, 0>(train.transitionMatrix(), train.controlMatrix(),
                                      train.observationMatrix(), Q, R, x0, 500, 21, 0.3, 10, 0.0);
  const auto one = compareWithKalman(train, train.transitionMatrix(), train.controlMatrix(),
                                     train.observationMatrix(), Q, R, x0, P0, alphaOne(), run);
  const auto def =
      compareWithKalman(train, train.transitionMatrix(), train.controlMatrix(),
                        train.observationMatrix(), Q, R, x0, P0, UnscentedParameters{}, run);
  std::cout << "[ measured ] UKF vs KF, moving train, 500 steps, alpha=1: " << one
            << "\n[ measured ] UKF vs KF, moving train, 500 steps, default alpha: " << def << "\n";
  EXPECT_LE(one.stateStep, 1e-9);
  EXPECT_LE(one.covarianceStep, 1e-9);
  EXPECT_LE(def.stateStep, kTrainDefaultAlphaTolerance);
  EXPECT_LE(def.covarianceStep, kTrainDefaultAlphaTolerance);
}

void checkNav3Reduced(const Matrix<4, 4>& R, std::uint64_t seed, const char* label) {
  const Nav3Reduced model;
  const Matrix<3, 3> Q = estimation::models::nav3ReducedProcessNoise();
  const Vector<3> x0(0.1, 0.2, 0.0);
  const Matrix<3, 3> P0 = Vector<3>(0.3, 0.2, 0.1).asDiagonal();
  const auto run = sftest::simulateNav3Drive(1000, seed, 0.3, 7);
  const auto one = compareWithKalman(model, model.transitionMatrix(), model.controlMatrix(),
                                     model.observationMatrix(), Q, R, x0, P0, alphaOne(), run);
  UnscentedParameters other;
  other.alpha = 0.5;
  other.beta = 0.0;
  other.kappa = 1.0;
  const auto alt = compareWithKalman(model, model.transitionMatrix(), model.controlMatrix(),
                                     model.observationMatrix(), Q, R, x0, P0, other, run);
  const auto def =
      compareWithKalman(model, model.transitionMatrix(), model.controlMatrix(),
                        model.observationMatrix(), Q, R, x0, P0, UnscentedParameters{}, run);
  std::cout << "[ measured ] UKF vs KF, nav3red " << label << ", 1000 steps, alpha=1: " << one
            << "\n[ measured ] UKF vs KF, nav3red " << label
            << ", alpha=0.5 beta=0 kappa=1: " << alt << "\n[ measured ] UKF vs KF, nav3red "
            << label << ", default alpha: " << def << "\n";
  EXPECT_LE(one.stateStep, 1e-9);
  EXPECT_LE(one.covarianceStep, 1e-9);
  EXPECT_LE(alt.stateStep, 1e-9);
  EXPECT_LE(alt.covarianceStep, 1e-9);
  EXPECT_LE(def.stateRun, kNav3DefaultAlphaTolerance);
  EXPECT_LE(def.covarianceRun, kNav3DefaultAlphaTolerance);
  EXPECT_LE(def.covarianceStep, kNav3DefaultAlphaTolerance);
}

TEST(UnscentedKalmanFilterLinear, Nav3ReducedWithControlsEqualsKalmanFilterForAnyAlpha) {
  checkNav3Reduced(estimation::models::nav3MeasurementNoise(), 22, "diagonal R");
}

TEST(UnscentedKalmanFilterLinear, CorrelatedNoiseNav3ReducedEqualsKalmanFilter) {
  checkNav3Reduced(sftest::correlatedNav3MeasurementNoise(), 23, "correlated R");
}

using sftest::ShiftSquareModel;

// Closed-form unscented moments of z = x^2 for n = 1, mean m, variance P. With
// s = n + lambda = alpha^2 (1 + kappa), the points are m and m +- c, c^2 = s P, and the weights
// W0 = 1 - 1/s, Wi = 1/(2s), Wc0 = W0 + 1 - alpha^2 + beta:
//   zMean = W0 m^2 + (1 - W0)(m^2 + c^2)           = m^2 + P
//   Pxz   = Wi [c (2mc + c^2 - P) - c (-2mc + c^2 - P)] = 4 m c^2 Wi = 2 m P
//   Pzz   = Wc0 P^2 + Wi [(2mc + c^2 - P)^2 + (-2mc + c^2 - P)^2]
//         = Wc0 P^2 + (4 m^2 c^2 + (c^2 - P)^2) / s = 4 m^2 P + (alpha^2 kappa + beta) P^2
// Step: x0 = 1, P0 = 0.5, Q = 0.1, R = 0.2, z = 5 -> predicted m = 2, P = 0.6 (linear f is
// exact), zMean = 4.6, Pxz = 2.4, Szz = 9.6 + (alpha^2 kappa + beta) 0.36 + 0.2,
// K = 2.4 / Szz, x = 2 + K (5 - 4.6), P = 0.6 - 2.4^2 / Szz.
void checkSquareStep(const UnscentedParameters& params, double tolerance) {
  UnscentedKalmanFilter<ShiftSquareModel> ukf(ShiftSquareModel{}, Matrix<1, 1>::Constant(0.1),
                                              Matrix<1, 1>::Constant(0.2), Vector<1>::Constant(1.0),
                                              Matrix<1, 1>::Constant(0.5), params);
  ukf.estimate(Measurement<1>::complete(Vector<1>::Constant(5.0)));
  const double a2k = params.alpha * params.alpha * params.kappa;
  const double Szz = 9.6 + (a2k + params.beta) * 0.36 + 0.2;
  EXPECT_NEAR(ukf.state()(0), 2.0 + 2.4 / Szz * 0.4, tolerance);
  EXPECT_NEAR(ukf.covariance()(0, 0), 0.6 - 2.4 * 2.4 / Szz, tolerance);
}

TEST(UnscentedKalmanFilterNonlinear, SquareObservationMatchesClosedFormMoments) {
  UnscentedParameters p;
  p.alpha = 1.0;
  p.beta = 2.0;
  p.kappa = 2.0;  // Szz = 9.6 + 4 * 0.36 + 0.2 = 11.24
  checkSquareStep(p, 1e-14);
  p.alpha = 0.5;
  p.beta = 0.0;
  p.kappa = 1.0;
  checkSquareStep(p, 1e-14);
  // Default alpha = 1e-3, kappa = 0: Szz = 9.6 + 0.72 + 0.2. The weights are ~1e6 (see the
  // rounding argument above), the terms cancelled are ~1e6 * m^2 = 4e6, so the absolute
  // rounding is ~4e6 * 1.1e-16 = 4.4e-10 per sum; 1e-9 is the matching tolerance.
  checkSquareStep(UnscentedParameters{}, 1e-9);
}

// ---------------------------------------------------------------------------------------------
// nav3ctrl: omega is corrected by gyro and wheels although omega' = u1.
// ---------------------------------------------------------------------------------------------
//
// Start x0 = 0, P0 = 0.1 I, u = (0, 0). The prediction gives omega- = u1 = 0 with variance
// Q(3,3) = 0.5 and no correlation with the other states (its transition row is zero), and
// v-, a- do not depend on omega. The observation is linear: gyro z0 = omega (R = 1.7e-4),
// accelerometer z1 = a, wheels z2 = 1000 (v - R omega), z3 = 1000 (v + R omega), each wheel with
// variance 2 (mm/s)^2. The wheel difference d = (z3 - z2) / (2000 R) measures omega alone with
// variance (2 + 2) / (2000 * 0.3)^2 = 1/90000, and its noise is independent of the wheel sum
// (equal variances), which measures v. So, with the gyro and wheels reporting omega = 0.3:
//   omega+ = (0.3 / 1.7e-4 + 0.3 * 90000) / (1/0.5 + 1/1.7e-4 + 90000)
//   var+   = 1 / (1/0.5 + 1/1.7e-4 + 90000)
// and with only the gyro, or only the wheels, the corresponding terms drop out.
struct OmegaCase {
  bool gyro, wheels;
};

void checkOmegaCorrection(const OmegaCase& c, double ukfTolerance) {
  const Nav3Ctrl model;
  const Matrix<7, 7> Q = estimation::models::nav3ProcessNoise();
  const Matrix<4, 4> R = estimation::models::nav3MeasurementNoise();
  const Vector<7> x0 = Vector<7>::Zero();
  const Matrix<7, 7> P0 = Matrix<7, 7>::Identity() * 0.1;

  Measurement<4> z(4);
  z.value << 0.3, 0.0, -0.3 * 0.3 * 1000.0, 0.3 * 0.3 * 1000.0;
  z.available << c.gyro, true, c.wheels, c.wheels;

  const double gyroPrecision = c.gyro ? 1.0 / 1.7e-4 : 0.0;
  const double wheelPrecision = c.wheels ? 90000.0 : 0.0;
  const double precision = 1.0 / 0.5 + gyroPrecision + wheelPrecision;
  const double expectedOmega = 0.3 * (gyroPrecision + wheelPrecision) / precision;
  const double expectedVariance = 1.0 / precision;

  ExtendedKalmanFilter<Nav3Ctrl> ekf(model, Q, R, x0, P0);
  UnscentedKalmanFilter<Nav3Ctrl> ukf(model, Q, R, x0, P0);
  UnscentedKalmanFilter<Nav3Ctrl> ukf1(model, Q, R, x0, P0, alphaOne());
  ekf.estimate(z);
  ukf.estimate(z);
  ukf1.estimate(z);

  // "Clearly towards 0.3": at least 99.9 % of the way from the prior 0.
  EXPECT_GT(ukf.state()(3), 0.2997);
  EXPECT_NEAR(ekf.state()(3), expectedOmega, 1e-12);
  EXPECT_NEAR(ekf.covariance()(3, 3), expectedVariance, 1e-14);
  EXPECT_NEAR(ukf1.state()(3), expectedOmega, 1e-12);
  EXPECT_NEAR(ukf1.covariance()(3, 3), expectedVariance, 1e-14);
  EXPECT_NEAR(ukf.state()(3), expectedOmega, ukfTolerance);
  EXPECT_NEAR(ukf.covariance()(3, 3), expectedVariance, ukfTolerance);
  // h is linear and the (omega, v, a) block of the prediction is linear, so EKF and UKF agree
  // on omega, v and a.
  for (int i : {3, 5, 6}) {
    EXPECT_NEAR(ukf.state()(i), ekf.state()(i), ukfTolerance) << "state " << i;
    EXPECT_NEAR(ukf1.state()(i), ekf.state()(i), 1e-12) << "state " << i;
  }
  std::cout << "[ measured ] nav3ctrl omega (gyro=" << c.gyro << ", wheels=" << c.wheels
            << "): expected " << expectedOmega << ", EKF diff "
            << std::abs(ekf.state()(3) - expectedOmega) << ", UKF default diff "
            << std::abs(ukf.state()(3) - expectedOmega) << ", UKF alpha=1 diff "
            << std::abs(ukf1.state()(3) - expectedOmega) << "\n";
}

// UKF default alpha, by the rounding argument above: the prior mean is 0, so the averaged
// quantities are only the sigma-point spreads, at most sqrt(3e-6 * 0.5) * 1000 * (1 + 0.3) ~
// 1.6 mm/s for the wheels, mapped to omega by the wheel gain ~1/(2000 R) = 1.7e-3 rad/s per
// mm/s: 2n * u * 2e6 * 1.6 * 1.7e-3 = 14 * 1.1e-16 * 2e6 * 2.7e-3 ~ 8e-12 -> 1e-11.
TEST(UnscentedKalmanFilterNav3Ctrl, GyroAndWheelsCorrectOmega) {
  checkOmegaCorrection({true, true}, 1e-11);
}

TEST(UnscentedKalmanFilterNav3Ctrl, GyroAloneCorrectsOmega) {
  checkOmegaCorrection({true, false}, 1e-11);
}

TEST(UnscentedKalmanFilterNav3Ctrl, WheelsAloneCorrectOmega) {
  checkOmegaCorrection({false, true}, 1e-11);
}

TEST(UnscentedKalmanFilterNav3Ctrl, ConstructorRefusesInvalidScaling) {
  UnscentedParameters p;
  p.alpha = 0.0;
  EXPECT_THROW(UnscentedKalmanFilter<Nav3Ctrl>(Nav3Ctrl{}, estimation::models::nav3ProcessNoise(),
                                               estimation::models::nav3MeasurementNoise(),
                                               Vector<7>::Zero(), Matrix<7, 7>::Identity(), p),
               estimation::ParameterError);
  p.alpha = 1.0;
  p.kappa = -7.0;  // n + lambda = alpha^2 (n + kappa) = 0
  EXPECT_THROW(UnscentedKalmanFilter<Nav3Ctrl>(Nav3Ctrl{}, estimation::models::nav3ProcessNoise(),
                                               estimation::models::nav3MeasurementNoise(),
                                               Vector<7>::Zero(), Matrix<7, 7>::Identity(), p),
               estimation::ParameterError);
}

// ---------------------------------------------------------------------------------------------
// The predicted mean (PredictedMean): the sigma points' weighted mean or f of the mean itself.
// ---------------------------------------------------------------------------------------------
//
// A unicycle x = (px, py, theta, v) stepping T = 1 s: px' = px + v cos(theta), py' = py +
// v sin(theta), theta' = theta, v' = v; z = v. From theta = 0 with variance 1 rad^2 and the
// other variances 1e-6, alpha = 1, kappa = 0 (n = 4, lambda = 0): eight sigma points of
// weight 1/8 and a central one of weight 0. Six of them have theta = 0 and step px by their
// own v, which averages to 1; two have theta = +-sqrt(4 * 1) = +-2 and step px by cos(2). So
//   sigma-point average: px' = (6 + 2 cos 2) / 8 = 0.75 + 0.25 cos 2 = 0.6460 (shrunk),
//   propagated mean:     px' = 0 + 1 * cos 0 = 1 (the step's length kept).
// The covariance is the same computation in both (around the points' mean).
struct Unicycle {
  static constexpr int StateSize = 4, MeasurementSize = 1, ControlSize = 0;
  estimation::Index stateSize() const { return 4; }
  estimation::Index measurementSize() const { return 1; }
  estimation::Index controlSize() const { return 0; }
  template <class S>
  void transition(const Eigen::Matrix<S, 4, 1>& x, const Vector<0>&,
                  Eigen::Matrix<S, 4, 1>& next) const {
    using std::cos;
    using std::sin;
    next << x(0) + x(3) * cos(x(2)), x(1) + x(3) * sin(x(2)), x(2), x(3);
  }
  template <class S>
  void observation(const Eigen::Matrix<S, 4, 1>& x, Eigen::Matrix<S, 1, 1>& z) const {
    z << x(3);
  }
};

UnscentedKalmanFilter<Unicycle> unicycleFilter(estimation::PredictedMean mean) {
  UnscentedParameters p = alphaOne();
  p.predictedMean = mean;
  const Matrix<4, 4> P0 = Vector<4>(1e-6, 1e-6, 1.0, 1e-6).asDiagonal();
  return UnscentedKalmanFilter<Unicycle>(Unicycle{}, Matrix<4, 4>::Zero(),
                                         Matrix<1, 1>::Constant(0.01), Vector<4>(0, 0, 0, 1), P0, p,
                                         estimation::AngularComponents{{2}, {}});
}

TEST(UnscentedKalmanFilterPredictedMean, PropagatedMeanKeepsTheStepOfAnUncertainHeading) {
  auto average = unicycleFilter(estimation::PredictedMean::SigmaPointAverage);
  auto propagated = unicycleFilter(estimation::PredictedMean::Propagated);
  Measurement<1> none(1);
  none.available << false;
  average.estimate(none);
  propagated.estimate(none);
  EXPECT_NEAR(average.state()(0), 0.75 + 0.25 * std::cos(2.0), 1e-12);
  EXPECT_NEAR(propagated.state()(0), 1.0, 1e-15);
  EXPECT_NEAR(propagated.state()(1), 0.0, 1e-15);
  EXPECT_NEAR(propagated.state()(3), 1.0, 1e-15);
  EXPECT_TRUE(average.covariance() == propagated.covariance());
}

TEST(UnscentedKalmanFilterPredictedMean, PropagatedMeanEqualsKalmanFilterOnLinearModels) {
  const Nav3Reduced model;
  const Matrix<3, 3> Q = estimation::models::nav3ReducedProcessNoise();
  const Matrix<4, 4> R = estimation::models::nav3MeasurementNoise();
  const Vector<3> x0(0.1, 0.2, 0.0);
  const Matrix<3, 3> P0 = Vector<3>(0.3, 0.2, 0.1).asDiagonal();
  const auto run = sftest::simulateNav3Drive(1000, 5, 0.3, 7);
  UnscentedParameters p = alphaOne();
  p.predictedMean = estimation::PredictedMean::Propagated;
  const auto d = compareWithKalman(model, model.transitionMatrix(), model.controlMatrix(),
                                   model.observationMatrix(), Q, R, x0, P0, p, run);
  std::cout << "[ measured ] UKF (propagated mean) vs KF, nav3red, 1000 steps: " << d << "\n";
  EXPECT_LE(d.stateStep, 1e-9);
  EXPECT_LE(d.covarianceStep, 1e-9);
}

}  // namespace
