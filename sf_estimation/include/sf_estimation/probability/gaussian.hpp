// The multivariate normal distribution and the random-number helpers built on it: density for
// likelihoods, sampling for particle filters, log-space normalisation of weights.
//
// Sampling accepts a positive SEMI-definite covariance, because process noise with zero rows
// (states driven only by other states, as in the thesis's EKF Q) is common; the density needs
// a positive definite covariance and refuses only when it is actually asked for.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <string>
#include <type_traits>
#include <utility>

#include <Eigen/Cholesky>
#include <Eigen/Core>
#include <boost/random/mersenne_twister.hpp>
#include <boost/random/normal_distribution.hpp>
#include <boost/random/uniform_01.hpp>

#include "sf_estimation/errors.hpp"
#include "sf_estimation/probability/cholesky.hpp"
#include "sf_estimation/types.hpp"

namespace estimation {
namespace probability {

/// The seedable engine used by the library's stochastic filters: the 64-bit Mersenne Twister.
/// Boost's implementation yields exactly the sequence of std::mt19937_64 for every seed (and
/// seed sequence) but draws about 2.8x faster with GCC 12 at -O2, which matters to a particle
/// filter drawing thousands of normals per step.
using RandomEngine = boost::random::mt19937_64;

namespace detail {

/// Engines known to yield 64 random bits per call (min() is not constexpr in Boost 1.74).
template <class Engine>
constexpr bool kYields64Bits =
    std::is_same_v<Engine, RandomEngine> || std::is_same_v<Engine, std::mt19937_64>;

/// The rare cases of standardNormal64() (about 1% of draws), Boost's own code: the base
/// layer's tail, and the test between a layer's bounds. False: rejected, draw again.
template <class Engine>
bool standardNormal64Rare(Engine& engine, double x, int i, int sign, double& result) {
  using Unit = boost::random::detail::unit_normal_distribution<double>;
  const double* const tableX = boost::random::detail::normal_table<double>::table_x;
  const double* const tableY = boost::random::detail::normal_table<double>::table_y;
  if (i == 0) {
    result = Unit().generate_tail(engine) * sign + 0.0;
    return true;
  }
  const double y01 = boost::random::uniform_01<double>()(engine);
  const double y = tableY[i] + y01 * (tableY[i + 1] - tableY[i]);
  double yAboveUpperBound, yAboveLowerBound;
  if (tableX[i] >= 1) {
    yAboveUpperBound = (tableX[i] - tableX[i + 1]) * y01 - (tableX[i] - x);
    yAboveLowerBound = y - (tableY[i] + (tableX[i] - x) * tableY[i] * tableX[i]);
  } else {
    yAboveLowerBound = (tableX[i] - tableX[i + 1]) * y01 - (tableX[i] - x);
    yAboveUpperBound = y - (tableY[i] + (tableX[i] - x) * tableY[i] * tableX[i]);
  }
  result = x * sign + 0.0;
  return yAboveUpperBound < 0 && (yAboveLowerBound < 0 || y < Unit::f(x));
}

/// One draw of boost::random::normal_distribution<double>(0, 1) from an engine that yields 64
/// random bits per call (RandomEngine does), bit for bit the value Boost returns. Boost's
/// ziggurat is one function too large for the compiler to inline into a loop, and the call
/// costs about a third of a draw; here its common case (about 99% of draws: one engine call,
/// one comparison with the table) is small enough to be inlined.
template <class Engine>
inline double standardNormal64(Engine& engine) {
  const double* const tableX = boost::random::detail::normal_table<double>::table_x;
  for (;;) {
    // generate_int_float_pair<double, 8>: the low 8 bits pick the layer and the sign, the
    // other 56 bits (bit 11 cleared, as Boost does) the position within the layer.
    std::uint64_t bits = engine();
    const int bucket = static_cast<int>(bits & 0xff);
    bits &= ~(std::uint64_t{1} << 11);
    const double position = static_cast<double>(bits >> 8) * 0x1p-56;
    const int sign = (bucket & 1) * 2 - 1;
    const int i = bucket >> 1;
    const double x = position * tableX[i];
    // "+ 0.0" is normal_distribution's "* sigma + mean" for sigma = 1, mean = 0.
    if (x < tableX[i + 1]) return x * sign + 0.0;
    double result;
    if (standardNormal64Rare(engine, x, i, sign, result)) return result;
  }
}

}  // namespace detail

/// Fills `out` with independent standard normal draws, column by column: exactly the draws of
/// boost::random::normal_distribution<double>, whose ziggurat sampler is several times faster
/// than std::normal_distribution (a particle filter draws thousands of normals per step).
template <class Engine, class Derived>
void fillStandardNormal(Engine& engine, Eigen::MatrixBase<Derived>& out) {
  boost::random::normal_distribution<double> standardNormal;
  for (Index col = 0; col < out.cols(); ++col) {
    for (Index row = 0; row < out.rows(); ++row) {
      if constexpr (detail::kYields64Bits<Engine>) {
        out.coeffRef(row, col) = detail::standardNormal64(engine);
      } else {
        out.coeffRef(row, col) = standardNormal(engine);
      }
    }
  }
}

/// Overload for temporaries such as `matrix.col(i)`.
template <class Engine, class Derived>
void fillStandardNormal(Engine& engine, Eigen::MatrixBase<Derived>&& out) {
  fillStandardNormal(engine, out);
}

/// log(sum(exp(v))) without overflow or underflow: the largest term is factored out. An empty
/// vector or all entries -inf give -inf (zero total weight); a NaN entry gives NaN.
template <class Derived>
double logSumExp(const Eigen::MatrixBase<Derived>& v) {
  if (v.size() == 0) return -std::numeric_limits<double>::infinity();
  if (v.hasNaN()) return std::numeric_limits<double>::quiet_NaN();
  const double largest = v.maxCoeff();
  if (!std::isfinite(largest)) return largest;  // all -inf, or a +inf term dominates
  // Terms below e^-700 cannot change a sum that contains e^0 = 1; clamping them keeps exp
  // from producing denormal numbers, on which x86 arithmetic is many times slower.
  constexpr double kLogFloor = -700.0;
  return largest + std::log((v.array() - largest).max(kLogFloor).exp().sum());
}

/// Square root S of a covariance P with S * S^T = P, from the pivoted LDLT factorisation
/// P = Pi^T L D L^T Pi, S = Pi^T L sqrt(D). Unlike Cholesky (LLT) it exists for positive
/// semi-definite P. Storage is preallocated at construction, so compute() and
/// multiplyInPlace() do not allocate (they can run inside a filter step).
template <int N>
class CovarianceSquareRoot {
 public:
  using MatrixType = Matrix<N, N>;

