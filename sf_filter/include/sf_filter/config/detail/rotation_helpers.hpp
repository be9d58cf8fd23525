// Rotation helpers for the model expressions of a header with QUATERNION_STATES
// (doc/configuration.md, "Rotations in 3D"). Each returns one component, as an expression
// of STATE_TRANSITION_MODEL or OBSERVATION_MODEL must: `q` is the index i of the quaternion
// x[i..i+3] (stored w, x, y, z; body to world), `k` the component (0, 1, 2 of a vector; 0 = w,
// 1 = x, 2 = y, 3 = z of a quaternion). Vector arguments may be state entries, controls,
// T or numbers. Templated on the state's scalar, so that AutoDiff differentiates them
// (sf_estimation/manifold/so3.hpp underneath).
//
//   quat_rotate(x, q, k, vx, vy, vz)           (R(q) v)_k: a body vector in the world frame
//   quat_rotate_inverse(x, q, k, vx, vy, vz)   (R(q)^T v)_k: a world vector in the body frame
//   quat_product(x, q, k, pw, px, py, pz)      (q p)_k, p = (pw, px, py, pz)
//   quat_exp(x, k, rx, ry, rz)                 exp(r)_k, the unit quaternion of rotation vector r
//   quat_integrate(x, q, k, rx, ry, rz)        (q exp(r))_k: q turned by the body rotation r,
//                                              e.g. r = omega T for a body rate omega
//   quat_euler(x, q, k)                        roll (k = 0), pitch (1), yaw (2) of q, in rad
//                                              (Z-Y-X, as tf2's getRPY)
#pragma once

#include <array>
#include <cmath>
#include <type_traits>
#include <utility>

#include <Eigen/Core>
#include <sf_estimation/manifold/so3.hpp>
#include <unsupported/Eigen/AutoDiff>

