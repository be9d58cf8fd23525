// Means of several states on a manifold.
//   quaternionAverage: the weighted average of unit quaternions by the eigenvector method
//     (Markley, Cheng, Crassidis, Oshman 2007): the unit q maximising sum w_i (q . q_i)^2, the
//     eigenvector of M = sum w_i q_i q_i^T of the largest eigenvalue. Insensitive to the sign
//     of each q_i (double cover) and to how far apart they are, but needs w_i >= 0
//     (particles): with negative weights M need not have a meaningful top eigenvector.
//   tangentMean: the mean of a layout's states in the tangent space, iterated: x <- x [+]
//     sum w_i (p_i [-] x) / sum w_i until the step vanishes. Takes signed weights (sigma
//     points); each point must lie within the injectivity radius of the mean (pi for angles).
#pragma once

#include <cmath>

#include <Eigen/Eigenvalues>

#include "sf_estimation/errors.hpp"
#include "sf_estimation/manifold/so3.hpp"
#include "sf_estimation/types.hpp"

namespace estimation {
namespace manifold {

/// Columns of `quaternions` are (w, x, y, z); weights >= 0, not all zero. The result has
/// w >= 0. Throws ParameterError for a negative or non-finite weight or a zero total.
template <int K>
Eigen::Quaterniond quaternionAverage(const Eigen::Matrix<double, 4, K>& quaternions,
                                     const Vector<K>& weights) {
  Eigen::Matrix4d M = Eigen::Matrix4d::Zero();
  double total = 0.0;
  for (Index i = 0; i < quaternions.cols(); ++i) {
    if (!(weights(i) >= 0.0) || !std::isfinite(weights(i))) {
      throw ParameterError("quaternionAverage: weights must be finite and non-negative");
    }
    total += weights(i);
    M.noalias() += weights(i) * quaternions.col(i) * quaternions.col(i).transpose();
  }
  if (!(total > 0.0)) throw ParameterError("quaternionAverage: the weights sum to zero");
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix4d> solver(M / total);
  Eigen::Vector4d q = solver.eigenvectors().col(3);  // eigenvalues ascend
  if (q(0) < 0.0) q = -q;
  return so3Normalised<double>(Eigen::Quaterniond(q(0), q(1), q(2), q(3)));
}

/// The fixed point of x <- x [+] sum w_i (p_i [-] x) / sum w_i, from `reference` (e.g. the
/// central sigma point), stopping when the step's largest entry is below `tolerance` or after
/// `maxIterations`. Returns the number of iterations taken. One iteration is exact for a flat
/// layout and for angles. Throws ParameterError when the weights sum to zero.
template <class Layout, int K>
int tangentMean(const Eigen::Matrix<double, Layout::StoredSize, K>& points,
                const Vector<K>& weights, const typename Layout::template Stored<double>& reference,
                typename Layout::template Stored<double>& mean, int maxIterations = 20,
                double tolerance = 1e-14) {
  using Tangent = typename Layout::template Tangent<double>;
  using Stored = typename Layout::template Stored<double>;
  const double total = weights.sum();
  if (!(std::abs(total) > 0.0) || !std::isfinite(total)) {
    throw ParameterError("tangentMean: the weights must have a finite, non-zero sum");
  }
  mean = reference;
  for (int iteration = 1; iteration <= maxIterations; ++iteration) {
    Tangent step = Tangent::Zero();
    for (Index i = 0; i < points.cols(); ++i) {
      const Stored p = points.col(i);
      step += weights(i) * Layout::minus(p, mean);
    }
    step /= total;
    mean = Layout::plus(mean, Tangent(step));
    if (step.cwiseAbs().maxCoeff() < tolerance) return iteration;
  }
  return maxIterations;
}

}  // namespace manifold
}  // namespace estimation
