// The plain value of a scalar that may be an AutoDiffScalar: the manifold code is templated on
// the scalar so that AutoDiff differentiates it, and branches (a Taylor series near zero, the
// wrap of an angle) are decided on the value alone.
#pragma once

#include <cmath>

#include <Eigen/Core>
#include <unsupported/Eigen/AutoDiff>

namespace estimation {
namespace manifold {

inline double scalarValue(double s) { return s; }

template <class Derivatives>
double scalarValue(const Eigen::AutoDiffScalar<Derivatives>& s) {
  return s.value();
}

/// atan2(y, x) of doubles or of AutoDiffScalars with the same derivative type. Eigen's own
/// atan2 of AutoDiffScalars returns a dynamic-size derivative vector, a heap allocation in a
/// filter step; here d atan2 = (x dy - y dx) / (x^2 + y^2) keeps the fixed size.
inline double atan2Scalar(double y, double x) { return std::atan2(y, x); }

template <class Derivatives>
Eigen::AutoDiffScalar<Derivatives> atan2Scalar(const Eigen::AutoDiffScalar<Derivatives>& y,
                                               const Eigen::AutoDiffScalar<Derivatives>& x) {
  const double yv = y.value(), xv = x.value();
  const double r2 = xv * xv + yv * yv;
  return Eigen::AutoDiffScalar<Derivatives>(
      std::atan2(yv, xv), Derivatives((xv * y.derivatives() - yv * x.derivatives()) / r2));
}

}  // namespace manifold
}  // namespace estimation