namespace sf_config {
namespace rotation_detail {

namespace mf = estimation::manifold;

template <class S, int N>
mf::Quaternion<S> quaternionAt(const Eigen::Matrix<S, N, 1>& x, int q) {
  return mf::storedQuaternion(x.template segment<4>(q));
}

/// An argument converted to the state's scalar where the helper is called (a non-deduced
/// context): each helper is then instantiated once per scalar, not once per combination of
/// argument expression types, which AutoDiff makes many (compile time and memory).
template <class S>
using Arg = typename Eigen::internal::remove_all<S>::type;

template <class S>
mf::Vector3<S> vector3(const Arg<S>& a, const Arg<S>& b, const Arg<S>& c) {
  return mf::Vector3<S>(a, b, c);
}

template <class S>
S quaternionComponent(const mf::Quaternion<S>& q, int k) {
  return k == 0 ? q.w() : q.vec()(k - 1);
}

/// Whether a and b have the same bits (an AutoDiff scalar: its value and derivatives). Equal
/// doubles differ in their bits only as +0 and -0; NaN never compares equal (computed anew).
/// Other scalars never compare equal, so they are always computed.
inline bool sameBits(double a, double b) { return a == b && std::signbit(a) == std::signbit(b); }

template <class D>
bool sameBits(const Eigen::AutoDiffScalar<D>& a, const Eigen::AutoDiffScalar<D>& b) {
  const auto &da = a.derivatives(), &db = b.derivatives();
  if (!sameBits(a.value(), b.value()) || da.size() != db.size()) return false;
  for (Eigen::Index i = 0; i < da.size(); ++i) {
    if (!sameBits(da(i), db(i))) return false;
  }
  return true;
}

template <class S>
bool sameBits(const S&, const S&) {
  return false;
}

/// compute(), or the result of the last call from the same helper (Compute, a lambda of one
/// helper and scalar) on this thread when its arguments had the same bits. A header's
/// expression asks for one component: the 4 of a turned quaternion (the 3 of a rotated vector)
/// repeat one rotation with the same arguments, e.g. ARMESTO_TURN(0..3) of
/// config/armesto_inertial_vision_ekf.h, whose UKF evaluated it 4 times at each of its 37
/// sigma points (doc/node_benchmarks.md, "The Armesto headers' step"). The helpers are pure,
/// so the remembered result has the bits a new computation would have.
template <class Compute, class S, std::size_t K>
const auto& remembered(const std::array<S, K>& args, const Compute& compute) {
  using Result = std::decay_t<decltype(std::declval<const Compute&>()())>;
  struct Last {
    std::array<S, K> args;
    Result result;
    bool valid = false;
  };
  thread_local Last last;
  bool same = last.valid;
  for (std::size_t i = 0; same && i < K; ++i) same = sameBits(args[i], last.args[i]);
  if (!same) {
    last.result = compute();
    last.args = args;
    last.valid = true;
  }
  return last.result;
}

/// The quaternion x[q..q+3] and three more arguments, the key of remembered().
template <class S, int N>
std::array<S, 7> quaternionAndVector(const Eigen::Matrix<S, N, 1>& x, int q, const Arg<S>& a,
                                     const Arg<S>& b, const Arg<S>& c) {
  return {x(q), x(q + 1), x(q + 2), x(q + 3), a, b, c};
}

/// op(the quaternion x[q..q+3], the vector (a, b, c)), remembered() per op (a lambda of one
/// helper) and arguments.
template <class Op, class S, int N>
const auto& rememberedOfQuaternionAndVector(const Op& op, const Eigen::Matrix<S, N, 1>& x, int q,
                                            const Arg<S>& a, const Arg<S>& b, const Arg<S>& c) {
  return remembered(quaternionAndVector(x, q, a, b, c),
                    [&] { return op(quaternionAt(x, q), vector3<S>(a, b, c)); });
}

}  // namespace rotation_detail

template <class S, int N>
S quat_rotate(const Eigen::Matrix<S, N, 1>& x, int q, int k, const rotation_detail::Arg<S>& vx,
              const rotation_detail::Arg<S>& vy, const rotation_detail::Arg<S>& vz) {
  namespace rd = rotation_detail;
  const auto rotate = [](const auto& p, const auto& v) { return rd::mf::so3Rotate<S>(p, v); };
  return rd::rememberedOfQuaternionAndVector(rotate, x, q, vx, vy, vz)(k);
}

template <class S, int N>
S quat_rotate_inverse(const Eigen::Matrix<S, N, 1>& x, int q, int k,
                      const rotation_detail::Arg<S>& vx, const rotation_detail::Arg<S>& vy,
                      const rotation_detail::Arg<S>& vz) {
  namespace rd = rotation_detail;
  const auto rotateInverse = [](const auto& p, const auto& v) {
    return rd::mf::so3RotateInverse<S>(p, v);
  };
  return rd::rememberedOfQuaternionAndVector(rotateInverse, x, q, vx, vy, vz)(k);
}

template <class S, int N>
S quat_product(const Eigen::Matrix<S, N, 1>& x, int q, int k, const rotation_detail::Arg<S>& pw,
               const rotation_detail::Arg<S>& px, const rotation_detail::Arg<S>& py,
               const rotation_detail::Arg<S>& pz) {
  namespace rd = rotation_detail;
  const rd::mf::Quaternion<S> p{pw, px, py, pz};
  return rd::quaternionComponent(rd::mf::so3Product<S>(rd::quaternionAt(x, q), p), k);
}

/// `x` only fixes the scalar (the state's, so that AutoDiff reaches it).
template <class S, int N>
S quat_exp(const Eigen::Matrix<S, N, 1>& x, int k, const rotation_detail::Arg<S>& rx,
           const rotation_detail::Arg<S>& ry, const rotation_detail::Arg<S>& rz) {
  static_cast<void>(x);
  namespace rd = rotation_detail;
  return rd::quaternionComponent(rd::mf::so3Exp<S>(rd::vector3<S>(rx, ry, rz)), k);
}

template <class S, int N>
S quat_integrate(const Eigen::Matrix<S, N, 1>& x, int q, int k, const rotation_detail::Arg<S>& rx,
                 const rotation_detail::Arg<S>& ry, const rotation_detail::Arg<S>& rz) {
  namespace rd = rotation_detail;
  const auto plus = [](const auto& p, const auto& r) { return rd::mf::so3Plus<S>(p, r); };
  return rd::quaternionComponent(rd::rememberedOfQuaternionAndVector(plus, x, q, rx, ry, rz), k);
}

template <class S, int N>
S quat_euler(const Eigen::Matrix<S, N, 1>& x, int q, int k) {
  using std::asin;
  using std::atan2;
  const S w = x(q), a = x(q + 1), b = x(q + 2), c = x(q + 3);
  if (k == 0) return atan2(S(2.0) * (w * a + b * c), S(1.0) - S(2.0) * (a * a + b * b));
  if (k == 1) {
    const S s = S(2.0) * (w * b - c * a);
    return asin(s > S(1.0) ? S(1.0) : (s < S(-1.0) ? S(-1.0) : s));
  }
  return atan2(S(2.0) * (w * c + a * b), S(1.0) - S(2.0) * (b * b + c * c));
}

}  // namespace sf_config
