// Numerical robustness: a failed factorisation or a non-finite result is reported as
// NumericalError (not as NaN in the estimate) and leaves the filter as it was; long runs keep
// the covariance symmetric, finite and positive semi-definite.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <iostream>
#include <limits>
#include <random>
#include <string>

#include <gtest/gtest.h>

#include "filter_test_utils.hpp"
#include "sf_estimation/errors.hpp"
#include "sf_estimation/extended_kalman_filter.hpp"
#include "sf_estimation/kalman_filter.hpp"
#include "sf_estimation/models/navigation.hpp"
#include "sf_estimation/unscented_kalman_filter.hpp"

namespace {

using estimation::ExtendedKalmanFilter;
using estimation::Index;
using estimation::KalmanFilter;
using estimation::Matrix;
using estimation::Measurement;
using estimation::NumericalError;
using estimation::UnscentedKalmanFilter;
using estimation::UnscentedParameters;
using estimation::Vector;
using estimation::models::Nav3Ctrl;

// x' = x, z = x^2 (sftest::SquareModel): with a negative beta the unscented Pzz is
// negative (see below).
using sftest::SquareModel;

/// x' = exp(x), z = x (scalar): overflows for x > 709.
struct ExponentialModel {
  static constexpr int StateSize = 1;
  static constexpr int MeasurementSize = 1;
  static constexpr int ControlSize = 0;
  Index stateSize() const { return 1; }
  Index measurementSize() const { return 1; }
  Index controlSize() const { return 0; }
  template <class S>
  void transition(const Eigen::Matrix<S, 1, 1>& x, const Vector<0>&,
                  Eigen::Matrix<S, 1, 1>& next) const {
    using std::exp;
    next(0) = exp(x(0));
  }
  template <class S>
  void observation(const Eigen::Matrix<S, 1, 1>& x, Eigen::Matrix<S, 1, 1>& z) const {
    z(0) = x(0);
  }
};

TEST(NumericsInnovation, IndefiniteInnovationCovarianceInKalmanFilter) {
  // P = [1 1; 1 1 - 1e-13] passes the semi-definiteness check (its negative LDLT pivot
  // -1e-13 is within the 1e-12 relative rounding tolerance), but along H = [1 -1] it has
  // variance 1 - 2 + (1 - 1e-13) = -1e-13, more negative than R = 1e-20 is positive:
  // S = H P H^T + R < 0 has no Cholesky factor.
  Matrix<2, 2> P;
  P << 1.0, 1.0, 1.0, 1.0 - 1e-13;
  KalmanFilter<2, 1> kf(Matrix<2, 2>::Identity(), Matrix<2, 0>(),
                        (Matrix<1, 2>() << 1.0, -1.0).finished(), Matrix<2, 2>::Zero(),
                        Matrix<1, 1>::Constant(1e-20));
  kf.setBelief(Vector<2>(0.5, -0.5), P);
  const Vector<2> x = kf.state();
  const Matrix<2, 2> before = kf.covariance();
  try {
    kf.estimate(Measurement<1>::complete(Vector<1>::Constant(3.0)));
    ADD_FAILURE() << "no NumericalError; state " << kf.state().transpose();
  } catch (const NumericalError& e) {
    EXPECT_NE(std::string(e.what()).find("positive definite"), std::string::npos) << e.what();
  }
  EXPECT_EQ(kf.state(), x);
  EXPECT_EQ(kf.covariance(), before);
  // The filter still works: with the measurement missing it predicts as usual.
  kf.estimate(Measurement<1>::missing());
  EXPECT_EQ(kf.state(), x);
}

TEST(NumericsInnovation, NegativeUnscentedInnovationVariance) {
  // z = x^2, x ~ N(0, 1), alpha = 1, kappa = 0, beta = -10: by the closed form
  // Pzz = 4 m^2 P + (alpha^2 kappa + beta) P^2 = -10 (see test_unscented_kalman_filter.cpp), so
  // Szz = -10 + R < 0. The filter must refuse instead of producing NaN.
  UnscentedParameters params;
  params.alpha = 1.0;
  params.beta = -10.0;
  params.kappa = 0.0;
  UnscentedKalmanFilter<SquareModel> ukf(SquareModel{}, Matrix<1, 1>::Zero(),
                                         Matrix<1, 1>::Constant(1e-3), Vector<1>::Zero(),
                                         Matrix<1, 1>::Constant(1.0), params);
  EXPECT_THROW(ukf.estimate(Measurement<1>::complete(Vector<1>::Constant(2.0))), NumericalError);
  EXPECT_EQ(ukf.state()(0), 0.0);
  EXPECT_EQ(ukf.covariance()(0, 0), 1.0);
  // Without the measurement the step is a plain (valid) time update.
  ukf.estimate(Measurement<1>::missing());
  EXPECT_EQ(ukf.state()(0), 0.0);
  EXPECT_NEAR(ukf.covariance()(0, 0), 1.0, 1e-15);
}

TEST(NumericsOverflow, NonFiniteEstimateIsRejected) {
  // exp(800) overflows: the time update is not finite.
  ExtendedKalmanFilter<ExponentialModel> ekf(
      ExponentialModel{}, Matrix<1, 1>::Constant(0.1), Matrix<1, 1>::Constant(0.1),
      Vector<1>::Constant(800.0), Matrix<1, 1>::Constant(1.0));
  EXPECT_THROW(ekf.estimate(Measurement<1>::missing()), NumericalError);
  EXPECT_THROW(ekf.estimate(Measurement<1>::complete(Vector<1>::Constant(1.0))), NumericalError);
  EXPECT_EQ(ekf.state()(0), 800.0);
  EXPECT_EQ(ekf.covariance()(0, 0), 1.0);

  UnscentedKalmanFilter<ExponentialModel> ukf(
      ExponentialModel{}, Matrix<1, 1>::Constant(0.1), Matrix<1, 1>::Constant(0.1),
      Vector<1>::Constant(800.0), Matrix<1, 1>::Constant(1.0));
  EXPECT_THROW(ukf.estimate(Measurement<1>::complete(Vector<1>::Constant(1.0))), NumericalError);
  EXPECT_EQ(ukf.state()(0), 800.0);
  EXPECT_EQ(ukf.covariance()(0, 0), 1.0);

  // A belief from which the step is fine works afterwards.
  ekf.setBelief(Vector<1>::Constant(0.0), Matrix<1, 1>::Constant(1.0));
  ekf.estimate(Measurement<1>::missing());
  EXPECT_NEAR(ekf.state()(0), 1.0, 1e-15);          // exp(0)
  EXPECT_NEAR(ekf.covariance()(0, 0), 1.1, 1e-15);  // exp(0)^2 * 1 + 0.1
}

TEST(NumericsOverflow, HugeCovarianceGivesNumericalErrorNotNan) {
  // P = 1e100 (the largest covariance entry a filter accepts, parameter_checks.hpp) and
  // H = 1e210: P H^T = 1e310 and H P H^T overflow to inf, so the gain is inf / inf.
  KalmanFilter<1, 1> kf(Matrix<1, 1>::Constant(1.0), Matrix<1, 0>(), Matrix<1, 1>::Constant(1e210),
                        Matrix<1, 1>::Constant(0.0), Matrix<1, 1>::Constant(1.0),
                        Vector<1>::Constant(2.0), Matrix<1, 1>::Constant(1e100));
  EXPECT_THROW(kf.estimate(Measurement<1>::complete(Vector<1>::Constant(1.0))), NumericalError);
  EXPECT_EQ(kf.state()(0), 2.0);
  EXPECT_EQ(kf.covariance()(0, 0), 1e100);
}

// ---------------------------------------------------------------------------------------------
// Long runs.
// ---------------------------------------------------------------------------------------------

struct CovarianceHealth {
  double asymmetry = 0.0;                                               // max |P - P^T|
  double minEigenvalueRatio = std::numeric_limits<double>::infinity();  // lambda_min / lambda_max
  bool finite = true;
};

template <class Filter>
CovarianceHealth runNav3Ctrl(Filter& filter, int steps, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  std::normal_distribution<double> normal(0.0, 1.0);
  std::bernoulli_distribution missing(0.2);
  CovarianceHealth health;
  for (int k = 0; k < steps; ++k) {
    filter.setControl(Vector<2>(uniform(rng), 0.7 * uniform(rng)));
    Measurement<4> z(4);
    const double v = 0.5 + 0.5 * uniform(rng), omega = 0.7 * uniform(rng);
    z.value << omega + 0.013 * normal(rng), 0.5 * normal(rng),
        1000.0 * (v - 0.3 * omega) + 1.4 * normal(rng),
        1000.0 * (v + 0.3 * omega) + 1.4 * normal(rng);
    for (Index i = 0; i < 4; ++i) z.available(i) = !missing(rng);
    filter.estimate(z);
    const Matrix<7, 7> P = filter.covariance();
    health.finite = health.finite && P.allFinite() && filter.state().allFinite();
    health.asymmetry = std::max(health.asymmetry, (P - P.transpose()).cwiseAbs().maxCoeff());
    if (k % 100 == 99) {
      const Vector<7> eig = sftest::symmetricEigenvalues(P);
      health.minEigenvalueRatio = std::min(health.minEigenvalueRatio, eig(0) / eig(6));
    }
  }
  return health;
}

TEST(NumericsLongRun, Nav3CtrlCovarianceStaysSymmetricOver10000Steps) {
  const Matrix<7, 7> Q = estimation::models::nav3ProcessNoise();
  const Matrix<4, 4> R = estimation::models::nav3MeasurementNoise();
  const Matrix<7, 7> P0 = Matrix<7, 7>::Identity() * 0.1;
  ExtendedKalmanFilter<Nav3Ctrl> ekf(Nav3Ctrl{}, Q, R, Vector<7>::Zero(), P0);
  UnscentedKalmanFilter<Nav3Ctrl> ukf(Nav3Ctrl{}, Q, R, Vector<7>::Zero(), P0);
  UnscentedParameters one;
  one.alpha = 1.0;
  UnscentedKalmanFilter<Nav3Ctrl> ukf1(Nav3Ctrl{}, Q, R, Vector<7>::Zero(), P0, one);
  const CovarianceHealth e = runNav3Ctrl(ekf, 10000, 71);
  const CovarianceHealth u = runNav3Ctrl(ukf, 10000, 71);
  const CovarianceHealth u1 = runNav3Ctrl(ukf1, 10000, 71);
  std::cout << "[ measured ] 10000 nav3ctrl steps: EKF asymmetry " << e.asymmetry
            << ", min eig ratio " << e.minEigenvalueRatio << "; UKF default " << u.asymmetry << ", "
            << u.minEigenvalueRatio << "; UKF alpha=1 " << u1.asymmetry << ", "
            << u1.minEigenvalueRatio << "\n";
  for (const CovarianceHealth& h : {e, u, u1}) {
    EXPECT_TRUE(h.finite);
    EXPECT_EQ(h.asymmetry, 0.0);  // symmetric to the last bit
    // Positive semi-definite up to rounding relative to the largest eigenvalue.
    EXPECT_GE(h.minEigenvalueRatio, -1e-12);
  }
}

}  // namespace
