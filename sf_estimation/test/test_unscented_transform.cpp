// The unscented transform's weighted sums over sigma points (unscented_transform.hpp): the
// cross-covariance against a hand-computed example and against the sum written out point by
// point, an exactly symmetric covariance, and the run-time-sized transform (the factory's)
// against the fixed-size one.
#include <cmath>

#include <gtest/gtest.h>

#include <Eigen/Core>

#include "sf_estimation/unscented_transform.hpp"

namespace {

using estimation::Dynamic;
using estimation::Index;
using estimation::Matrix;
using estimation::UnscentedParameters;
using estimation::UnscentedTransform;
using estimation::Vector;

// n = 1, alpha = 1, beta = 0, kappa = 2: lambda = 1 * (1 + 2) - 1 = 2, so the covariance weights
// are Wc0 = 2/3 + 1 - 1 + 0 = 2/3 and Wc1 = Wc2 = 1 / (2 (n + lambda)) = 1/6.
UnscentedParameters handParameters() {
  UnscentedParameters p;
  p.alpha = 1.0;
  p.beta = 0.0;
  p.kappa = 2.0;
  return p;
}

TEST(UnscentedTransform, CrossCovarianceHandComputed) {
  const UnscentedTransform<1> ut(1, handParameters());
  ASSERT_DOUBLE_EQ(ut.covarianceWeights()(0), 2.0 / 3.0);
  ASSERT_DOUBLE_EQ(ut.covarianceWeights()(1), 1.0 / 6.0);
  Matrix<1, 3> a;
  a << 1, 4, -2;  // deviations from 1: 0, 3, -3
  Vector<1> aMean;
  aMean << 1;
  Matrix<2, 3> b;
  b << 0, 1, -1,  // deviations from 0: 0, 1, -1
      2, 2, 5;    // deviations from 3: -1, -1, 2
  Vector<2> bMean;
  bMean << 0, 3;
  // 2/3 * 0 * (0, -1) + 1/6 * 3 * (1, -1) + 1/6 * (-3) * (-1, 2) = (1, -1.5)
  Matrix<1, 2> cross;
  ut.crossCovariance(a, aMean, b, bMean, cross);
  EXPECT_DOUBLE_EQ(cross(0, 0), 1.0);
  EXPECT_DOUBLE_EQ(cross(0, 1), -1.5);
  // 1/6 * 9 + 1/6 * 9 = 3
  Matrix<1, 1> variance;
  ut.crossCovariance(a, aMean, a, aMean, variance);
  EXPECT_DOUBLE_EQ(variance(0, 0), 3.0);
}

// Points of a 3-state transform (7 points) and of a 2-row measurement, not symmetric about
// their means, rows of different magnitudes; `set` shifts every phase.
struct ThreeStatePoints {
  Matrix<3, 7> x;
  Vector<3> xMean;
  Matrix<2, 7> z;
  Vector<2> zMean;
  explicit ThreeStatePoints(int set = 0) {
    const double scales[3] = {1.0, 10.0, 0.01};
    const double shift = 0.37 * set;
    for (Index i = 0; i < 3; ++i) {
      xMean(i) = scales[i] * std::cos(1.0 + static_cast<double>(i) + shift);
      for (Index k = 0; k < 7; ++k)
        x(i, k) = scales[i] *
                  std::sin(1.3 * static_cast<double>(i) + 0.7 * static_cast<double>(k) + shift);
    }
    for (Index i = 0; i < 2; ++i) {
      zMean(i) = 100.0 * static_cast<double>(i) + std::sin(2.0 + shift);
      for (Index k = 0; k < 7; ++k)
        z(i, k) =
            100.0 * static_cast<double>(i) + std::cos(0.9 * static_cast<double>(k + i) + shift);
    }
  }
};

// sum_i Wc_i (a_i - aMean)(b_i - bMean)^T, point by point.
template <class A, class AMean, class B, class BMean, class Weights>
Eigen::MatrixXd pointByPoint(const A& a, const AMean& aMean, const B& b, const BMean& bMean,
                             const Weights& wc) {
  Eigen::MatrixXd sum = Eigen::MatrixXd::Zero(a.rows(), b.rows());
  for (Index i = 0; i < a.cols(); ++i) {
    const Eigen::VectorXd da = a.col(i) - aMean;
    const Eigen::VectorXd db = b.col(i) - bMean;
    sum += wc(i) * da * db.transpose();
  }
  return sum;
}

TEST(UnscentedTransform, CrossCovarianceIsTheSumOverPoints) {
  UnscentedParameters p;
  p.alpha = 0.5;
  const UnscentedTransform<3> ut(3, p);
  const ThreeStatePoints s;
  Matrix<3, 2> cross;
  ut.crossCovariance(s.x, s.xMean, s.z, s.zMean, cross);
  const Eigen::MatrixXd expected = pointByPoint(s.x, s.xMean, s.z, s.zMean, ut.covarianceWeights());
  const double scale = expected.cwiseAbs().maxCoeff();
  for (Index i = 0; i < 3; ++i)
    for (Index j = 0; j < 2; ++j) EXPECT_NEAR(cross(i, j), expected(i, j), 1e-13 * scale);
}

// Each entry summed on its own would round the products of Wc_k and the deviations a_ik, a_jk
// differently for (i, j) and (j, i): in 54 of the 180 off-diagonal entries of these 20 sets, for
// a plain product of the weighted deviations (measured). The transform forms one triangle.
TEST(UnscentedTransform, CovarianceIsSymmetricToTheBit) {
  UnscentedParameters p;
  p.alpha = 0.5;
  const UnscentedTransform<3> ut(3, p);
  for (int set = 0; set < 20; ++set) {
    const ThreeStatePoints s(set);
    Matrix<3, 3> P;
    ut.crossCovariance(s.x, s.xMean, s.x, s.xMean, P);
    const Eigen::MatrixXd expected =
        pointByPoint(s.x, s.xMean, s.x, s.xMean, ut.covarianceWeights());
    const double scale = expected.cwiseAbs().maxCoeff();
    for (Index i = 0; i < 3; ++i) {
      for (Index j = 0; j < 3; ++j) {
        EXPECT_EQ(P(i, j), P(j, i)) << "set " << set << ", entry (" << i << ", " << j << ")";
        EXPECT_NEAR(P(i, j), expected(i, j), 1e-13 * scale);
      }
    }
  }
}

TEST(UnscentedTransform, RunTimeSizeMatchesFixedSize) {
  UnscentedParameters p;
  p.alpha = 0.5;
  const UnscentedTransform<3> fixed(3, p);
  const UnscentedTransform<Dynamic> runTime(3, p);
  const ThreeStatePoints s;
  Matrix<3, 2> crossFixed;
  fixed.crossCovariance(s.x, s.xMean, s.z, s.zMean, crossFixed);
  const Eigen::MatrixXd x = s.x, z = s.z;
  const Eigen::VectorXd xMean = s.xMean, zMean = s.zMean;
  Eigen::MatrixXd crossRunTime, covarianceRunTime;
  runTime.crossCovariance(x, xMean, z, zMean, crossRunTime);
  runTime.crossCovariance(x, xMean, x, xMean, covarianceRunTime);
  ASSERT_EQ(crossRunTime.rows(), 3);
  ASSERT_EQ(crossRunTime.cols(), 2);
  const double scale = crossFixed.cwiseAbs().maxCoeff();
  for (Index i = 0; i < 3; ++i)
    for (Index j = 0; j < 2; ++j) EXPECT_NEAR(crossRunTime(i, j), crossFixed(i, j), 1e-14 * scale);
  Matrix<3, 3> covarianceFixed;
  fixed.crossCovariance(s.x, s.xMean, s.x, s.xMean, covarianceFixed);
  for (Index i = 0; i < 3; ++i) {
    for (Index j = 0; j < 3; ++j) {
      EXPECT_EQ(covarianceRunTime(i, j), covarianceRunTime(j, i));
      EXPECT_NEAR(covarianceRunTime(i, j), covarianceFixed(i, j),
                  1e-14 * covarianceFixed.cwiseAbs().maxCoeff());
    }
  }
}

}  // namespace