  /// Pivots of the LDLT that are negative by less than this fraction of the largest diagonal
  /// entry of P are rounding errors of a singular P and are clamped to 0; covariance
  /// propagation in the filters accumulates rounding far below it, while a genuinely
  /// indefinite matrix from a modelling error lies far above.
  static constexpr double kRelativeTolerance = 1e-9;

  explicit CovarianceSquareRoot(Index size = (N == Dynamic ? 0 : N))
      : ldlt_(size),
        factor_(MatrixType::Zero(size, size)),
        transpositions_(size),
        matrix_(MatrixType::Zero(size, size)) {
    transpositions_.setIdentity();
  }

  Index size() const { return matrix_.rows(); }

  /// The square root S (S * S^T = P) of the last covariance given to compute().
  const MatrixType& matrix() const { return matrix_; }

  /// Factors `covariance`. Throws ParameterError on a wrong size and NumericalError when the
  /// covariance is not finite, not symmetric or not positive semi-definite; on a throw the
  /// previously computed root is kept.
  template <class Derived>
  void compute(const Eigen::MatrixBase<Derived>& covariance) {
    const Index n = size();
    if (covariance.rows() != n || covariance.cols() != n) {
      throw ParameterError("covariance must be " + std::to_string(n) + "x" + std::to_string(n) +
                           ", got " + std::to_string(covariance.rows()) + "x" +
                           std::to_string(covariance.cols()));
    }
    factorise(covariance);  // a MatrixType binds directly, anything else is evaluated once
  }

  /// v <- S * v = Pi^T (L sqrt(D) v), without a temporary: row k of the triangular factor
  /// only reads entries j <= k, so rows are computed from the last to the first, each
  /// overwriting an entry no remaining row needs; Pi^T is then a sequence of swaps.
  template <class Derived>
  void multiplyInPlace(Eigen::MatrixBase<Derived>& v) const {
    const Index n = size();
    for (Index k = n - 1; k >= 0; --k) {
      double sum = 0.0;
      for (Index j = 0; j <= k; ++j) sum += factor_(k, j) * v(j);
      v(k) = sum;
    }
    for (Index k = n - 1; k >= 0; --k) {
      const Index other = transpositions_.coeff(k);
      if (other != k) std::swap(v(k), v(other));
    }
  }

