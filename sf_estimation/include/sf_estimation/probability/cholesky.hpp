// Cholesky factorisation of the small fixed-size matrices of a filter step, as plain loops.
// Its own header so that a check needing only this (measurement.hpp) does not include the
// random-number code of gaussian.hpp, nor instantiate Eigen::LLT for every measurement size.
#pragma once

#include <cmath>

#include "sf_estimation/types.hpp"

namespace estimation {
namespace probability {

/// The order in which an entry of L below the diagonal takes off the products of the columns
/// before it; the two round differently in the last bits.
enum class CholeskyOrder {
  /// ((A(i,k) - p_0) - p_1) - ...: the sigma points' and the checks' order.
  chained,
  /// A(i,k) - (p_0 + p_1 + ...): Eigen::LLT's, which runs them as a matrix-vector product; with
  /// it the factor is Eigen::LLT's bit for bit (innovationLikelihood).
  sumFirst,
};

/// Cholesky factorisation A = L L^T of a symmetric positive definite matrix, in place: L
/// overwrites the lower triangle (only the lower triangle is read; the strict upper triangle
/// is left as it was). Returns false, like Eigen::LLT, when a pivot is not positive. It is
/// Eigen's unblocked algorithm written as plain loops: Eigen::LLT works on run-time-sized
/// blocks, which costs several times more on the 3x3 to 7x7 matrices of a filter step, and
/// instantiates Eigen's blocked matrix kernels, several seconds of compile time per size.
template <int N, CholeskyOrder order = CholeskyOrder::chained>
bool choleskyInPlace(Matrix<N, N>& A) {
  const Index n = A.rows();
  for (Index k = 0; k < n; ++k) {
    double squares = 0.0;
    for (Index j = 0; j < k; ++j) squares += A(k, j) * A(k, j);
    const double pivot = A(k, k) - squares;
    if (pivot <= 0.0) return false;
    const double diagonal = std::sqrt(pivot);
    A(k, k) = diagonal;
    for (Index i = k + 1; i < n; ++i) {
      if constexpr (order == CholeskyOrder::chained) {
        double sum = A(i, k);
        for (Index j = 0; j < k; ++j) sum -= A(i, j) * A(k, j);
        A(i, k) = sum / diagonal;
      } else {
        double products = 0.0;
        for (Index j = 0; j < k; ++j) products += A(i, j) * A(k, j);
        A(i, k) = (A(i, k) - products) / diagonal;
      }
    }
  }
  return true;
}

/// Whether the symmetric A (its lower triangle is read) is positive definite, by the test of
/// choleskyInPlace (every pivot > 0) without its square roots: the pivots of A = L D L^T are the
/// squares of the Cholesky diagonal. A filter checks every new covariance this way; at these
/// sizes the check costs latency, and a square root per column was most of it. The pivots
/// round differently from choleskyInPlace's, so the two could disagree only about a matrix
/// within rounding of singular, which the repair (numerical_repairs.hpp) then judges anyway.
template <int N>
bool positiveDefinite(const Matrix<N, N>& A) {
  const Index n = A.rows();
  Matrix<N, N> W(n, n);  // below the diagonal: L D, the column before its scaling by 1 / D
  Vector<N> inverse(n);  // 1 / D
  Vector<N> l(n);        // row k of L
  // Unrolled for a filter's sizes, so that the factor stays in registers between the columns.
#pragma GCC unroll 8
  for (Index k = 0; k < n; ++k) {
    double pivot = A(k, k);
#pragma GCC unroll 8
    for (Index j = 0; j < k; ++j) {
      l(j) = W(k, j) * inverse(j);
      pivot -= l(j) * W(k, j);
    }
    if (pivot <= 0.0) return false;
    inverse(k) = 1.0 / pivot;
#pragma GCC unroll 8
    for (Index i = k + 1; i < n; ++i) {
      double sum = A(i, k);
#pragma GCC unroll 8
      for (Index j = 0; j < k; ++j) sum -= W(i, j) * l(j);
      W(i, k) = sum;
    }
  }
  return true;
}

}  // namespace probability
}  // namespace estimation
