// SO(2), planar rotations stored as one angle in (-pi, pi]. The retraction is the wrapped sum:
// a [+] d = wrap(a + d), b [-] a = wrap(b - a), so that a [+] (b [-] a) = b for every pair and
// the tangent coordinate is the angle itself (the group is commutative: left and right
// perturbations coincide).
#pragma once

#include "sf_estimation/angles.hpp"
#include "sf_estimation/manifold/scalar.hpp"

namespace estimation {
namespace manifold {

/// a wrapped to (-pi, pi] for a double or an AutoDiffScalar: the wrap adds a multiple of 2 pi
/// decided on the value (angles.hpp's wrapAngle), which leaves the derivatives unchanged.
template <class Scalar>
Scalar wrap(const Scalar& a) {
  const double v = scalarValue(a);
  return a + Scalar(wrapAngle(v) - v);
}

/// a [+] d: the angle a rotated by d.
template <class Scalar>
Scalar so2Plus(const Scalar& a, const Scalar& d) {
  return wrap<Scalar>(a + d);
}

/// b [-] a: the shortest rotation from a to b, in (-pi, pi].
template <class Scalar>
Scalar so2Minus(const Scalar& b, const Scalar& a) {
  return wrap<Scalar>(b - a);
}

}  // namespace manifold
}  // namespace estimation
