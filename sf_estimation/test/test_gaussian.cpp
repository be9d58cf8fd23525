// Tests of probability/gaussian.hpp against closed-form densities and sampling statistics.
#include <cmath>
#include <limits>
#include <string>

#include <gtest/gtest.h>

#include "sf_estimation/errors.hpp"
#include "sf_estimation/probability/gaussian.hpp"

namespace {

using estimation::Index;
using estimation::InvalidInputError;
using estimation::NumericalError;
using estimation::ParameterError;
using estimation::probability::covarianceSquareRoot;
using estimation::probability::fillStandardNormal;
using estimation::probability::logSumExp;
using estimation::probability::MultivariateGaussian;
using estimation::probability::RandomEngine;

constexpr double kPi = 3.14159265358979323846;

// Mean and covariance (divided by n) of the columns of `samples`.
struct SampleMoments {
  Eigen::VectorXd mean;
  Eigen::MatrixXd covariance;
};

SampleMoments momentsOf(const Eigen::MatrixXd& samples) {
  const double n = static_cast<double>(samples.cols());
  SampleMoments moments;
  moments.mean = samples.rowwise().sum() / n;
  const Eigen::MatrixXd centred = samples.colwise() - moments.mean;
  moments.covariance = centred * centred.transpose() / n;
  return moments;
}

// Checks sample moments of N(mean, P) draws within 5 standard errors: SE(mean_i) =
// sqrt(P_ii / n); SE(cov_ij) = sqrt((P_ii P_jj + P_ij^2) / n) for a Gaussian.
void expectMomentsMatch(const Eigen::MatrixXd& samples, const Eigen::VectorXd& mean,
                        const Eigen::MatrixXd& P) {
  const double n = static_cast<double>(samples.cols());
  const SampleMoments moments = momentsOf(samples);
  for (Index i = 0; i < mean.size(); ++i) {
    EXPECT_NEAR(moments.mean(i), mean(i), 5.0 * std::sqrt(P(i, i) / n)) << "mean " << i;
    for (Index j = 0; j < mean.size(); ++j) {
      const double standardError = std::sqrt((P(i, i) * P(j, j) + P(i, j) * P(i, j)) / n);
      EXPECT_NEAR(moments.covariance(i, j), P(i, j), 5.0 * standardError)
          << "covariance " << i << "," << j;
    }
  }
}

TEST(Gaussian, StandardNormalDensityAtZeroIsOneOverSqrtTwoPi) {
  const MultivariateGaussian<1> g(Eigen::Matrix<double, 1, 1>(0.0),
                                  Eigen::Matrix<double, 1, 1>(1.0));
  // 1 / sqrt(2 pi) = 0.3989422804014327
  EXPECT_NEAR(g.density(Eigen::Matrix<double, 1, 1>(0.0)), 0.3989422804014327, 1e-15);
  // log: -0.5 log(2 pi) = -0.9189385332046727
  EXPECT_NEAR(g.logDensity(Eigen::Matrix<double, 1, 1>(0.0)), -0.9189385332046727, 1e-14);
  // one sigma away: exp(-0.5) / sqrt(2 pi) = 0.24197072451914337
  EXPECT_NEAR(g.density(Eigen::Matrix<double, 1, 1>(1.0)), 0.24197072451914337, 1e-15);
}

// mean (1, 2), P = [[2, 0.5], [0.5, 1]], x = (2, 1):
//   det P = 2 - 0.25 = 1.75, P^-1 = [[1, -0.5], [-0.5, 2]] / 1.75, d = x - mean = (1, -1)
//   d^T P^-1 d = (1 + 0.5 + 0.5 + 2) / 1.75 = 4 / 1.75 = 2.2857142857
//   density = exp(-0.5 * 2.2857142857) / (2 pi sqrt(1.75)) = 0.31890 / 8.31187 = 0.0383676
//   log density = -1.1428571429 - log(8.3118715) = -3.2605421032
TEST(Gaussian, TwoDimensionalDensityMatchesClosedForm) {
  const Eigen::Vector2d mean(1.0, 2.0);
  Eigen::Matrix2d P;
  P << 2.0, 0.5, 0.5, 1.0;
  const Eigen::Vector2d x(2.0, 1.0);
  const double expectedDensity = std::exp(-0.5 * 4.0 / 1.75) / (2.0 * kPi * std::sqrt(1.75));
  EXPECT_NEAR(expectedDensity, 0.03836759318252469, 1e-15);  // the hand value above

  const MultivariateGaussian<2> fixedSize(mean, P);
  EXPECT_NEAR(fixedSize.density(x), 0.03836759318252469, 1e-15);
  EXPECT_NEAR(fixedSize.logDensity(x), -3.2605421032341995, 1e-13);

  const MultivariateGaussian<Eigen::Dynamic> dynamicSize(mean, P);
  Eigen::VectorXd workspace(2);
  EXPECT_NEAR(dynamicSize.logDensity(Eigen::VectorXd(x), workspace), -3.2605421032341995, 1e-13);
  EXPECT_NEAR(dynamicSize.density(Eigen::VectorXd(x)), 0.03836759318252469, 1e-15);
  // at the mean the exponent is 0: 1 / (2 pi sqrt(1.75)) = 0.1203093
  EXPECT_NEAR(dynamicSize.density(Eigen::VectorXd(mean)), 1.0 / (2.0 * kPi * std::sqrt(1.75)),
              1e-15);
}

TEST(Gaussian, LogDensityRejectsAPointOfTheWrongSize) {
  const MultivariateGaussian<Eigen::Dynamic> g(Eigen::VectorXd::Zero(2),
                                               Eigen::MatrixXd::Identity(2, 2));
  EXPECT_THROW(g.logDensity(Eigen::VectorXd::Zero(3)), InvalidInputError);
}

TEST(Gaussian, DensityThrowsOnSingularCovarianceButSamplingWorks) {
  Eigen::Matrix2d singular;
  singular << 1.0, 1.0, 1.0, 1.0;  // rank 1: x1 - x2 has zero variance
  const MultivariateGaussian<2> g(Eigen::Vector2d(0.5, -0.5), singular);
  EXPECT_FALSE(g.isPositiveDefinite());
  EXPECT_THROW(g.density(Eigen::Vector2d(0.0, 0.0)), NumericalError);
  EXPECT_THROW(g.logDensity(Eigen::Vector2d(0.0, 0.0)), NumericalError);
  RandomEngine engine(7);
  for (int k = 0; k < 100; ++k) {
    const Eigen::Vector2d x = g.sample(engine);
    EXPECT_NEAR(x(0) - x(1), 1.0, 1e-12);  // the mean difference, exactly as the rank says
  }
}

TEST(Gaussian, SemiDefiniteSamplingKeepsZeroRowsExactlyAtTheMean) {
  // Process noise acting only on entries 0 and 2, as in an EKF Q with zero rows.
  Eigen::Matrix4d Q = Eigen::Matrix4d::Zero();
  Q(0, 0) = 2.0;
  Q(0, 2) = Q(2, 0) = 0.5;
  Q(2, 2) = 1.0;
  const Eigen::Vector4d mean(1.0, 2.0, 3.0, 4.0);
  const MultivariateGaussian<Eigen::Dynamic> g(mean, Q);
  EXPECT_FALSE(g.isPositiveDefinite());
  EXPECT_THROW(g.density(Eigen::VectorXd(mean)), NumericalError);

  RandomEngine engine(11);
  const int count = 200000;
  Eigen::MatrixXd samples(4, count);
  for (int k = 0; k < count; ++k) {
    g.sample(engine, samples.col(k));
    ASSERT_EQ(samples(1, k), 2.0);
    ASSERT_EQ(samples(3, k), 4.0);
  }
  expectMomentsMatch(samples, mean, Q);
}

TEST(Gaussian, RankOneSamplesLieOnTheLine) {
  // P = v v^T: x - mean = s v with s ~ N(0, 1).
  const Eigen::Vector3d v(1.0, 2.0, -1.0);
  const Eigen::Matrix3d P = v * v.transpose();
  const Eigen::Vector3d mean(0.0, 1.0, 2.0);
  const MultivariateGaussian<3> g(mean, P);
  RandomEngine engine(3);
  const int count = 200000;
  double sumOfSquares = 0.0;
  for (int k = 0; k < count; ++k) {
    const Eigen::Vector3d d = g.sample(engine) - mean;
    const double s = d.dot(v) / v.squaredNorm();
    ASSERT_LT((d - s * v).norm(), 1e-12);
    sumOfSquares += s * s;
  }
  // E[s^2] = 1, SE = sqrt(2 / n)
  EXPECT_NEAR(sumOfSquares / count, 1.0, 5.0 * std::sqrt(2.0 / count));
}

TEST(Gaussian, SamplingStatisticsMatchMeanAndCovariance) {
  // Diagonal increasing so that the LDLT pivots reorder the rows.
  Eigen::Matrix3d P;
  P << 1.0, 0.5, 0.2,  //
      0.5, 4.0, -1.0,  //
      0.2, -1.0, 9.0;
  const Eigen::Vector3d mean(1.0, -2.0, 0.5);
  const MultivariateGaussian<3> g(mean, P);
  RandomEngine engine(2024);
  const int count = 200000;
  Eigen::MatrixXd samples(3, count);
  for (int k = 0; k < count; ++k) samples.col(k) = g.sample(engine);
  expectMomentsMatch(samples, mean, P);
}

TEST(Gaussian, InPlaceSampleEqualsMeanPlusSquareRootTimesNormals) {
  Eigen::Matrix3d P;
  P << 1.0, 0.5, 0.2, 0.5, 4.0, -1.0, 0.2, -1.0, 9.0;
  const Eigen::Vector3d mean(1.0, -2.0, 0.5);
  const MultivariateGaussian<Eigen::Dynamic> g(mean, P);
  RandomEngine sampler(99);
  RandomEngine reference(99);
  Eigen::MatrixXd particles(3, 4);
  for (Index k = 0; k < particles.cols(); ++k) {
    g.sample(sampler, particles.col(k));
    Eigen::VectorXd z(3);
    fillStandardNormal(reference, z);
    const Eigen::VectorXd expected = mean + g.squareRoot() * z;
    EXPECT_LT((particles.col(k) - expected).norm(), 1e-12);
  }
}

TEST(Gaussian, SampleRejectsAnOutputOfTheWrongSize) {
  const MultivariateGaussian<Eigen::Dynamic> g(Eigen::VectorXd::Zero(2),
                                               Eigen::MatrixXd::Identity(2, 2));
  RandomEngine engine(1);
  Eigen::VectorXd out(3);
  EXPECT_THROW(g.sample(engine, out), InvalidInputError);
}

TEST(Gaussian, ConstructorRejectsInvalidCovariances) {
  Eigen::Matrix2d indefinite;
  indefinite << 1.0, 2.0, 2.0, 1.0;  // eigenvalues 3 and -1
  EXPECT_THROW(MultivariateGaussian<2>(Eigen::Vector2d::Zero(), indefinite), NumericalError);

  Eigen::Matrix2d negativeVariance;
  negativeVariance << 1.0, 0.0, 0.0, -1e-3;
  EXPECT_THROW(MultivariateGaussian<2>(Eigen::Vector2d::Zero(), negativeVariance), NumericalError);

  Eigen::Matrix2d notFinite = Eigen::Matrix2d::Identity();
  notFinite(1, 1) = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(MultivariateGaussian<2>(Eigen::Vector2d::Zero(), notFinite), NumericalError);

  Eigen::Matrix2d asymmetric;
  asymmetric << 1.0, 0.5, 0.4, 1.0;
  EXPECT_THROW(MultivariateGaussian<2>(Eigen::Vector2d::Zero(), asymmetric), NumericalError);

  try {
    MultivariateGaussian<Eigen::Dynamic>(Eigen::VectorXd::Zero(2), Eigen::MatrixXd::Identity(3, 3));
    FAIL() << "expected ParameterError";
  } catch (const ParameterError& e) {
    EXPECT_NE(std::string(e.what()).find("covariance"), std::string::npos) << e.what();
  }
  try {
    MultivariateGaussian<2>(Eigen::Vector2d(0.0, std::nan("")), Eigen::Matrix2d::Identity());
    FAIL() << "expected ParameterError";
  } catch (const ParameterError& e) {
    EXPECT_NE(std::string(e.what()).find("mean"), std::string::npos) << e.what();
  }
}

TEST(CovarianceSquareRoot, ReconstructsPositiveDefiniteAndSemiDefiniteMatrices) {
  Eigen::Matrix3d pivoted;
  pivoted << 1.0, 0.5, 0.2, 0.5, 4.0, -1.0, 0.2, -1.0, 9.0;
  const Eigen::Matrix3d S = covarianceSquareRoot(pivoted);
  EXPECT_LT((S * S.transpose() - pivoted).cwiseAbs().maxCoeff(), 1e-12);

  Eigen::MatrixXd semiDefinite = Eigen::MatrixXd::Zero(4, 4);
  semiDefinite(0, 0) = 2.0;
  semiDefinite(0, 2) = semiDefinite(2, 0) = 0.5;
  semiDefinite(2, 2) = 1.0;
  const Eigen::MatrixXd T = covarianceSquareRoot(semiDefinite);
  EXPECT_LT((T * T.transpose() - semiDefinite).cwiseAbs().maxCoeff(), 1e-12);
  EXPECT_EQ(T.row(1).cwiseAbs().maxCoeff(), 0.0);
  EXPECT_EQ(T.row(3).cwiseAbs().maxCoeff(), 0.0);

  EXPECT_EQ(covarianceSquareRoot(Eigen::Matrix2d::Zero()).cwiseAbs().maxCoeff(), 0.0);
}

TEST(CovarianceSquareRoot, ClampsRoundingSizeNegativePivotsAndRejectsNegativeOnes) {
  // Second LDLT pivot: (1 - 1e-13) - 1 * 1 = -1e-13, a rounding error of a singular matrix.
  Eigen::Matrix2d almostSingular;
  almostSingular << 1.0, 1.0, 1.0, 1.0 - 1e-13;
  const Eigen::Matrix2d S = covarianceSquareRoot(almostSingular);
  EXPECT_TRUE(S.allFinite());
  EXPECT_LT((S * S.transpose() - almostSingular).cwiseAbs().maxCoeff(), 1e-12);

  // Second pivot (1 - 1e-3) - 1 = -1e-3: clearly indefinite.
  Eigen::Matrix2d indefinite;
  indefinite << 1.0, 1.0, 1.0, 1.0 - 1e-3;
  EXPECT_THROW(covarianceSquareRoot(indefinite), NumericalError);
  EXPECT_THROW(covarianceSquareRoot(Eigen::MatrixXd::Identity(2, 3)), ParameterError);
}

TEST(FillStandardNormal, DrawsHaveStandardNormalMomentsAndTails) {
  RandomEngine engine(5);
  const int count = 200000;
  Eigen::VectorXd draws(count);
  fillStandardNormal(engine, draws);
  const double mean = draws.mean();
  const double variance = (draws.array() - mean).square().mean();
  EXPECT_NEAR(mean, 0.0, 5.0 / std::sqrt(count));            // SE 1/sqrt(n)
  EXPECT_NEAR(variance, 1.0, 5.0 * std::sqrt(2.0 / count));  // SE sqrt(2/n)
  // P(|x| > 2) = erfc(2 / sqrt 2) = 0.0455003, binomial SE sqrt(p (1 - p) / n)
  const double p = std::erfc(std::sqrt(2.0));
  const double tailFraction = static_cast<double>((draws.array().abs() > 2.0).count()) / count;
  EXPECT_NEAR(tailFraction, p, 5.0 * std::sqrt(p * (1.0 - p) / count));
}

TEST(FillStandardNormal, FillsMatrixBlocksAndIsReproducibleForASeed) {
  RandomEngine first(42);
  RandomEngine second(42);
  Eigen::MatrixXd a = Eigen::MatrixXd::Zero(3, 4);
  Eigen::MatrixXd b = Eigen::MatrixXd::Zero(3, 4);
  fillStandardNormal(first, a.rightCols(2));
  fillStandardNormal(second, b.rightCols(2));
  EXPECT_EQ(a, b);
  EXPECT_EQ(a.leftCols(2).cwiseAbs().maxCoeff(), 0.0);  // outside the block untouched
  EXPECT_GT(a.rightCols(2).cwiseAbs().minCoeff(), 0.0);
}

TEST(LogSumExp, MatchesDirectSumAndAvoidsOverflow) {
  // log(1 + 2 + 3) = log 6
  EXPECT_NEAR(logSumExp(Eigen::Vector3d(std::log(1.0), std::log(2.0), std::log(3.0))),
              std::log(6.0), 1e-15);
  // exp(1000) overflows: the result is 1000 + log 2 = 1000.6931471805599
  EXPECT_NEAR(logSumExp(Eigen::Vector2d(1000.0, 1000.0)), 1000.6931471805599, 1e-12);
  // exp(-1000) underflows: -1000 + log(1 + e^-1) = -999.6867383124818
  EXPECT_NEAR(logSumExp(Eigen::Vector2d(-1000.0, -1001.0)), -999.6867383124818, 1e-12);
  const double inf = std::numeric_limits<double>::infinity();
  EXPECT_EQ(logSumExp(Eigen::Vector2d(-inf, -inf)), -inf);
  EXPECT_EQ(logSumExp(Eigen::VectorXd(0)), -inf);
  EXPECT_NEAR(logSumExp(Eigen::Vector2d(-inf, 0.5)), 0.5, 1e-15);
  EXPECT_TRUE(std::isnan(logSumExp(Eigen::Vector2d(std::nan(""), 0.0))));
}

}  // namespace
