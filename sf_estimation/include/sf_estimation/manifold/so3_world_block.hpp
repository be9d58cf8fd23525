// A unit quaternion perturbed on the left, in the world frame: q [+] phi = exp(phi) q,
// q1 [-] q0 = log(q1 q0^-1). The chart of the node's QUATERNION_STATES (doc/manifolds.md, "The
// node on a state layout"). Its error is a rotation about the world's axes, so the direction
// that a gravity (accelerometer) measurement cannot see is the world's z whatever the estimate:
// an EKF's unobservable heading variance stays on that axis and never leaks into the
// corrections of roll and pitch. With So3Block's body-frame error that axis is gravity seen in
// the estimated body, which every roll or pitch correction moves while the covariance (no
// reset Jacobian) keeps the old one: config/imu_attitude.h's heading then drifted by 20 deg in
// 30 s of a simulated run (1.2 deg with this block). Stored w, x, y, z like So3Block.
#pragma once

#include <type_traits>

#include "sf_estimation/manifold/so3.hpp"

namespace estimation {
namespace manifold {

struct So3WorldBlock {
  static constexpr int StoredSize = 4;
  static constexpr int TangentSize = 3;
  static constexpr bool IsFlat = false;
  static constexpr const char* Name = "So3WorldBlock";

  template <class X, class D, class Out>
  static void plus(const X& x, const D& d, Out&& out) {
    using S = typename std::decay_t<Out>::Scalar;
    const Vector3<S> phi = d;
    storeQuaternion(so3Normalised<S>(so3Exp<S>(phi) * storedQuaternion(x)), out);
  }
  template <class Y, class X, class Out>
  static void minus(const Y& y, const X& x, Out&& out) {
    using S = typename std::decay_t<Out>::Scalar;
    out = so3Log<S>(storedQuaternion(y) * storedQuaternion(x).conjugate());
  }
  /// d[y [-] x]/dy at y = x (3 x 4, stored w, x, y, z), in closed form: 2 / |x|^2 times the
  /// vector part of dy x^*. Bit for bit what AutoDiff of minus gives there, up to an exact
  /// zero's sign (y x^* has a zero vector part, so log takes its series with r = 0 and scales by
  /// 2 / w, w = |x|^2 summed in the quaternion product's order); without AutoDiff, the step
  /// unit of a node with a measured quaternion is 60-80 MB smaller (doc/build_cost.md, "The
  /// measured quaternion's rows").
  template <class X>
  static Eigen::Matrix<double, 3, 4> minusDerivative(const X& x) {
    const double w = x(0), a = x(1), b = x(2), c = x(3);
    const double s = 2.0 / (w * w + a * a + b * b + c * c);
    Eigen::Matrix<double, 3, 4> d;
    d << -a * s, w * s, -c * s, b * s,  //
        -b * s, c * s, w * s, -a * s,   //
        -c * s, -b * s, a * s, w * s;
    return d;
  }
  template <class X>
  static void normalise(X&& x) {
    using S = typename std::decay_t<X>::Scalar;
    storeQuaternion(so3Normalised<S>(storedQuaternion(x)), x);
  }
};

}  // namespace manifold
}  // namespace estimation
