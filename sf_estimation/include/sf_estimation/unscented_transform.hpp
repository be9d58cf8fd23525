// The scaled unscented transform (thesis eqs. 3.5-3.10): sigma points of a Gaussian and the
// weighted mean, covariance and cross-covariance of transformed points.
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include <Eigen/Cholesky>

#include "sf_estimation/angles.hpp"
#include "sf_estimation/errors.hpp"
#include "sf_estimation/kalman_correction.hpp"  // SF_ESTIMATION_FOR_MEASUREMENT_SIZES
#include "sf_estimation/probability/gaussian.hpp"
#include "sf_estimation/small_products.hpp"
#include "sf_estimation/types.hpp"

namespace estimation {

/// Which point the UKF's time update takes as the predicted mean.
enum class PredictedMean {
  /// The weighted mean of the propagated sigma points (thesis Algorithm 3.3, Julier and
  /// Uhlmann): the mean is corrected to second order for the curvature of f.
  SigmaPointAverage,
  /// f of the mean itself, the sigma points giving only the covariance (UKF-M, Brossard,
  /// Barrau and Bonnabel 2020). Where f rotates a velocity by an uncertain heading, the
  /// second-order correction is the mean of cos(theta) over the heading's spread, which
  /// shrinks each step by 1 - sigma^2 / 2 and points backwards past 2 rad^2: a dead-reckoned
  /// track contracts. The propagated mean keeps the step's length, as the EKF does.
  Propagated,
};

struct UnscentedParameters {
  double alpha = 1e-3;  ///< spread of the sigma points around the mean
  double beta = 2.0;    ///< prior knowledge of the distribution (2 is optimal for Gaussians)
  double kappa = 0.0;   ///< secondary scaling
  PredictedMean predictedMean = PredictedMean::SigmaPointAverage;
};

template <int N>
class UnscentedTransform {
 public:
  static constexpr int PointCount = sigmaPointCount(N);
  template <int Rows>
  using Points = Matrix<Rows, PointCount>;

  UnscentedTransform(Index n, const UnscentedParameters& p) : n_(n), params_(p) {
    if (!(p.alpha > 0.0) || !std::isfinite(p.alpha) || !std::isfinite(p.beta) ||
        !std::isfinite(p.kappa)) {
      throw ParameterError(
          "UnscentedKalmanFilter: parameter 'alpha' must be positive and "
          "alpha, beta, kappa finite");
    }
    lambda_ = p.alpha * p.alpha * (static_cast<double>(n) + p.kappa) - static_cast<double>(n);
    if (!(static_cast<double>(n) + lambda_ > 0.0)) {
      throw ParameterError(
          "UnscentedKalmanFilter: n + lambda = alpha^2 (n + kappa) must be "
          "positive; check 'alpha' and 'kappa'");
    }
    const Index count = 2 * n + 1;
    meanWeights_.setConstant(count, 0.5 / (static_cast<double>(n) + lambda_));
    covarianceWeights_ = meanWeights_;
    meanWeights_(0) = lambda_ / (static_cast<double>(n) + lambda_);
    covarianceWeights_(0) = meanWeights_(0) + 1.0 - p.alpha * p.alpha + p.beta;
  }

  Index pointCount() const { return 2 * n_ + 1; }
  const UnscentedParameters& parameters() const { return params_; }

  /// Spread the sigma points of (mean, P) need to resolve every state: a point is stored to
  /// about eps |x_i|, and the transform's sums amplify that by its weights, so that the
  /// relative error of the covariance is about eps |x_i| / (alpha sqrt(n + kappa) sigma_i).
  /// Returns the smallest alpha that keeps it below 1 / kResolution for every state (capped
  /// at 1), or the configured alpha when that suffices. A state far from the origin with a
  /// small variance (a global coordinate, a time stamp) needs a larger alpha than 1e-3.
  static constexpr double kResolution = 1e6;
  double alphaFor(const Vector<N>& mean, const Matrix<N, N>& P) const {
    const double nk = static_cast<double>(n_) + params_.kappa;
    double alpha = params_.alpha;
    for (Index i = 0; i < n_; ++i) {
      if (!(P(i, i) > 0.0)) continue;
      const double offset =
          kResolution * std::numeric_limits<double>::epsilon() * std::abs(mean(i));
      // needed <= alpha, decided without a square root and a division (the usual case).
      if (nk > 0.0 && offset * offset <= alpha * alpha * nk * P(i, i)) continue;
      const double needed = offset / std::sqrt(nk * P(i, i));
      alpha = std::max(alpha, std::min(1.0, needed));
    }
    return alpha;
  }
  double lambda() const { return lambda_; }
  const Vector<PointCount>& meanWeights() const { return meanWeights_; }
  const Vector<PointCount>& covarianceWeights() const { return covarianceWeights_; }

  /// Columns: mean, mean + i-th column of sqrt((n+lambda) P), mean - that column.
  void sigmaPoints(const Vector<N>& mean, const Matrix<N, N>& P, Points<N>& points) const;

