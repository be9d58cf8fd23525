// Tests of ParticleFilterSIR (thesis Algorithms 3.4, 3.5): agreement with the Kalman filter on
// a linear Gaussian model within the Monte-Carlo error, determinism, log-space weights,
// systematic resampling, and the strong exception guarantee (engine included).
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <iostream>
#include <limits>
#include <map>
#include <utility>
#include <vector>

#include <gtest/gtest.h>
#include <Eigen/LU>

#include "filter_test_utils.hpp"
#include "sf_estimation/errors.hpp"
#include "sf_estimation/kalman_filter.hpp"
#include "sf_estimation/models/moving_train.hpp"
#include "sf_estimation/particle_filter.hpp"

namespace {

using estimation::Index;
using estimation::InvalidInputError;
using estimation::KalmanFilter;
using estimation::Matrix;
using estimation::Measurement;
using estimation::NumericalError;
using estimation::ParticleFilterParameters;
using estimation::ParticleFilterSIR;
using estimation::Vector;
using estimation::models::MovingTrain;

ParticleFilterParameters parameters(Index particles, std::uint64_t seed, double threshold = 0.5) {
  ParticleFilterParameters p;
  p.particles = particles;
  p.seed = seed;
  p.resamplingThreshold = threshold;
  return p;
}

/// 1-D random walk x' = x + w, z = x + v. `poison` makes the transition return NaN (to
/// provoke a NumericalError inside a step).
struct RandomWalk {
  static constexpr int StateSize = 1;
  static constexpr int MeasurementSize = 1;
  static constexpr int ControlSize = 0;
  bool poison = false;
  Index stateSize() const { return 1; }
  Index measurementSize() const { return 1; }
  Index controlSize() const { return 0; }
  template <class S>
  void transition(const Eigen::Matrix<S, 1, 1>& x, const Vector<0>&,
                  Eigen::Matrix<S, 1, 1>& next) const {
    next(0) = poison ? S(std::numeric_limits<double>::quiet_NaN()) : x(0);
  }
  template <class S>
  void observation(const Eigen::Matrix<S, 1, 1>& x, Eigen::Matrix<S, 1, 1>& z) const {
    z(0) = x(0);
  }
};

// ---------------------------------------------------------------------------------------------
// Agreement with the Kalman filter.
// ---------------------------------------------------------------------------------------------

/// vech index pairs of a symmetric 2x2 matrix: (0,0), (0,1), (1,1).
constexpr int kRow[3] = {0, 0, 1};
constexpr int kCol[3] = {0, 1, 1};

/// Covariance of vech(S - P) for the sample covariance S of n Gaussian draws with covariance
/// P (Wishart): Cov(S_ij, S_kl) = (P_ik P_jl + P_il P_jk) / n; returned for n = 1.
Matrix<3, 3> sampleCovarianceSpread(const Matrix<2, 2>& P) {
  Matrix<3, 3> out;
  for (int a = 0; a < 3; ++a) {
    for (int b = 0; b < 3; ++b) {
      out(a, b) =
          P(kRow[a], kRow[b]) * P(kCol[a], kCol[b]) + P(kRow[a], kCol[b]) * P(kCol[a], kRow[b]);
    }
  }
  return out;
}

/// The linear map vech(D) -> vech(F D F^T) for symmetric D.
Matrix<3, 3> congruenceMap(const Matrix<2, 2>& F) {
  Matrix<3, 3> G;
  for (int a = 0; a < 3; ++a) {
    for (int b = 0; b < 3; ++b) {
      const int k = kRow[b], l = kCol[b];
      G(a, b) = F(kRow[a], k) * F(kCol[a], l) + (k != l ? F(kRow[a], l) * F(kCol[a], k) : 0.0);
    }
  }
  return G;
}

TEST(ParticleFilterLinearGaussian, MeanMatchesKalmanFilterWithinMonteCarloError) {
  // On a linear Gaussian model the exact posterior is the Kalman filter's N(x, P).
  //
  // Tolerance. In one step the weighted particle mean is a self-normalised importance
  // sampling estimate of x with variance ~ P / N_eff (N_eff = effective sample size of the
  // step), and the weighted sample covariance estimates P with the Wishart spread
  // Cov(P_ij, P_kl) ~ (P_ik P_jl + P_il P_jk) / N_eff. An error e of the particle set's mean
  // before a step is carried into the next estimate like any prior error in a Kalman filter,
  // e -> F e with F = (I - K H) A, and resampling adds the spread of N draws (P / N). So the
  // Monte-Carlo variance of the estimate propagates as
  //   V_t = F V_{t-1} F^T + P_t / N_eff,t  (+ P_t / N after resampling),   V_0 = P0 / N
  // and the same with the congruence map for the covariance error. The test requires the PF
  // to be within 5 standard deviations sqrt(V_ii) (a single-step bound sqrt(P / N_eff) ignores
  // the inherited error and is exceeded by a factor ~2 after a few steps).
  const MovingTrain train;
  Matrix<2, 2> Q;
  Q << 0.02, 0.0, 0.0, 0.05;
  Matrix<2, 2> R;
  R << 0.25, 0.0, 0.0, 0.1;
  const Vector<2> x0(1.0, 0.3);
  const Matrix<2, 2> P0 = Vector<2>(0.5, 0.2).asDiagonal();
  const Index N = 20000;
  const double n = static_cast<double>(N);
  const Matrix<2, 2> A = train.transitionMatrix();
  KalmanFilter<2, 2> kf(A, train.controlMatrix(), train.observationMatrix(), Q, R, x0, P0);
  ParticleFilterSIR<MovingTrain> pf(train, Q, R, x0, P0, parameters(N, 2024));

  const auto run = sftest::simulateLinear<2, 2, 0>(
      A, train.controlMatrix(), train.observationMatrix(), Q, R, x0, 30, 51, 0.0, 0, 0.0);
  Matrix<2, 2> V = P0 / n;
  Matrix<3, 3> W = sampleCovarianceSpread(P0) / n;
  double worstMean = 0.0, worstVariance = 0.0, maxError = 0.0, minEss = n, maxSe = 0.0;
  int resampled = 0;
  for (std::size_t k = 0; k < run.size(); ++k) {
    // Gain of this step (H = I): K = P- (P- + R)^-1, F = (I - K) A.
    const Matrix<2, 2> Pprior = A * kf.covariance() * A.transpose() + Q;
    const Matrix<2, 2> K = Pprior * (Pprior + R).inverse();
    const Matrix<2, 2> F = (Matrix<2, 2>::Identity() - K) * A;
    kf.estimate(run[k].z);
    pf.estimate(run[k].z);
    const Matrix<2, 2> P = kf.covariance();
    const double ess = pf.effectiveSampleSize();
    const double resampling = pf.resampledLastStep() ? 1.0 / n : 0.0;
    V = F * V * F.transpose() + P * (1.0 / ess + resampling);
    const Matrix<3, 3> G = congruenceMap(F);
    W = G * W * G.transpose() + sampleCovarianceSpread(P) * (1.0 / ess + resampling);
    minEss = std::min(minEss, ess);
    resampled += pf.resampledLastStep() ? 1 : 0;
    for (Index i = 0; i < 2; ++i) {
      const int vech = i == 0 ? 0 : 2;
      const double meanSd = std::sqrt(V(i, i)), varianceSd = std::sqrt(W(vech, vech));
      const double meanError = std::abs(pf.state()(i) - kf.state()(i));
      const double varianceError = std::abs(pf.covariance()(i, i) - P(i, i));
      worstMean = std::max(worstMean, meanError / meanSd);
      worstVariance = std::max(worstVariance, varianceError / varianceSd);
      maxError = std::max(maxError, meanError);
      maxSe = std::max(maxSe, meanSd);
      ASSERT_LE(meanError, 5.0 * meanSd) << "step " << k << ", state " << i;
      ASSERT_LE(varianceError, 5.0 * varianceSd) << "step " << k << ", variance " << i;
    }
  }
  std::cout << "[ measured ] PF (N=20000) vs KF, moving train, 30 steps: max |mean error| "
            << maxError << " (largest standard deviation " << maxSe << "), max error / sd "
            << worstMean << ", max variance error / sd " << worstVariance << ", min N_eff "
            << minEss << ", resampled in " << resampled << " steps\n";
  EXPECT_GT(resampled, 0);
  EXPECT_GT(minEss, 1000.0);  // the Gaussian approximations above need a large N_eff
}

// ---------------------------------------------------------------------------------------------
// Determinism.
// ---------------------------------------------------------------------------------------------

TEST(ParticleFilterDeterminism, SameSeedSameOutputDifferentSeedDifferent) {
  const MovingTrain train;
  const Matrix<2, 2> Q = Matrix<2, 2>::Identity() * 0.05;
  const Matrix<2, 2> R = Matrix<2, 2>::Identity() * 0.2;
  const Vector<2> x0(0.0, 1.0);
  const Matrix<2, 2> P0 = Matrix<2, 2>::Identity();
  ParticleFilterSIR<MovingTrain> a(train, Q, R, x0, P0, parameters(500, 7));
  ParticleFilterSIR<MovingTrain> b(train, Q, R, x0, P0, parameters(500, 7));
  ParticleFilterSIR<MovingTrain> c(train, Q, R, x0, P0, parameters(500, 8));
  const auto run =
      sftest::simulateLinear<2, 2, 0>(train.transitionMatrix(), train.controlMatrix(),
                                      train.observationMatrix(), Q, R, x0, 25, 52, 0.2, 0, 0.0);
  std::vector<Vector<2>> first;
  for (const auto& step : run) {
    a.estimate(step.z);
    b.estimate(step.z);
    c.estimate(step.z);
    first.push_back(a.state());
    ASSERT_EQ(a.state(), b.state());
    ASSERT_EQ(a.covariance(), b.covariance());
    ASSERT_EQ(a.particles(), b.particles());
    ASSERT_EQ(a.logWeights(), b.logWeights());
    EXPECT_NE(a.state(), c.state());
  }
  // reset() re-seeds: the run repeats exactly.
  a.reset();
  for (std::size_t k = 0; k < run.size(); ++k) {
    a.estimate(run[k].z);
    ASSERT_EQ(a.state(), first[k]) << "step " << k;
  }
}

// ---------------------------------------------------------------------------------------------
// Log-space weights.
// ---------------------------------------------------------------------------------------------

TEST(ParticleFilterWeights, VeryAccurateSensorDoesNotUnderflow) {
  // Random walk, Q = 1, P0 = 1, R = 1e-12, N = 1000, z = 0.5. The predicted particles are
  // ~N(0, 2); a linear-space likelihood exp(-r^2 / (2e-12)) underflows to 0 for |r| > 3.9e-5,
  // while the nearest of 1000 particles is typically ~1/(2 * 1000 * 0.27) = 2e-3 away from z,
  // so without log weights every weight would be 0 (and the estimate NaN). With log weights
  // the particle nearest to z takes all the weight.
  const double z = 0.5;
  const Index N = 1000;
  const Matrix<1, 1> Q = Matrix<1, 1>::Constant(1.0);
  const Matrix<1, 1> P0 = Matrix<1, 1>::Constant(1.0);
  ParticleFilterSIR<RandomWalk> accurate(RandomWalk{}, Q, Matrix<1, 1>::Constant(1e-12),
                                         Vector<1>::Zero(), P0, parameters(N, 99));
  // Same seed, never resampling: its particles after the step are the predicted particles of
  // the accurate filter (same draws), so the nearest one can be found independently.
  ParticleFilterSIR<RandomWalk> twin(RandomWalk{}, Q, Matrix<1, 1>::Constant(1.0),
                                     Vector<1>::Zero(), P0, parameters(N, 99, 0.0));
  accurate.estimate(Measurement<1>::complete(Vector<1>::Constant(z)));
  twin.estimate(Measurement<1>::complete(Vector<1>::Constant(z)));

  Index nearest = 0;
  for (Index i = 1; i < N; ++i) {
    if (std::abs(twin.particles()(0, i) - z) < std::abs(twin.particles()(0, nearest) - z)) {
      nearest = i;
    }
  }
  const double best = twin.particles()(0, nearest);
  std::cout << "[ measured ] R = 1e-12: nearest particle " << std::abs(best - z)
            << " from z, estimate " << accurate.state()(0) << "\n";
  ASSERT_GT(std::abs(best - z), 3.9e-5);  // linear-space weights would all be 0 here
  ASSERT_TRUE(std::isfinite(accurate.state()(0)));
  ASSERT_TRUE(accurate.logWeights().allFinite());
  EXPECT_NEAR(accurate.state()(0), best, 1e-12);
  EXPECT_LT(std::abs(accurate.state()(0) - z), 0.05);
  EXPECT_NEAR(accurate.effectiveSampleSize(), 1.0, 1e-9);
  EXPECT_TRUE(accurate.resampledLastStep());
  EXPECT_NEAR(accurate.covariance()(0, 0), 0.0, 1e-20);

  // The filter keeps working from the collapsed set.
  accurate.estimate(Measurement<1>::complete(Vector<1>::Constant(z)));
  EXPECT_TRUE(std::isfinite(accurate.state()(0)));
  EXPECT_LT(std::abs(accurate.state()(0) - z), 0.05);
}

// ---------------------------------------------------------------------------------------------
// Systematic resampling.
// ---------------------------------------------------------------------------------------------

TEST(ParticleFilterResampling, SystematicResamplingCopiesFloorOrCeilOfNw) {
  // Threshold 1: resample after every step. A twin with the same seed that never resamples
  // shows the weighted set before resampling. Systematic resampling places N equidistant
  // pointers, so particle i is copied floor(N w_i) or ceil(N w_i) times; afterwards the count
  // is unchanged and every weight is 1/N.
  const MovingTrain train;
  const Matrix<2, 2> Q = Matrix<2, 2>::Identity() * 0.05;
  const Matrix<2, 2> R = Matrix<2, 2>::Identity() * 0.3;
  const Vector<2> x0(0.0, 1.0);
  const Matrix<2, 2> P0 = Matrix<2, 2>::Identity();
  const Index N = 800;
  ParticleFilterSIR<MovingTrain> always(train, Q, R, x0, P0, parameters(N, 5, 1.0));
  ParticleFilterSIR<MovingTrain> never(train, Q, R, x0, P0, parameters(N, 5, 0.0));
  const Measurement<2> z = Measurement<2>::complete(Vector<2>(0.8, 0.4));
  always.estimate(z);
  never.estimate(z);

  ASSERT_TRUE(always.resampledLastStep());
  ASSERT_FALSE(never.resampledLastStep());
  EXPECT_EQ(always.particleCount(), N);
  EXPECT_EQ(always.particles().cols(), N);
  EXPECT_EQ(always.logWeights().size(), N);
  EXPECT_EQ(always.logWeights(), Eigen::VectorXd::Constant(N, -std::log(static_cast<double>(N))));
  EXPECT_EQ(always.effectiveSampleSize(), never.effectiveSampleSize());  // N_eff before

  std::map<std::pair<double, double>, Index> index;
  for (Index i = 0; i < N; ++i) {
    index[{never.particles()(0, i), never.particles()(1, i)}] = i;
  }
  ASSERT_EQ(static_cast<Index>(index.size()), N);  // continuous draws: all distinct
  std::vector<Index> copies(static_cast<std::size_t>(N), 0);
  for (Index j = 0; j < N; ++j) {
    const auto it = index.find({always.particles()(0, j), always.particles()(1, j)});
    ASSERT_NE(it, index.end()) << "resampled particle " << j << " is not a predicted particle";
    ++copies[static_cast<std::size_t>(it->second)];
  }
  for (Index i = 0; i < N; ++i) {
    const double expected = static_cast<double>(N) * std::exp(never.logWeights()(i));
    const double count = static_cast<double>(copies[static_cast<std::size_t>(i)]);
    ASSERT_GE(count, std::floor(expected - 1e-9)) << "particle " << i << ", N w = " << expected;
    ASSERT_LE(count, std::ceil(expected + 1e-9)) << "particle " << i << ", N w = " << expected;
  }
  // The estimate is the moments of the weighted set before resampling (the twin's particles
  // and weights), not those of the resampled copies: sum w_i x_i and sum w_i (x_i - m)^2.
  Vector<2> mean = Vector<2>::Zero();
  for (Index i = 0; i < N; ++i) mean += std::exp(never.logWeights()(i)) * never.particles().col(i);
  Matrix<2, 2> covariance = Matrix<2, 2>::Zero();
  for (Index i = 0; i < N; ++i) {
    const Vector<2> d = never.particles().col(i) - mean;
    covariance += std::exp(never.logWeights()(i)) * d * d.transpose();
  }
  EXPECT_LE(sftest::maxAbsDiff(always.state(), mean), 1e-12);
  EXPECT_LE(sftest::maxAbsDiff(always.covariance(), covariance), 1e-12);
  EXPECT_EQ(always.state(), never.state());
  EXPECT_EQ(always.covariance(), never.covariance());
  // The resampled set's plain mean differs from it (by the Monte-Carlo noise of resampling).
  const Vector<2> resampledMean = always.particles().rowwise().mean();
  EXPECT_GT(sftest::maxAbsDiff(always.state(), resampledMean), 1e-9);
}

TEST(ParticleFilterResampling, ThresholdOneResamplesWhenTheEffectiveSampleSizeIsN) {
  // Equal weights (no measurement): N_eff = N exactly (N = 8: the weights 1/8 are exact).
  // The rule is N_eff <= threshold N, inclusive: threshold 1 resamples every step.
  ParticleFilterSIR<RandomWalk> pf(RandomWalk{}, Matrix<1, 1>::Constant(0.1),
                                   Matrix<1, 1>::Constant(0.2), Vector<1>::Zero(),
                                   Matrix<1, 1>::Identity(), parameters(8, 3, 1.0));
  pf.estimate(Measurement<1>::missing());
  EXPECT_EQ(pf.effectiveSampleSize(), 8.0);
  EXPECT_TRUE(pf.resampledLastStep());
  // Threshold 0 never resamples (N_eff >= 1).
  ParticleFilterSIR<RandomWalk> never(RandomWalk{}, Matrix<1, 1>::Constant(0.1),
                                      Matrix<1, 1>::Constant(0.2), Vector<1>::Zero(),
                                      Matrix<1, 1>::Identity(), parameters(8, 3, 0.0));
  never.estimate(Measurement<1>::complete(Vector<1>::Constant(100.0)));
  EXPECT_FALSE(never.resampledLastStep());
}

TEST(ParticleFilterResampling, ThresholdDecidesWhenToResample) {
  const MovingTrain train;
  const Matrix<2, 2> Q = Matrix<2, 2>::Identity() * 0.05;
  const Matrix<2, 2> R = Matrix<2, 2>::Identity() * 0.3;
  ParticleFilterSIR<MovingTrain> pf(train, Q, R, Vector<2>(0.0, 1.0), Matrix<2, 2>::Identity(),
                                    parameters(600, 6, 0.5));
  const auto run = sftest::simulateLinear<2, 2, 0>(train.transitionMatrix(), train.controlMatrix(),
                                                   train.observationMatrix(), Q, R,
                                                   Vector<2>(0.0, 1.0), 30, 53, 0.0, 0, 0.0);
  int resampled = 0;
  for (const auto& step : run) {
    pf.estimate(step.z);
    const bool below = pf.effectiveSampleSize() <= 0.5 * 600.0;
    ASSERT_EQ(pf.resampledLastStep(), below);
    resampled += below ? 1 : 0;
  }
  EXPECT_GT(resampled, 0);
  EXPECT_LT(resampled, 30);
}

// ---------------------------------------------------------------------------------------------
// Rejected steps leave the filter unchanged, its random engine included.
// ---------------------------------------------------------------------------------------------

TEST(ParticleFilterRejection, NanMeasurementChangesNothing) {
  const MovingTrain train;
  const Matrix<2, 2> Q = Matrix<2, 2>::Identity() * 0.05;
  const Matrix<2, 2> R = Matrix<2, 2>::Identity() * 0.3;
  ParticleFilterSIR<MovingTrain> a(train, Q, R, Vector<2>(0.0, 1.0), Matrix<2, 2>::Identity(),
                                   parameters(300, 77));
  ParticleFilterSIR<MovingTrain> b = a;
  const Measurement<2> z1 = Measurement<2>::complete(Vector<2>(0.2, 0.9));
  const Measurement<2> z2 = Measurement<2>::complete(Vector<2>(0.3, 1.1));
  a.estimate(z1);
  b.estimate(z1);

  const Eigen::MatrixXd particles = a.particles();
  const Eigen::VectorXd weights = a.logWeights();
  const Vector<2> state = a.state();
  Measurement<2> bad = Measurement<2>::complete(Vector<2>(0.3, 1.1));
  bad.value(1) = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(a.estimate(bad), InvalidInputError);
  EXPECT_EQ(a.particles(), particles);
  EXPECT_EQ(a.logWeights(), weights);
  EXPECT_EQ(a.state(), state);

  a.estimate(z2);
  b.estimate(z2);  // never saw the bad input
  EXPECT_EQ(a.particles(), b.particles());
  EXPECT_EQ(a.logWeights(), b.logWeights());
  EXPECT_EQ(a.state(), b.state());
  EXPECT_EQ(a.covariance(), b.covariance());
}

TEST(ParticleFilterRejection, NumericalErrorInsideAStepRestoresTheEngine) {
  // The transition yields NaN after the process noise was drawn: the step is rejected and the
  // engine must be rewound, so the next step equals that of a filter that never tried it.
  const Matrix<1, 1> Q = Matrix<1, 1>::Constant(0.5);
  const Matrix<1, 1> R = Matrix<1, 1>::Constant(0.2);
  ParticleFilterSIR<RandomWalk> a(RandomWalk{}, Q, R, Vector<1>::Zero(), Matrix<1, 1>::Identity(),
                                  parameters(300, 78, 1.0));
  ParticleFilterSIR<RandomWalk> b = a;
  const Measurement<1> z1 = Measurement<1>::complete(Vector<1>::Constant(0.4));
  const Measurement<1> z2 = Measurement<1>::complete(Vector<1>::Constant(0.1));
  a.estimate(z1);
  b.estimate(z1);

  const Eigen::MatrixXd particles = a.particles();
  a.model().poison = true;
  EXPECT_THROW(a.estimate(z2), NumericalError);
  EXPECT_EQ(a.particles(), particles);
  a.model().poison = false;

  a.estimate(z2);
  b.estimate(z2);
  EXPECT_EQ(a.particles(), b.particles());
  EXPECT_EQ(a.logWeights(), b.logWeights());
  EXPECT_EQ(a.state(), b.state());
}

TEST(ParticleFilterBelief, SetBeliefDrawsTheParticlesAnewOrChangesNothing) {
  ParticleFilterSIR<MovingTrain> pf(MovingTrain{}, Matrix<2, 2>::Identity() * 0.01,
                                    Matrix<2, 2>::Identity(), Vector<2>::Zero(),
                                    Matrix<2, 2>::Identity(), parameters(20000, 3));
  Matrix<2, 2> P;
  P << 0.04, 0.01, 0.01, 0.09;
  pf.setBelief(Vector<2>(2.0, -1.0), P);
  // The sample mean's standard deviation is sqrt(P_ii / N): 0.0014 and 0.0021.
  EXPECT_NEAR(pf.state()(0), 2.0, 5.0 * std::sqrt(0.04 / 20000));
  EXPECT_NEAR(pf.state()(1), -1.0, 5.0 * std::sqrt(0.09 / 20000));
  // A sample variance's standard deviation is P_ii sqrt(2 / N): 4e-4 and 9e-4.
  EXPECT_NEAR(pf.covariance()(0, 0), 0.04, 5.0 * 0.04 * std::sqrt(2.0 / 20000));
  EXPECT_NEAR(pf.covariance()(1, 1), 0.09, 5.0 * 0.09 * std::sqrt(2.0 / 20000));
  EXPECT_DOUBLE_EQ(pf.effectiveSampleSize(), 20000.0);
  const auto particles = pf.particles();
  const Vector<2> x = pf.state();
  Matrix<2, 2> bad = P;
  bad(0, 1) = 0.5;  // not symmetric
  EXPECT_THROW(pf.setBelief(Vector<2>(0.0, 0.0), bad), estimation::ParameterError);
  EXPECT_EQ(pf.particles(), particles);
  EXPECT_EQ(pf.state(), x);
}

TEST(ParticleFilterParametersCheck, RefusesInvalidParameters) {
  const Matrix<1, 1> one = Matrix<1, 1>::Constant(1.0);
  EXPECT_THROW(ParticleFilterSIR<RandomWalk>(RandomWalk{}, one, one, Vector<1>::Zero(), one,
                                             parameters(0, 1)),
               estimation::ParameterError);
  EXPECT_THROW(ParticleFilterSIR<RandomWalk>(RandomWalk{}, one, one, Vector<1>::Zero(), one,
                                             parameters(10, 1, 1.5)),
               estimation::ParameterError);
  EXPECT_THROW(ParticleFilterSIR<RandomWalk>(RandomWalk{}, one, Matrix<1, 1>::Zero(),
                                             Vector<1>::Zero(), one, parameters(10, 1)),
               estimation::ParameterError);  // R must be positive definite
}

}  // namespace
