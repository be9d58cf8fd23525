// Tests of the predicted measurement and innovation covariance every model-based filter gives
// (measurement_prediction.hpp) and of the squared Mahalanobis distance computed from them:
// hand computations for the Kalman filter in one and two dimensions, the UKF equal to the KF
// on a linear model, the EKF on z = x^2 by hand, and the particle filter equal to the moments
// of the particles its next step draws.
#include <cmath>
#include <cstring>
#include <limits>
#include <random>

#include <Eigen/Cholesky>

#include <gtest/gtest.h>

#include "filter_test_utils.hpp"
#include "sf_estimation/extended_kalman_filter.hpp"
#include "sf_estimation/function_model.hpp"
#include "sf_estimation/kalman_filter.hpp"
#include "sf_estimation/measurement_prediction.hpp"
#include "sf_estimation/models/moving_train.hpp"
#include "sf_estimation/moving_average.hpp"
#include "sf_estimation/particle_filter.hpp"
#include "sf_estimation/unscented_kalman_filter.hpp"

namespace {

using estimation::ExtendedKalmanFilter;
using estimation::KalmanFilter;
using estimation::Matrix;
using estimation::Measurement;
using estimation::MeasurementPrediction;
using estimation::ParticleFilterSIR;
using estimation::squaredMahalanobisDistance;
using estimation::UnscentedKalmanFilter;
using estimation::Vector;
using estimation::models::MovingTrain;

static_assert(estimation::HasMeasurementPrediction<KalmanFilter<2, 2, 0>>::value,
              "the Kalman filter predicts its measurement");
static_assert(estimation::HasMeasurementPrediction<UnscentedKalmanFilter<MovingTrain>>::value,
              "the UKF predicts its measurement");
static_assert(estimation::HasMeasurementPrediction<ParticleFilterSIR<MovingTrain>>::value,
              "the particle filter predicts its measurement");
static_assert(!estimation::HasMeasurementPrediction<estimation::MovingAverage>::value,
              "a moving average has no model, hence no predicted measurement");

TEST(MeasurementPrediction, KalmanFilterOneDimensionByHand) {
  // x' = x + 0.5 u, z = x; x0 = 2, P0 = 1, Q = 0.5, R = 0.25, u = 2.
  //   x- = 2 + 0.5 * 2 = 3,  P- = 1 + 0.5 = 1.5,  z^ = 3,  S = 1.5 + 0.25 = 1.75
  //   z = 4:  d^2 = (4 - 3)^2 / 1.75 = 4 / 7
  KalmanFilter<1, 1, 1> kf(Matrix<1, 1>(1.0), Matrix<1, 1>(0.5), Matrix<1, 1>(1.0),
                           Matrix<1, 1>(0.5), Matrix<1, 1>(0.25), Vector<1>(2.0),
                           Matrix<1, 1>(1.0));
  kf.setControl(Vector<1>(2.0));
  MeasurementPrediction<1> p;
  kf.predictMeasurement(p);
  EXPECT_DOUBLE_EQ(p.mean(0), 3.0);
  EXPECT_DOUBLE_EQ(p.covariance(0, 0), 1.5);
  EXPECT_DOUBLE_EQ(p.noise(0, 0), 0.25);
  EXPECT_DOUBLE_EQ(squaredMahalanobisDistance(p, Measurement<1>::complete(Vector<1>(4.0))),
                   4.0 / 7.0);
  EXPECT_DOUBLE_EQ(squaredMahalanobisDistance(p, 0, 4.0), 4.0 / 7.0);
  // The message's own variance 0.5 replaces R: S = 2, d^2 = 1 / 2.
  EXPECT_DOUBLE_EQ(squaredMahalanobisDistance(p, 0, 4.0, 0.5), 0.5);
  // The filter is unchanged.
  EXPECT_DOUBLE_EQ(kf.state()(0), 2.0);
  EXPECT_DOUBLE_EQ(kf.covariance()(0, 0), 1.0);
}

KalmanFilter<2, 2, 0> trainKalmanFilter() {
  // The hand-computed step of test_kalman_filter.cpp: A = [1 0.1; 0 1], H = I,
  // x0 = (1, 2), P0 = I, Q = diag(0.99, 1), R = I.
  const MovingTrain train;
  Matrix<2, 2> Q;
  Q << 0.99, 0, 0, 1;
  return KalmanFilter<2, 2, 0>(train.transitionMatrix(), train.controlMatrix(),
                               train.observationMatrix(), Q, Matrix<2, 2>::Identity(),
                               Vector<2>(1, 2), Matrix<2, 2>::Identity());
}

TEST(MeasurementPrediction, KalmanFilterTwoDimensionsByHand) {
  KalmanFilter<2, 2, 0> kf = trainKalmanFilter();
  // x- = (1.2, 2), P- = [2 0.1; 0.1 2], z^ = x-, S = P- + I = [3 0.1; 0.1 3].
  MeasurementPrediction<2> p;
  kf.predictMeasurement(p);
  EXPECT_NEAR(p.mean(0), 1.2, 1e-15);
  EXPECT_DOUBLE_EQ(p.mean(1), 2.0);
  Matrix<2, 2> expected;
  expected << 2, 0.1, 0.1, 2;
  EXPECT_LT(sftest::maxAbsDiff(p.covariance, expected), 1e-15);

  // z = (1.5, 1.0): y = (0.3, -1.0), S^-1 = [3 -0.1; -0.1 3] / 8.99,
  // d^2 = (3 * 0.09 + 3 * 1 - 2 * 0.1 * 0.3 * (-1)) / 8.99 = 3.33 / 8.99.
  Measurement<2> z = Measurement<2>::complete(Vector<2>(1.5, 1.0));
  EXPECT_NEAR(squaredMahalanobisDistance(p, z), 3.33 / 8.99, 1e-15);

  // Only the first entry present: d^2 = 0.3^2 / 3 = 0.03.
  z.available << true, false;
  EXPECT_NEAR(squaredMahalanobisDistance(p, z), 0.03, 1e-15);
  // Only the second, with its own variance 0.5: S = 2 + 0.5, d^2 = 1 / 2.5 = 0.4.
  z.available << false, true;
  z.varianceGiven << false, true;
  z.variance << 0.0, 0.5;
  EXPECT_NEAR(squaredMahalanobisDistance(p, z), 0.4, 1e-15);
  EXPECT_NEAR(squaredMahalanobisDistance(p, 1, 1.0, 0.5), 0.4, 1e-15);

  // The prediction is the time update the next step performs: without a measurement the
  // estimate is x- (H = I) with covariance P-.
  kf.estimate(Measurement<2>::missing());
  EXPECT_LT(sftest::maxAbsDiff(kf.state(), p.mean), 1e-15);
  EXPECT_LT(sftest::maxAbsDiff(kf.covariance(), p.covariance), 1e-15);
}

// The likelihood terms of the same prediction (S = [3 0.1; 0.1 3]): log det S = log 8.99 with
// both entries, log 3 with the first alone, log 2.5 with the second and its own variance; the
// distance is squaredMahalanobisDistance's.
TEST(MeasurementPrediction, InnovationLikelihoodByHand) {
  KalmanFilter<2, 2, 0> kf = trainKalmanFilter();
  MeasurementPrediction<2> p;
  kf.predictMeasurement(p);
  Measurement<2> z = Measurement<2>::complete(Vector<2>(1.5, 1.0));
  estimation::InnovationLikelihood l = estimation::innovationLikelihood(p, z);
  EXPECT_NEAR(l.squaredDistance, 3.33 / 8.99, 1e-15);
  EXPECT_NEAR(l.logDeterminant, std::log(8.99), 1e-14);
  z.available << true, false;
  l = estimation::innovationLikelihood(p, z);
  EXPECT_NEAR(l.squaredDistance, 0.03, 1e-15);
  EXPECT_NEAR(l.logDeterminant, std::log(3.0), 1e-14);
  z.available << false, true;
  z.varianceGiven << false, true;
  z.variance << 0.0, 0.5;
  l = estimation::innovationLikelihood(p, z);
  EXPECT_NEAR(l.logDeterminant, std::log(2.5), 1e-14);
  EXPECT_EQ(estimation::innovationLikelihood(p, Measurement<2>::missing()).logDeterminant, 0.0);
}

// The likelihood's factor is written as loops in Eigen::LLT's order (probability/cholesky.hpp)
// so that it gives exactly what Eigen::LLT gave: NIS values, gates and the tuned files depend on
// those bits. Random covariances over twelve orders of magnitude, compared bit for bit.
template <int M>
void expectLikelihoodOfEigenLlt(int m, std::mt19937_64& random) {
  std::normal_distribution<double> normal;
  std::uniform_real_distribution<double> exponent(-6.0, 6.0);
  for (int trial = 0; trial < 2000; ++trial) {
    Eigen::MatrixXd B(m, m + trial % 3);
    for (Eigen::Index i = 0; i < B.size(); ++i) {
      B.data()[i] = normal(random) * std::pow(10.0, exponent(random) * (trial % 2));
    }
    MeasurementPrediction<M> p(m);
    p.noise = B * B.transpose();
    if (trial % 5 == 0) p.noise.diagonal().array() += std::pow(10.0, exponent(random));
    Vector<M> y(m);
    for (int i = 0; i < m; ++i) y(i) = normal(random) * std::pow(10.0, exponent(random));
    const Eigen::LLT<Matrix<M, M>> llt(p.noise);
    if (llt.info() != Eigen::Success) {
      EXPECT_THROW(estimation::innovationLikelihood(p, Measurement<M>::complete(y)),
                   estimation::NumericalError);
      continue;
    }
    double logDeterminant = 0.0;
    for (int i = 0; i < m; ++i) logDeterminant += 2.0 * std::log(llt.matrixLLT()(i, i));
    const double squaredDistance = llt.matrixL().solve(y).squaredNorm();
    const estimation::InnovationLikelihood l =
        estimation::innovationLikelihood(p, Measurement<M>::complete(y));
    ASSERT_EQ(std::memcmp(&l.squaredDistance, &squaredDistance, sizeof(double)), 0)
        << "size " << m << ", trial " << trial << ": " << l.squaredDistance << " vs "
        << squaredDistance;
    ASSERT_EQ(std::memcmp(&l.logDeterminant, &logDeterminant, sizeof(double)), 0)
        << "size " << m << ", trial " << trial;
  }
}

TEST(MeasurementPrediction, InnovationLikelihoodIsEigenLltBitForBit) {
  std::mt19937_64 random(7);
  expectLikelihoodOfEigenLlt<4>(4, random);
  expectLikelihoodOfEigenLlt<6>(6, random);
  expectLikelihoodOfEigenLlt<estimation::Dynamic>(5, random);
  expectLikelihoodOfEigenLlt<estimation::Dynamic>(9, random);
}

TEST(MeasurementPrediction, RefusesAnInnovationCovarianceThatIsNotPositiveDefinite) {
  MeasurementPrediction<2> p;
  p.covariance << 1, 2, 2, 1;  // eigenvalues 3 and -1
  p.noise.setZero();
  EXPECT_THROW(squaredMahalanobisDistance(p, Measurement<2>::complete(Vector<2>(1, 1))),
               estimation::NumericalError);
  // One entry: S_00 = covariance(0, 0) + R(0, 0) must be positive.
  p.covariance(0, 0) = -1.0;
  p.noise(0, 0) = 0.5;
  EXPECT_THROW(squaredMahalanobisDistance(p, 0, 1.0), estimation::NumericalError);
  EXPECT_NO_THROW(squaredMahalanobisDistance(p, 0, 1.0, 2.0));
}

TEST(MeasurementPrediction, UnscentedEqualsKalmanOnALinearModel) {
  // On a linear model the unscented transform is exact, so z^ and H P- H^T agree with the
  // Kalman filter's for any sigma-point spread. A non-diagonal belief exercises every entry.
  MovingTrain train;
  train.T = 0.25;
  Matrix<2, 2> Q, R, P0;
  Q << 0.03, 0.01, 0.01, 0.02;
  R << 0.4, 0.1, 0.1, 0.3;
  P0 << 2.0, 0.5, 0.5, 1.0;
  const Vector<2> x0(3.0, -1.0);
  KalmanFilter<2, 2, 0> kf(train.transitionMatrix(), train.controlMatrix(),
                           train.observationMatrix(), Q, R, x0, P0);
  for (double alpha : {1e-3, 0.5, 1.0}) {
    estimation::UnscentedParameters ut;
    ut.alpha = alpha;
    UnscentedKalmanFilter<MovingTrain> ukf(train, Q, R, x0, P0, ut);
    MeasurementPrediction<2> fromKf, fromUkf;
    kf.predictMeasurement(fromKf);
    ukf.predictMeasurement(fromUkf);
    EXPECT_LT(sftest::relDiff(fromUkf.mean, fromKf.mean), 1e-9) << "alpha " << alpha;
    EXPECT_LT(sftest::relDiff(fromUkf.covariance, fromKf.covariance), 1e-9) << "alpha " << alpha;
    EXPECT_EQ(fromUkf.noise, R);
    const Measurement<2> z = Measurement<2>::complete(Vector<2>(2.0, 0.5));
    EXPECT_NEAR(squaredMahalanobisDistance(fromUkf, z), squaredMahalanobisDistance(fromKf, z),
                1e-9);
  }
}

TEST(MeasurementPrediction, ExtendedKalmanFilterLinearisesAtThePrediction) {
  // x0 = 3, P0 = 0.2, Q = 0.05: x- = 3, P- = 0.25; z^ = 9, H = 2 x- = 6, H P- H^T = 9.
  ExtendedKalmanFilter<sftest::SquareModel> ekf(sftest::SquareModel{}, Matrix<1, 1>(0.05),
                                                Matrix<1, 1>(1.0), Vector<1>(3.0),
                                                Matrix<1, 1>(0.2));
  MeasurementPrediction<1> p;
  ekf.predictMeasurement(p);
  EXPECT_DOUBLE_EQ(p.mean(0), 9.0);
  EXPECT_NEAR(p.covariance(0, 0), 9.0, 1e-12);
  // z = 13: d^2 = 16 / (9 + 1) = 1.6.
  EXPECT_NEAR(squaredMahalanobisDistance(p, 0, 13.0), 1.6, 1e-12);
}

TEST(MeasurementPrediction, ParticleFilterOfDynamicSizeFillsAnEmptyPrediction) {
  // The fuzzer's finding (sf_estimation/fuzz/regressions/particle_filter_prediction_unsized):
  // a default-constructed prediction of dynamic size has no entries, and the particle filter
  // accumulated into it without sizing it (an Eigen size assertion, or memory overrun with
  // assertions off). Empty storage must give the same prediction as storage of the right size
  // filled with junk.
  const auto model = estimation::makeFunctionModel(
      2, 2, 0, [](const auto& x, const auto&, auto& next) { next = x; },
      [](const auto& x, auto& z) { z = x; });
  estimation::ParticleFilterParameters params;
  params.particles = 64;
  params.seed = 3;
  const Eigen::MatrixXd I = Eigen::MatrixXd::Identity(2, 2);
  ParticleFilterSIR<estimation::FunctionModel> pf(model, 0.1 * I, 0.2 * I,
                                                  Eigen::Vector2d(1.0, 0.5), I, params);
  MeasurementPrediction<estimation::Dynamic> empty, junk;
  junk.mean = Eigen::VectorXd::Constant(2, 7.0);
  junk.covariance = Eigen::MatrixXd::Constant(2, 2, 7.0);
  pf.predictMeasurement(empty);
  pf.predictMeasurement(junk);
  ASSERT_EQ(empty.mean.size(), 2);
  ASSERT_EQ(empty.covariance.rows(), 2);
  ASSERT_EQ(empty.covariance.cols(), 2);
  EXPECT_EQ(empty.mean, junk.mean);
  EXPECT_EQ(empty.covariance, junk.covariance);
  EXPECT_EQ(empty.noise, 0.2 * I);
  // the particles' spread around x0 = (1, 0.5) with P0 = I and Q = 0.1 I
  EXPECT_GT(empty.covariance(0, 0), 0.3);
}

TEST(MeasurementPrediction, ParticleFilterUsesTheParticlesOfItsNextStep) {
  MovingTrain train;
  Matrix<2, 2> Q, R;
  Q << 0.04, 0.0, 0.0, 0.01;
  R << 0.3, 0.05, 0.05, 0.2;
  estimation::ParticleFilterParameters params;
  params.particles = 500;
  params.seed = 7;
  params.resamplingThreshold = 0.0;  // keep the unequal weights of the first correction
  ParticleFilterSIR<MovingTrain> pf(train, Q, R, Vector<2>(1.0, 0.5), Matrix<2, 2>::Identity(),
                                    params);
  pf.estimate(Measurement<2>::complete(Vector<2>(1.2, 0.4)));  // unequal weights from here

  MeasurementPrediction<2> p;
  pf.predictMeasurement(p);
  EXPECT_EQ(p.noise, R);

  // A step without measurement draws the same particles and keeps the weights: the
  // prediction must be the weighted moments of h (= identity) over the new particles.
  pf.estimate(Measurement<2>::missing());
  const Eigen::VectorXd w = pf.logWeights().array().exp();
  Vector<2> mean = Vector<2>::Zero();
  for (Eigen::Index i = 0; i < pf.particleCount(); ++i) mean += w(i) * pf.particles().col(i);
  Matrix<2, 2> covariance = Matrix<2, 2>::Zero();
  for (Eigen::Index i = 0; i < pf.particleCount(); ++i) {
    const Vector<2> d = pf.particles().col(i) - mean;
    covariance += w(i) * d * d.transpose();
  }
  EXPECT_LT(sftest::maxAbsDiff(p.mean, mean), 1e-12);
  EXPECT_LT(sftest::maxAbsDiff(p.covariance, covariance), 1e-12);
  // Here h is the identity, so this is the filter's own mean and covariance.
  EXPECT_LT(sftest::maxAbsDiff(p.mean, pf.state()), 1e-12);
  EXPECT_LT(sftest::maxAbsDiff(p.covariance, pf.covariance()), 1e-12);
}

TEST(MeasurementPrediction, ParticleFilterPredictionLeavesTheFilterUnchanged) {
  MovingTrain train;
  const Matrix<2, 2> Q = Matrix<2, 2>::Identity() * 0.01, R = Matrix<2, 2>::Identity() * 0.1;
  estimation::ParticleFilterParameters params;
  params.particles = 200;
  ParticleFilterSIR<MovingTrain> a(train, Q, R, Vector<2>(0, 1), Matrix<2, 2>::Identity(), params);
  ParticleFilterSIR<MovingTrain> b = a;
  MeasurementPrediction<2> p;
  a.predictMeasurement(p);
  const Measurement<2> z = Measurement<2>::complete(Vector<2>(0.2, 0.9));
  a.estimate(z);
  b.estimate(z);
  EXPECT_EQ(a.state(), b.state());  // same random numbers: bit for bit
  EXPECT_EQ(a.covariance(), b.covariance());
}

}  // namespace