 private:
  Eigen::LDLT<MatrixType> ldlt_;  // scratch of compute()
  MatrixType factor_;             // L sqrt(D), in pivoted order
  typename Eigen::LDLT<MatrixType>::TranspositionType transpositions_;  // Pi
  MatrixType matrix_;                                                   // Pi^T L sqrt(D)

  // compute() of a covariance of the right size; out of the class body, so that the library's
  // instances (below) are used instead of compiling it again.
  void factorise(const MatrixType& covariance);
};

template <int N>
void CovarianceSquareRoot<N>::factorise(const MatrixType& covariance) {
  const Index n = size();
  if (!covariance.allFinite()) {
    throw NumericalError("covariance contains a non-finite value");
  }
  const double scale = n == 0 ? 0.0 : covariance.diagonal().cwiseAbs().maxCoeff();
  const double tolerance = kRelativeTolerance * scale;
  for (Index row = 0; row < n; ++row) {
    for (Index col = 0; col < row; ++col) {
      if (std::abs(covariance(row, col) - covariance(col, row)) > tolerance) {
        throw NumericalError("covariance is not symmetric: entry (" + std::to_string(row) + "," +
                             std::to_string(col) + ") differs from its transpose");
      }
    }
  }
  if (n == 0) return;

  ldlt_.compute(covariance);  // only scratch changes before the checks below pass
  if (ldlt_.info() != Eigen::Success) {
    throw NumericalError("covariance is not positive semi-definite (LDLT factorisation failed)");
  }
  const auto& d = ldlt_.vectorD();
  const auto& packed = ldlt_.matrixLDLT();  // strictly lower part holds L
  for (Index k = 0; k < n; ++k) {
    if (!std::isfinite(d(k))) {
      throw NumericalError("covariance factorisation produced a non-finite pivot");
    }
    if (d(k) < -tolerance) {
      throw NumericalError("covariance is not positive semi-definite: LDLT pivot " +
                           std::to_string(d(k)) + " is negative");
    }
    if (d(k) > 0.0 && !packed.col(k).tail(n - k - 1).allFinite()) {
      throw NumericalError("covariance factorisation produced a non-finite factor");
    }
  }

  // Commit. Columns with a zero (or clamped) pivot contribute nothing to P, so they are
  // zeroed instead of multiplied: L below a rounding-size pivot may be huge or infinite.
  for (Index k = 0; k < n; ++k) {
    factor_.col(k).head(k).setZero();
    if (d(k) > 0.0) {
      const double root = std::sqrt(d(k));
      factor_(k, k) = root;
      factor_.col(k).tail(n - k - 1) = root * packed.col(k).tail(n - k - 1);
    } else {
      factor_.col(k).tail(n - k).setZero();
    }
  }
  transpositions_ = ldlt_.transpositionsP();
  matrix_ = factor_;
  matrix_ = transpositions_.transpose() * matrix_;  // row swaps in place, no temporary
}

// The factorisation (a pivoted LDLT) is compiled once in the library for the state sizes of
// the sigma-point and particle filters, 1..7 (sigma_point_steps.cpp.in, unscented_transform.hpp);
// other sizes instantiate it where they use it.
#if !defined(SF_ESTIMATION_INSTANTIATING_SIGMA_POINT_STEPS) && \
    !defined(SF_ESTIMATION_IMPLICIT_INSTANCES)
extern template class CovarianceSquareRoot<1>;
extern template class CovarianceSquareRoot<2>;
extern template class CovarianceSquareRoot<3>;
extern template class CovarianceSquareRoot<4>;
extern template class CovarianceSquareRoot<5>;
extern template class CovarianceSquareRoot<6>;
extern template class CovarianceSquareRoot<7>;
#endif

/// Returns S with S * S^T = P for a positive semi-definite P (see CovarianceSquareRoot).
template <class Derived>
Matrix<Derived::RowsAtCompileTime, Derived::RowsAtCompileTime> covarianceSquareRoot(
    const Eigen::MatrixBase<Derived>& covariance) {
  CovarianceSquareRoot<Derived::RowsAtCompileTime> root(covariance.rows());
  root.compute(covariance);
  return root.matrix();
}

/// Normal distribution N(mean, covariance) of dimension N (Eigen::Dynamic allowed). The
/// covariance is factored once at construction.
template <int N>
class MultivariateGaussian {
 public:
  using Vector = estimation::Vector<N>;
  using Matrix = estimation::Matrix<N, N>;

