// The plain value of a scalar that may be an AutoDiffScalar: the manifold code is templated on
// the scalar so that AutoDiff differentiates it, and branches (a Taylor series near zero, the
// wrap of an angle) are decided on the value alone.
#pragma once

#include <Eigen/Core>
#include <unsupported/Eigen/AutoDiff>

namespace estimation {
namespace manifold {

inline double scalarValue(double s) { return s; }

template <class Derivatives>
double scalarValue(const Eigen::AutoDiffScalar<Derivatives>& s) {
  return s.value();
}

}  // namespace manifold
}  // namespace estimation
