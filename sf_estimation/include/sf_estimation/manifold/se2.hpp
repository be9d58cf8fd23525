// SE(2), a planar pose stored as (theta, x, y) with the right (body) perturbation:
// chi [+] xi = chi exp(xi), i.e. theta + xi_theta and p + R(theta) V(xi_theta) rho, and
// chi_y [-] chi_x = log(chi_x^-1 chi_y). Unlike SO(2) x R^2 (So2Block beside a VectorBlock<2>)
// the position error is expressed in the body frame and coupled to the heading error through
// V, which is what keeps a filter consistent when a heading is poorly known (UKF-M's "left
// SE(2) UKF"; doc/manifolds.md measures both). V(t) = [s -c; c s] with s = sin t / t,
// c = (1 - cos t) / t.
#pragma once

#include <cmath>
#include <type_traits>

#include <Eigen/Core>

#include "sf_estimation/manifold/so2.hpp"

namespace estimation {
namespace manifold {

/// Below this |t| (rad) V's coefficients use their series (truncation below 1e-17).
constexpr double kSe2SeriesAngle = 1e-4;

/// s = sin t / t and c = (1 - cos t) / t, by series near 0 so that AutoDiff differentiates them.
template <class Scalar>
void se2VCoefficients(const Scalar& t, Scalar& s, Scalar& c) {
  using std::sin;
  if (std::abs(scalarValue(t)) < kSe2SeriesAngle) {
    s = Scalar(1.0) - t * t / 6.0;
    c = t / 2.0 - t * t * t / 24.0;
  } else {
    // 1 - cos t = 2 sin^2(t / 2) without the cancellation of 1 - cos t near 0.
    const Scalar half = sin(t / 2.0);
    s = sin(t) / t;
    c = Scalar(2.0) * half * half / t;
  }
}

/// R(theta) v.
template <class Scalar>
Eigen::Matrix<Scalar, 2, 1> rotate2(const Scalar& theta, const Eigen::Matrix<Scalar, 2, 1>& v) {
  using std::cos;
  using std::sin;
  const Scalar c = cos(theta), s = sin(theta);
  return Eigen::Matrix<Scalar, 2, 1>(c * v(0) - s * v(1), s * v(0) + c * v(1));
}

struct Se2Block {
  static constexpr int StoredSize = 3;
  static constexpr int TangentSize = 3;
  static constexpr bool IsFlat = false;
  static constexpr const char* Name = "Se2Block";

  template <class X, class D, class Out>
  static void plus(const X& x, const D& d, Out&& out) {
    using S = typename std::decay_t<Out>::Scalar;
    S s, c;
    se2VCoefficients<S>(d(0), s, c);
    const Eigen::Matrix<S, 2, 1> vRho(s * d(1) - c * d(2), c * d(1) + s * d(2));
    const Eigen::Matrix<S, 2, 1> p = x.template tail<2>();
    const S theta = x(0);
    out.template tail<2>() = p + rotate2<S>(theta, vRho);
    out(0) = so2Plus<S>(theta, d(0));
  }
  template <class Y, class X, class Out>
  static void minus(const Y& y, const X& x, Out&& out) {
    using S = typename std::decay_t<Out>::Scalar;
    const S dTheta = so2Minus<S>(y(0), x(0));
    const Eigen::Matrix<S, 2, 1> dp = y.template tail<2>() - x.template tail<2>();
    const Eigen::Matrix<S, 2, 1> t = rotate2<S>(S(-x(0)), dp);  // chi_x^-1 chi_y's translation
    S s, c;
    se2VCoefficients<S>(dTheta, s, c);
    const S det = s * s + c * c;  // V^-1 = [s c; -c s] / det
    out(0) = dTheta;
    out(1) = (s * t(0) + c * t(1)) / det;
    out(2) = (-c * t(0) + s * t(1)) / det;
  }
  template <class X>
  static void normalise(X&& x) {
    x(0) = wrap(x(0));
  }
};

}  // namespace manifold
}  // namespace estimation
