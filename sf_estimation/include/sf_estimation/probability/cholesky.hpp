// Cholesky factorisation of the small fixed-size matrices of a filter step, as plain loops.
// Its own header so that a check needing only this (measurement.hpp) does not include the
// random-number code of gaussian.hpp, nor instantiate Eigen::LLT for every measurement size.
#pragma once

#include <cmath>

#include "sf_estimation/types.hpp"

namespace estimation {
namespace probability {

/// Cholesky factorisation A = L L^T of a symmetric positive definite matrix, in place: L
/// overwrites the lower triangle (only the lower triangle is read; the strict upper triangle
/// is left as it was). Returns false, like Eigen::LLT, when a pivot is not positive. It is
/// Eigen's unblocked algorithm written as plain loops: Eigen::LLT works on run-time-sized
/// blocks, which costs several times more on the 3x3 to 7x7 matrices of a filter step.
template <int N>
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
      double sum = A(i, k);
      for (Index j = 0; j < k; ++j) sum -= A(i, j) * A(k, j);
      A(i, k) = sum / diagonal;
    }
  }
  return true;
}

}  // namespace probability
}  // namespace estimation
