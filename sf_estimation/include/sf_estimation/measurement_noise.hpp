// The measurement noise of one step: the configured R, with the per-entry variances a
// measurement may carry on the diagonal and its covariances between present entries off it,
// and missing entries decoupled (identity row and column) so that a filter's update equals
// the update with only the present rows (and the present rows' block of the covariances).
#pragma once

#include "sf_estimation/measurement.hpp"

namespace estimation {

/// R for this step: per-entry variances replace the diagonal, given covariances between present
/// entries the off-diagonal entries, missing entries are decoupled.
template <int M>
void effectiveMeasurementNoise(const Matrix<M, M>& R, const Measurement<M>& z, Matrix<M, M>& out) {
  out = R;
  for (Index i = 0; i < z.size(); ++i) {
    if (!z.available(i)) {
      out.row(i).setZero();
      out.col(i).setZero();
      out(i, i) = 1.0;
    } else if (z.varianceGiven(i)) {
      out(i, i) = z.variance(i);
    }
  }
  if (!z.covarianceGiven.any()) return;
  for (Index i = 0; i < z.size(); ++i) {
    for (Index j = 0; j < z.size(); ++j) {
      if (i != j && z.covarianceUsed(i, j)) out(i, j) = z.covariance(i, j);
    }
  }
}

}  // namespace estimation