  /// The sigma points from the Cholesky factor of (n+lambda) P; false (points unset) when
  /// P is not positive definite. That factor also proves P needs no repair
  /// (numerical_repairs.hpp), so a filter that tries this first pays for one factorisation.
  bool choleskySigmaPoints(const Vector<N>& mean, const Matrix<N, N>& P, Points<N>& points) const;

  /// Weighted mean of the points, taken as the central point (column 0) plus the weighted
  /// mean of the other points' deviations from it. Mathematically this is sum_i Wm_i p_i (the
  /// weights sum to 1); numerically it avoids cancelling a large offset against the huge,
  /// opposite weights of a small alpha (Wm_0 = -1e6 for alpha = 1e-3, n = 1): a state at 1e9
  /// with a variance of 1 would otherwise get its mean wrong by 1e9 * 1e6 * 1e-16 = 0.1, and
  /// its covariance negative. Angle rows average wrapped deviations (angles.hpp, meanAround):
  /// exact on the circle as long as every point lies within pi of the central one.
  template <int Rows>
  void mean(const Points<Rows>& points, Vector<Rows>& result,
            const AngleMask<Rows>& angles = AngleMask<Rows>()) const;

  /// sum_i Wc_i (a_i - aMean)(b_i - bMean)^T; with a = b this is the covariance. The
  /// deviations of the rows marked in aAngles / bAngles are wrapped to (-pi, pi].
  template <int RowsA, int RowsB>
  void crossCovariance(const Points<RowsA>& a, const Vector<RowsA>& aMean, const Points<RowsB>& b,
                       const Vector<RowsB>& bMean, Matrix<RowsA, RowsB>& result,
                       const AngleMask<RowsA>& aAngles = AngleMask<RowsA>(),
                       const AngleMask<RowsB>& bAngles = AngleMask<RowsB>()) const;

 private:
  void fillPoints(const Vector<N>& mean, const Matrix<N, N>& root, Points<N>& points) const;

