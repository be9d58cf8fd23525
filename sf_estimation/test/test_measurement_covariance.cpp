// Covariances between measurement entries (a sensor's covariance block, measurement.hpp,
// measurement_noise.hpp): they replace R's off-diagonal entries for one step, are used only
// between present entries (the block is reduced exactly as R is for missing rows), and a block
// that is not a covariance is refused before the filter changes. Checked against a Kalman
// update computed by hand; the EKF and UKF on the same linear model must agree with it.
#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include "sf_estimation/errors.hpp"
#include "sf_estimation/extended_kalman_filter.hpp"
#include "sf_estimation/kalman_filter.hpp"
#include "sf_estimation/measurement_noise.hpp"
#include "sf_estimation/unscented_kalman_filter.hpp"

namespace {

using estimation::Matrix;
using estimation::Measurement;
using estimation::Vector;

/// x' = x (2 states, a position x, y), z = (x, y, x): two sensors of x, one of y.
struct Position {
  static constexpr int StateSize = 2, MeasurementSize = 3, ControlSize = 0;
  estimation::Index stateSize() const { return 2; }
  estimation::Index measurementSize() const { return 3; }
  estimation::Index controlSize() const { return 0; }
  template <class S>
  void transition(const Eigen::Matrix<S, 2, 1>& x, const Vector<0>&,
                  Eigen::Matrix<S, 2, 1>& next) const {
    next = x;
  }
  template <class S>
  void observation(const Eigen::Matrix<S, 2, 1>& x, Eigen::Matrix<S, 3, 1>& z) const {
    z << x(0), x(1), x(0);
  }
};

Matrix<3, 2> observationMatrix() {
  Matrix<3, 2> H;
  H << 1, 0, 0, 1, 1, 0;
  return H;
}

/// R of the header: 4 on the diagonal, uncorrelated; Q = 0; x0 = 0, P0 = I.
Matrix<3, 3> headerR() { return Matrix<3, 3>::Identity() * 4.0; }

estimation::KalmanFilter<2, 3, 0> makeKalman() {
  return {Matrix<2, 2>::Identity(), Matrix<2, 0>(), observationMatrix(),
          Matrix<2, 2>::Zero(),     headerR(),      Vector<2>::Zero(),
          Matrix<2, 2>::Identity()};
}

/// z = (1, 2, -), a pose's x and y with the block [[1, 0.5], [0.5, 1]]; the third entry
/// missing, with covariances to it given (they must be ignored).
Measurement<3> correlatedPose() {
  Measurement<3> z;
  z.value << 1.0, 2.0, 7.0;
  z.available << true, true, false;
  z.varianceGiven << true, true, false;
  z.variance << 1.0, 1.0, 0.0;
  z.covarianceGiven << false, true, true, true, false, true, true, true, false;
  z.covariance << 0.0, 0.5, 0.3, 0.5, 0.0, 0.3, 0.3, 0.3, 0.0;
  return z;
}

// By hand: P- = I, R = [[1, .5], [.5, 1]] on the present rows, S = [[2, .5], [.5, 2]],
// det S = 3.75, K = P- S^-1 = S^-1 = [[2, -.5], [-.5, 2]] / 3.75;
// x = K z = (2 - 1, -.5 + 4) / 3.75 = (1, 3.5) / 3.75, P = I - K.
const Vector<2> kState(1.0 / 3.75, 3.5 / 3.75);
Matrix<2, 2> handCovariance() {
  Matrix<2, 2> P;
  P << 1.0 - 2.0 / 3.75, 0.5 / 3.75, 0.5 / 3.75, 1.0 - 2.0 / 3.75;
  return P;
}

template <class Filter>
void expectHandUpdate(const Filter& f, double tolerance) {
  EXPECT_NEAR((f.state() - kState).norm(), 0.0, tolerance) << f.state().transpose();
  EXPECT_NEAR((f.covariance() - handCovariance()).norm(), 0.0, tolerance) << f.covariance();
}

TEST(MeasurementCovariance, KalmanUpdateWithACorrelatedBlockByHand) {
  auto kf = makeKalman();
  kf.estimate(correlatedPose());
  expectHandUpdate(kf, 1e-14);
  // Without the correlation the same variances give x = (1, 2) / 2.
  auto uncorrelated = makeKalman();
  Measurement<3> z = correlatedPose();
  z.covarianceGiven.setConstant(false);
  uncorrelated.estimate(z);
  EXPECT_NEAR(uncorrelated.state()(1), 1.0, 1e-14);
  EXPECT_GT(std::abs(kf.state()(1) - uncorrelated.state()(1)), 0.05);
}

TEST(MeasurementCovariance, EffectiveNoiseKeepsOnlyThePresentBlock) {
  Matrix<3, 3> R;
  estimation::effectiveMeasurementNoise(headerR(), correlatedPose(), R);
  Matrix<3, 3> expected;
  expected << 1.0, 0.5, 0.0, 0.5, 1.0, 0.0, 0.0, 0.0, 1.0;  // missing row: identity, decoupled
  EXPECT_EQ(R, expected);
}

TEST(MeasurementCovariance, ExtendedAndUnscentedFiltersAgreeOnTheLinearModel) {
  estimation::ExtendedKalmanFilter<Position> ekf(Position{}, Matrix<2, 2>::Zero(), headerR(),
                                                 Vector<2>::Zero(), Matrix<2, 2>::Identity());
  ekf.estimate(correlatedPose());
  expectHandUpdate(ekf, 1e-12);
  estimation::UnscentedKalmanFilter<Position> ukf(Position{}, Matrix<2, 2>::Zero(), headerR(),
                                                  Vector<2>::Zero(), Matrix<2, 2>::Identity());
  ukf.estimate(correlatedPose());
  expectHandUpdate(ukf, 1e-9);
}

/// The message of the InvalidInputError the Kalman filter throws for z; the filter must be
/// left as it was.
std::string refusal(const Measurement<3>& z) {
  auto kf = makeKalman();
  try {
    kf.estimate(z);
  } catch (const estimation::InvalidInputError& e) {
    EXPECT_EQ(kf.state(), Vector<2>::Zero());
    EXPECT_EQ(kf.covariance(), (Matrix<2, 2>::Identity()));
    return e.what();
  }
  return "accepted";
}

TEST(MeasurementCovariance, ABlockThatIsNoCovarianceIsRefusedAndTheFilterUnchanged) {
  Measurement<3> z = correlatedPose();
  z.covariance(0, 1) = z.covariance(1, 0) = 1.5;  // |c| > sqrt(1 * 1)
  EXPECT_EQ(refusal(z), "covariance block of measurements 0, 1 is not positive definite");
  z = correlatedPose();
  z.covariance(0, 1) = 0.4;
  EXPECT_EQ(refusal(z), "covariance of measurements 0 and 1 is not symmetric");
  z = correlatedPose();
  z.covariance(0, 1) = z.covariance(1, 0) = NAN;
  EXPECT_EQ(refusal(z), "covariance of measurements 0 and 1 is not finite");
  z = correlatedPose();
  z.varianceGiven(1) = false;
  EXPECT_EQ(refusal(z), "covariance of measurements 0 and 1 is given without both their variances");
}

}  // namespace