  /// Throws ParameterError on mismatched sizes or a non-finite mean, NumericalError when the
  /// covariance is not symmetric positive semi-definite.
  MultivariateGaussian(const Vector& mean, const Matrix& covariance)
      : mean_(mean), covariance_(covariance), squareRoot_(mean.size()), llt_(mean.size()) {
    if (!mean_.allFinite()) {
      throw ParameterError("MultivariateGaussian: parameter 'mean' contains a non-finite value");
    }
    if (covariance_.rows() != mean_.size() || covariance_.cols() != mean_.size()) {
      throw ParameterError("MultivariateGaussian: parameter 'covariance' is " +
                           std::to_string(covariance_.rows()) + "x" +
                           std::to_string(covariance_.cols()) + ", the mean has " +
                           std::to_string(mean_.size()) + " entries");
    }
    squareRoot_.compute(covariance_);
    llt_.compute(covariance_);
    positiveDefinite_ = llt_.info() == Eigen::Success;
    double logDeterminant = 0.0;
    for (Index i = 0; positiveDefinite_ && i < dimension(); ++i) {
      const double pivot = llt_.matrixLLT()(i, i);
      positiveDefinite_ = std::isfinite(pivot) && pivot > 0.0;
      if (positiveDefinite_) logDeterminant += 2.0 * std::log(pivot);
    }
    constexpr double kLogTwoPi = 1.8378770664093454836;  // log(2 pi)
    logNormaliser_ = -0.5 * (static_cast<double>(dimension()) * kLogTwoPi + logDeterminant);
  }

  Index dimension() const { return mean_.size(); }
  const Vector& mean() const { return mean_; }
  const Matrix& covariance() const { return covariance_; }
  /// S with S * S^T = covariance, used for sampling.
  const Matrix& squareRoot() const { return squareRoot_.matrix(); }
  /// False for a semi-definite covariance: such a Gaussian can be sampled but has no density.
  bool isPositiveDefinite() const { return positiveDefinite_; }

  /// log N(x; mean, covariance) = -0.5 (m log(2 pi) + log det P + |L^-1 (x - mean)|^2).
  /// Throws NumericalError unless the covariance is positive definite and InvalidInputError
  /// on a wrong size. Allocates a temporary for Eigen::Dynamic; see the workspace overload.
  template <class Derived>
  double logDensity(const Eigen::MatrixBase<Derived>& x) const {
    Vector workspace(dimension());
    return logDensity(x, workspace);
  }

  /// As logDensity(x), using the caller's preallocated `workspace` (size dimension()) so that
  /// repeated evaluations, e.g. one per particle, do not allocate.
  template <class Derived>
  double logDensity(const Eigen::MatrixBase<Derived>& x, Vector& workspace) const {
    requirePositiveDefinite();
    if (x.size() != dimension()) {
      throw InvalidInputError("MultivariateGaussian: point has " + std::to_string(x.size()) +
                              " entries, the distribution has " + std::to_string(dimension()));
    }
    workspace = x - mean_;
    llt_.matrixL().solveInPlace(workspace);
    return logNormaliser_ - 0.5 * workspace.squaredNorm();
  }

  template <class Derived>
  double density(const Eigen::MatrixBase<Derived>& x) const {
    return std::exp(logDensity(x));
  }

  template <class Engine>
  Vector sample(Engine& engine) const {
    Vector out(dimension());
    sample(engine, out);
    return out;
  }

  /// Writes one draw into `out` (size dimension(); e.g. a column of a particle matrix)
  /// without allocating. Components with zero variance are exactly the mean.
  template <class Engine, class Out>
  void sample(Engine& engine, Out&& out) const {
    if (out.size() != dimension()) {
      throw InvalidInputError("MultivariateGaussian: sample output has " +
                              std::to_string(out.size()) + " entries, the distribution has " +
                              std::to_string(dimension()));
    }
    fillStandardNormal(engine, out);
    squareRoot_.multiplyInPlace(out);
    out += mean_;
  }

 private:
  void requirePositiveDefinite() const {
    if (!positiveDefinite_) {
      throw NumericalError(
          "MultivariateGaussian: covariance is not positive definite, the density is undefined "
          "(the distribution can only be sampled)");
    }
  }

  Vector mean_;
  Matrix covariance_;
  CovarianceSquareRoot<N> squareRoot_;
  Eigen::LLT<Matrix> llt_;
  bool positiveDefinite_ = false;
  double logNormaliser_ = 0.0;
};

}  // namespace probability
}  // namespace estimation