  Index n_;
  UnscentedParameters params_;
  double lambda_ = 0.0;
  Vector<PointCount> meanWeights_, covarianceWeights_;
};

template <int N>
void UnscentedTransform<N>::sigmaPoints(const Vector<N>& mean, const Matrix<N, N>& P,
                                        Points<N>& points) const {
  if (choleskySigmaPoints(mean, P, points)) return;
  // Singular but valid covariances (a state known exactly) have no Cholesky factor; the
  // LDLT-based root handles them and throws NumericalError for indefinite ones.
  const Matrix<N, N> scaled = (static_cast<double>(n_) + lambda_) * P;
  probability::CovarianceSquareRoot<N> semiDefiniteRoot(n_);
  semiDefiniteRoot.compute(scaled);
  fillPoints(mean, semiDefiniteRoot.matrix(), points);
}

template <int N>
bool UnscentedTransform<N>::choleskySigmaPoints(const Vector<N>& mean, const Matrix<N, N>& P,
                                                Points<N>& points) const {
  Matrix<N, N> root = (static_cast<double>(n_) + lambda_) * P;
  if (!probability::choleskyInPlace(root)) return false;
  // Element by element: at N = 1 the loop never runs, yet GCC 12 warned (-Warray-bounds) about
  // the vectorized store of a column block it saw there.
  for (Index col = 1; col < n_; ++col)
    for (Index row = 0; row < col; ++row) root(row, col) = 0.0;
  fillPoints(mean, root, points);
  return true;
}

template <int N>
template <int Rows>
void UnscentedTransform<N>::mean(const Points<Rows>& points, Vector<Rows>& result,
                                 const AngleMask<Rows>& angles) const {
  const Vector<Rows> reference = points.col(0);
  Points<Rows> deviations = points.colwise() - reference;
  angles.wrap(deviations);
  result.resize(points.rows());
  multiply<Store::Assign>(deviations, meanWeights_, result);
  result += reference;
  angles.wrap(result);
}

template <int N>
template <int RowsA, int RowsB>
void UnscentedTransform<N>::crossCovariance(const Points<RowsA>& a, const Vector<RowsA>& aMean,
                                            const Points<RowsB>& b, const Vector<RowsB>& bMean,
                                            Matrix<RowsA, RowsB>& result,
                                            const AngleMask<RowsA>& aAngles,
                                            const AngleMask<RowsB>& bAngles) const {
  Points<RowsA> deviationsA = a.colwise() - aMean;
  aAngles.wrap(deviationsA);
  Points<RowsB> deviationsB = b.colwise() - bMean;
  bAngles.wrap(deviationsB);
  if constexpr (N != Dynamic && RowsA != Dynamic && RowsB != Dynamic) {
    // At fixed sizes each entry is one dot product over the points, of deviations stored
    // transposed so that the dot runs over contiguous memory. As one matrix product Eigen
    // would pick its blocked GEMM from 2n+1 >= 8 points on, whose packing costs more than
    // the arithmetic. With the same points on both sides the result is a covariance:
    // symmetric, so only its lower triangle is computed.
    using Deviations = Eigen::Matrix<double, PointCount, RowsA>;
    const Deviations da = deviationsA.transpose();
    const Eigen::Matrix<double, PointCount, RowsB> weightedDb =
        covarianceWeights_.asDiagonal() * deviationsB.transpose();
    bool symmetric = false;
    if constexpr (RowsA == RowsB) symmetric = &a == &b && &aMean == &bMean;
    for (Index j = 0; j < result.cols(); ++j) {
      for (Index i = symmetric ? j : 0; i < result.rows(); ++i) {
        result(i, j) = da.col(i).dot(weightedDb.col(j));
        if (symmetric) result(j, i) = result(i, j);
      }
    }
  } else {
    const Points<RowsA> weighted = deviationsA * covarianceWeights_.asDiagonal();
    result.noalias() = weighted * deviationsB.transpose();
    // The product rounds (Wc_k a_ik) a_jk and (Wc_k a_jk) a_ik apart: a covariance takes its
    // lower triangle, as at fixed sizes, so that it is symmetric to the bit.
    if constexpr (RowsA == RowsB) {
      if (&a == &b && &aMean == &bMean) {
        for (Index j = 1; j < result.cols(); ++j)
          for (Index i = 0; i < j; ++i) result(i, j) = result(j, i);
      }
    }
  }
}

template <int N>
void UnscentedTransform<N>::fillPoints(const Vector<N>& mean, const Matrix<N, N>& root,
                                       Points<N>& points) const {
  points.resize(n_, 2 * n_ + 1);
  points.col(0) = mean;
  // Fixed-size column blocks when N is known: a run-time-sized block is several times slower.
  points.template middleCols<N>(1, n_) = root.colwise() + mean;
  points.template middleCols<N>(1 + n_, n_) = (-root).colwise() + mean;
}

// The transform depends only on the sizes: it is compiled once in the library for the state
// sizes 1..7 and measurement sizes 1..6 (cmake/sigma_point_steps.cpp.in), so that a node's
// translation unit does not instantiate it again. The grid stops at 7 states: no shipped
// sigma-point or particle configuration has more, and each further state size costs about
// half a minute and over a gigabyte to compile. Other sizes instantiate it where they use it.
//
// The sums over points of a state's N rows, and of a measurement's M rows with M != N.
#define SF_ESTIMATION_TRANSFORM_MEAN(N, R)                                                        \
  template void UnscentedTransform<N>::mean<R>(const Points<R>&, Vector<R>&, const AngleMask<R>&) \
      const;
#define SF_ESTIMATION_TRANSFORM_COVARIANCE(N, A, B)                                          \
  template void UnscentedTransform<N>::crossCovariance<A, B>(                                \
      const Points<A>&, const Vector<A>&, const Points<B>&, const Vector<B>&, Matrix<A, B>&, \
      const AngleMask<A>&, const AngleMask<B>&) const;
#define SF_ESTIMATION_TRANSFORM_STATE_ROWS(N) \
  SF_ESTIMATION_TRANSFORM_MEAN(N, N) SF_ESTIMATION_TRANSFORM_COVARIANCE(N, N, N)
#define SF_ESTIMATION_TRANSFORM_ROWS(N, M) \
  SF_ESTIMATION_TRANSFORM_MEAN(N, M)       \
  SF_ESTIMATION_TRANSFORM_COVARIANCE(N, M, M) SF_ESTIMATION_TRANSFORM_COVARIANCE(N, N, M)
#if !defined(SF_ESTIMATION_INSTANTIATING_SIGMA_POINT_STEPS) && \
    !defined(SF_ESTIMATION_IMPLICIT_INSTANCES)
// Declared for every M in 1..6: a repeated explicit instantiation declaration (M = N) is
// allowed, unlike a repeated definition.
#define SF_ESTIMATION_EXTERN_TRANSFORM_ROWS(N, M)                                      \
  extern SF_ESTIMATION_TRANSFORM_MEAN(N, M) extern SF_ESTIMATION_TRANSFORM_COVARIANCE( \
      N, M, M) extern SF_ESTIMATION_TRANSFORM_COVARIANCE(N, N, M)
#define SF_ESTIMATION_EXTERN_TRANSFORM(N)                                                      \
  extern template class UnscentedTransform<N>;                                                 \
  extern SF_ESTIMATION_TRANSFORM_MEAN(N, N) extern SF_ESTIMATION_TRANSFORM_COVARIANCE(N, N, N) \
      SF_ESTIMATION_FOR_MEASUREMENT_SIZES(SF_ESTIMATION_EXTERN_TRANSFORM_ROWS, N)
SF_ESTIMATION_EXTERN_TRANSFORM(1)
SF_ESTIMATION_EXTERN_TRANSFORM(2)
SF_ESTIMATION_EXTERN_TRANSFORM(3)
SF_ESTIMATION_EXTERN_TRANSFORM(4)
SF_ESTIMATION_EXTERN_TRANSFORM(5)
SF_ESTIMATION_EXTERN_TRANSFORM(6)
SF_ESTIMATION_EXTERN_TRANSFORM(7)
#undef SF_ESTIMATION_EXTERN_TRANSFORM
#undef SF_ESTIMATION_EXTERN_TRANSFORM_ROWS
#endif

}  // namespace estimation
