// SO(3), rotations held as unit quaternions (Eigen::Quaternion<Scalar>; in a state vector stored
// as w, x, y, z) with 3 tangent coordinates, a rotation vector phi (axis times angle).
//
// Retraction: the right (body) perturbation q [+] phi = q exp(phi), q1 [-] q0 = log(q0^-1 q1).
// The error lives in the body frame: a gyro's noise and bias enter it directly, the covariance
// of a heading-free attitude (roll, pitch from gravity) stays block-structured whatever the
// yaw, and it is the choice of UKF-M's attitude example, whose benchmark the library
// reproduces (doc/manifolds.md). The left (world-frame) perturbation exp(phi) q would do as
// well for a filter; it is only a different chart, and both are exact inverses of their [-].
//
// Every function is templated on the scalar so that Eigen's AutoDiffScalar differentiates it:
// the series branches near the identity use squared norms only (a square root of zero has no
// derivative), so the Jacobians of exp and log at phi = 0 are exactly the identity.
#pragma once

#include <cmath>

#include <Eigen/Geometry>

#include "sf_estimation/manifold/scalar.hpp"

namespace estimation {
namespace manifold {

template <class Scalar>
using Quaternion = Eigen::Quaternion<Scalar>;
template <class Scalar>
using Vector3 = Eigen::Matrix<Scalar, 3, 1>;

/// Below this squared angle (rad^2) exp and log use their series: the truncated terms are
/// below 1e-18 relative, and the closed forms' sin(t)/t and atan2(n, w)/n lose no accuracy
/// above it.
constexpr double kSo3SeriesAngleSquared = 1e-6;

/// exp(phi): the unit quaternion of the rotation by |phi| about phi / |phi|.
template <class Scalar>
Quaternion<Scalar> so3Exp(const Vector3<Scalar>& phi) {
  using std::cos;
  using std::sin;
  using std::sqrt;
  const Scalar t2 = phi.squaredNorm();
  Scalar c, k;  // q = (cos(t/2), sin(t/2)/t phi)
  if (scalarValue(t2) < kSo3SeriesAngleSquared) {
    c = Scalar(1.0) - t2 / 8.0 + t2 * t2 / 384.0;
    k = Scalar(0.5) - t2 / 48.0 + t2 * t2 / 3840.0;
  } else {
    const Scalar t = sqrt(t2);
    c = cos(t / 2.0);
    k = sin(t / 2.0) / t;
  }
  return Quaternion<Scalar>(c, k * phi(0), k * phi(1), k * phi(2));
}

/// log(q): the rotation vector of q with angle in [0, pi]. q and -q are the same rotation
/// (double cover): the one with w >= 0 is taken, so the shortest rotation is returned. Uses
/// the angle 2 atan2(|v|, w), which is accurate near 0 and near pi alike (acos(w) is not) and
/// independent of |q|: a quaternion that drifted off the unit sphere gives the rotation of its
/// normalised self. At exactly pi, phi and -phi are the same rotation; either may be returned.
template <class Scalar>
Vector3<Scalar> so3Log(const Quaternion<Scalar>& q) {
  using std::sqrt;
  Scalar w = q.w();
  Vector3<Scalar> v = q.vec();
  if (scalarValue(w) < 0.0) {
    w = -w;
    v = -v;
  }
  const Scalar n2 = v.squaredNorm();
  const Scalar w2 = w * w;
  if (scalarValue(n2) < kSo3SeriesAngleSquared * scalarValue(w2)) {
    // 2 atan(n / w) / n = (2 / w) (1 - r / 3 + r^2 / 5 - ...), r = n^2 / w^2 (the angle is small).
    const Scalar r = n2 / w2;
    return v * (Scalar(2.0) / w * (Scalar(1.0) - r / 3.0 + r * r / 5.0));
  }
  const Scalar n = sqrt(n2);
  return v * (Scalar(2.0) * atan2Scalar(n, w) / n);
}

/// a b: first b, then a (in the body frame of a).
template <class Scalar>
Quaternion<Scalar> so3Product(const Quaternion<Scalar>& a, const Quaternion<Scalar>& b) {
  return a * b;
}

/// q v q^-1: v rotated by q (body to world). q must be unit.
template <class Scalar>
Vector3<Scalar> so3Rotate(const Quaternion<Scalar>& q, const Vector3<Scalar>& v) {
  return q._transformVector(v);
}

/// q^-1 v q: v rotated by the inverse of q (world to body). q must be unit.
template <class Scalar>
Vector3<Scalar> so3RotateInverse(const Quaternion<Scalar>& q, const Vector3<Scalar>& v) {
  return q.conjugate()._transformVector(v);
}

/// q / |q|: removes the drift of the unit norm that rounding accumulates.
template <class Scalar>
Quaternion<Scalar> so3Normalised(const Quaternion<Scalar>& q) {
  using std::sqrt;
  const Scalar norm = sqrt(q.coeffs().squaredNorm());
  return Quaternion<Scalar>(q.coeffs() / norm);
}

/// q [+] phi = q exp(phi), normalised (see the top of the file for the choice of side).
template <class Scalar>
Quaternion<Scalar> so3Plus(const Quaternion<Scalar>& q, const Vector3<Scalar>& phi) {
  return so3Normalised<Scalar>(q * so3Exp<Scalar>(phi));
}

/// q1 [-] q0 = log(q0^-1 q1): the body-frame rotation vector from q0 to q1, angle <= pi.
template <class Scalar>
Vector3<Scalar> so3Minus(const Quaternion<Scalar>& q1, const Quaternion<Scalar>& q0) {
  return so3Log<Scalar>(q0.conjugate() * q1);
}

/// The quaternion stored as (w, x, y, z) at the start of `stored`.
template <class Derived>
Quaternion<typename Derived::Scalar> storedQuaternion(const Eigen::MatrixBase<Derived>& stored) {
  return Quaternion<typename Derived::Scalar>(stored(0), stored(1), stored(2), stored(3));
}

/// Writes q as (w, x, y, z) to the start of `stored`.
template <class Scalar, class Derived>
void storeQuaternion(const Quaternion<Scalar>& q, Eigen::MatrixBase<Derived>& stored) {
  stored(0) = q.w();
  stored(1) = q.x();
  stored(2) = q.y();
  stored(3) = q.z();
}

}  // namespace manifold
}  // namespace estimation
