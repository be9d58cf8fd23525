// A filter state made of blocks, fixed at compile time: plain vector entries, SO(2) angles and
// SO(3) unit quaternions. A state is stored as StoredSize numbers (a quaternion as w, x, y, z)
// and perturbed in a tangent space of TangentSize coordinates (a quaternion's 3, a rotation
// vector): the covariance is TangentSize x TangentSize. The layout gives
//   x [+] delta  (boxplus: the retraction, block by block; so2.hpp, so3.hpp),
//   y [-] x      (boxminus: its inverse, x [+] (y [-] x) = y),
//   normalise(x) (angles wrapped, quaternions unit),
// on Eigen vectors of any scalar, so that AutoDiff differentiates a model through them. A
// layout of vector blocks only is flat: [+] and [-] are then exactly + and -.
//
//   using Pose2 = StateLayout<So2Block, VectorBlock<2>>;   // heading, then x, y
//   using Attitude = StateLayout<So3Block, VectorBlock<3>>;  // quaternion, then gyro bias
#pragma once

#include <type_traits>
#include <utility>

#include <Eigen/Core>

#include "sf_estimation/manifold/so2.hpp"
#include "sf_estimation/manifold/so3.hpp"

namespace estimation {
namespace manifold {

/// N plain entries: [+] and [-] are + and -.
template <int N>
struct VectorBlock {
  static_assert(N > 0, "VectorBlock: at least one entry");
  static constexpr int StoredSize = N;
  static constexpr int TangentSize = N;
  static constexpr bool IsFlat = true;
  static constexpr const char* Name = "VectorBlock";

  template <class X, class D, class Out>
  static void plus(const X& x, const D& d, Out&& out) {
    out = x + d;
  }
  template <class Y, class X, class Out>
  static void minus(const Y& y, const X& x, Out&& out) {
    out = y - x;
  }
  template <class X>
  static void normalise(X&&) {}
};

/// One angle in (-pi, pi] (today's ANGLE_STATES): wrapped sum and difference.
struct So2Block {
  static constexpr int StoredSize = 1;
  static constexpr int TangentSize = 1;
  static constexpr bool IsFlat = false;
  static constexpr const char* Name = "So2Block";

  template <class X, class D, class Out>
  static void plus(const X& x, const D& d, Out&& out) {
    out(0) = so2Plus(x(0), d(0));
  }
  template <class Y, class X, class Out>
  static void minus(const Y& y, const X& x, Out&& out) {
    out(0) = so2Minus(y(0), x(0));
  }
  template <class X>
  static void normalise(X&& x) {
    x(0) = wrap(x(0));
  }
};

/// A unit quaternion, stored w, x, y, z, perturbed on the right: q [+] phi = q exp(phi).
struct So3Block {
  static constexpr int StoredSize = 4;
  static constexpr int TangentSize = 3;
  static constexpr bool IsFlat = false;
  static constexpr const char* Name = "So3Block";

  template <class X, class D, class Out>
  static void plus(const X& x, const D& d, Out&& out) {
    using S = typename std::decay_t<Out>::Scalar;
    const Vector3<S> phi = d;
    storeQuaternion(so3Plus<S>(storedQuaternion(x), phi), out);
  }
  template <class Y, class X, class Out>
  static void minus(const Y& y, const X& x, Out&& out) {
    using S = typename std::decay_t<Out>::Scalar;
    out = so3Minus<S>(storedQuaternion(y), storedQuaternion(x));
  }
  template <class X>
  static void normalise(X&& x) {
    using S = typename std::decay_t<X>::Scalar;
    storeQuaternion(so3Normalised<S>(storedQuaternion(x)), x);
  }
};

template <class... Blocks>
struct StateLayout {
  static_assert(sizeof...(Blocks) > 0, "StateLayout: at least one block");
  static constexpr int StoredSize = (Blocks::StoredSize + ...);
  static constexpr int TangentSize = (Blocks::TangentSize + ...);
  /// Only vector blocks: [+] and [-] are + and -, and a plain Kalman filter applies.
  static constexpr bool IsFlat = (Blocks::IsFlat && ...);

  template <class Scalar>
  using Stored = Eigen::Matrix<Scalar, StoredSize, 1>;
  template <class Scalar>
  using Tangent = Eigen::Matrix<Scalar, TangentSize, 1>;

  /// x [+] delta.
  template <class Scalar>
  static Stored<Scalar> plus(const Stored<Scalar>& x, const Tangent<Scalar>& delta) {
    Stored<Scalar> out;
    forEachBlock([&](auto block, auto at, auto tangentAt) {
      using B = decltype(block);
      B::plus(x.template segment<B::StoredSize>(at),
              delta.template segment<B::TangentSize>(tangentAt),
              out.template segment<B::StoredSize>(at));
    });
    return out;
  }

  /// y [-] x: the tangent vector that takes x to y.
  template <class Scalar>
  static Tangent<Scalar> minus(const Stored<Scalar>& y, const Stored<Scalar>& x) {
    Tangent<Scalar> out;
    forEachBlock([&](auto block, auto at, auto tangentAt) {
      using B = decltype(block);
      B::minus(y.template segment<B::StoredSize>(at), x.template segment<B::StoredSize>(at),
               out.template segment<B::TangentSize>(tangentAt));
    });
    return out;
  }

  /// Angles wrapped to (-pi, pi], quaternions scaled to unit norm.
  template <class Scalar>
  static void normalise(Stored<Scalar>& x) {
    forEachBlock([&](auto block, auto at, auto) {
      using B = decltype(block);
      B::normalise(x.template segment<B::StoredSize>(at));
    });
  }

  /// Calls f(Block{}, stored offset, tangent offset) for every block in order; the offsets are
  /// std::integral_constant, so that segments keep fixed sizes.
  template <class F>
  static void forEachBlock(F&& f) {
    visit<0, 0, Blocks...>(f);
  }

 private:
  template <int At, int TangentAt, class B, class... Rest, class F>
  static void visit(F& f) {
    f(B{}, std::integral_constant<int, At>{}, std::integral_constant<int, TangentAt>{});
    if constexpr (sizeof...(Rest) > 0) {
      visit<At + B::StoredSize, TangentAt + B::TangentSize, Rest...>(f);
    }
  }
};

/// The flat layout of N plain entries: the state of today's filters.
template <int N>
using FlatLayout = StateLayout<VectorBlock<N>>;

}  // namespace manifold
}  // namespace estimation
