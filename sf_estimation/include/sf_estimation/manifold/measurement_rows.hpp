// The measurement of a layout filter whose inputs hold rotations (a measured unit quaternion,
// the node's QUATERNION_INPUTS), read through a measurement layout: state_layout.hpp's blocks
// over the M stored entries of the model's flat z = h(x). The filters keep the flat interface
// (M stored rows, R M x M), with the measured block in LayoutEmbedding's form, as Q and P0 are:
// a quaternion's rotation vector z [-] h(x) (So3WorldBlock: log(q_z q_h^-1), about the world's
// axes, angle <= pi, so q and -q give the same innovation) sits on its x, y, z rows, its R on
// the same rows in rad^2; its w row carries no information and is treated as a missing entry
// (zero innovation and H row, identity noise row: kalman_correction.hpp), so the update is the
// one with the tangent rows only. A flat measurement layout leaves everything to subtraction.
#pragma once

#include <array>
#include <string>
#include <type_traits>

#include <unsupported/Eigen/AutoDiff>

#include "sf_estimation/errors.hpp"
#include "sf_estimation/manifold/layout_embedding.hpp"
#include "sf_estimation/measurement.hpp"

namespace estimation {
namespace manifold {

template <class Layout>
struct MeasurementRows {
  static constexpr int M = Layout::StoredSize, T = Layout::TangentSize;
  using Embedding = LayoutEmbedding<Layout>;

  /// z [-] h in the stored form: tangent coordinate t on row storedOfTangent()[t], the rows
  /// without one zero.
  static Vector<M> innovation(const Vector<M>& z, const Vector<M>& h) {
    const Vector<T> tangent = Layout::template minus<double>(z, h);
    const std::array<int, T> rows = Embedding::storedOfTangent();
    Vector<M> out = Vector<M>::Zero();
    for (int t = 0; t < T; ++t) out(rows[t]) = tangent(t);
    return out;
  }

  /// Turns the rows of dh/de (M x D, e the state's tangent error) into those of
  /// d/de [h(x [+] e) [-] h(x)] = d[z [-] h]/dz at z = h times dh/de, in the stored form, block
  /// by block: a flat block's rows are its own rows of dh/de, a rotation's come from the
  /// derivative of its own minus over its own entries (blockDerivative).
  template <int D>
  static void tangentRows(const Vector<M>& h, Matrix<M, D>& H) {
    const std::array<int, T> rows = Embedding::storedOfTangent();
    Matrix<M, D> out = Matrix<M, D>::Zero();
    Layout::forEachBlock([&](auto block, auto at, auto tangentAt) {
      using B = decltype(block);
      if constexpr (B::IsFlat) {
        for (int k = 0; k < B::TangentSize; ++k) out.row(rows[tangentAt + k]) = H.row(at + k);
      } else {
        const Matrix<B::TangentSize, B::StoredSize> J =
            blockDerivative<B>(h.template segment<B::StoredSize>(at));
        for (int k = 0; k < B::TangentSize; ++k) {
          // Summed over all M rows of H, zeros outside the block, as AutoDiff over all M
          // entries did: the same products in the same order, so the same rounding.
          Vector<M> d = Vector<M>::Zero();
          d.template segment<B::StoredSize>(at) = J.row(k).transpose();
          out.row(rows[tangentAt + k]) = d.transpose() * H;
        }
      }
    });
    H = out;
  }

  /// Marks missing the rows without a tangent coordinate (see the top of the file) and every
  /// row of a rotation with a missing component: a quaternion is read whole or not at all.
  static void withoutTangentFreeRows(Measurement<M>& z) {
    Layout::forEachBlock([&](auto block, auto at, auto) {
      using B = decltype(block);
      if constexpr (!B::IsFlat) {
        if (!z.available.template segment<B::StoredSize>(at).all())
          z.available.template segment<B::StoredSize>(at).setConstant(false);
      }
    });
    const std::array<bool, M> free = tangentFree();
    for (int i = 0; i < M; ++i) z.available(i) = z.available(i) && !free[i];
  }

  /// The configured R as the manifold filter's base holds it: the rows without a tangent
  /// coordinate must be zero (ParameterError otherwise) and get the identity's, never used.
  static Matrix<M, M> storedNoise(const std::string& name, Matrix<M, M> R) {
    const std::array<bool, M> free = tangentFree();
    for (int i = 0; i < M; ++i) {
      if (!free[i]) continue;
      if (R.row(i).cwiseAbs().sum() != 0.0 || R.col(i).cwiseAbs().sum() != 0.0) {
        throw ParameterError(name + ": row and column " + std::to_string(i) +
                             " (a measured quaternion's w) must be zero: the quaternion's noise "
                             "is the 3 x 3 rotation-vector covariance on its x, y, z rows");
      }
      R(i, i) = 1.0;
    }
    return R;
  }

 private:
  /// d[z [-] h]/dz of one block at z = h (B::TangentSize x B::StoredSize): the block's own
  /// closed form if it has one (So3WorldBlock, the measured quaternion), AutoDiff of its minus
  /// over its own entries otherwise. AutoDiff through a quaternion's log cost a 3D header's
  /// step unit about 100 MB (doc/build_cost.md, "The measured quaternion's rows").
  template <class B>
  static Matrix<B::TangentSize, B::StoredSize> blockDerivative(const Vector<B::StoredSize>& h) {
    if constexpr (HasMinusDerivative<B>::value) {
      return B::minusDerivative(h);
    } else {
      using Ad = Eigen::AutoDiffScalar<Vector<B::StoredSize>>;
      Eigen::Matrix<Ad, B::StoredSize, 1> z;
      for (Index i = 0; i < B::StoredSize; ++i) z(i) = Ad(h(i), B::StoredSize, i);
      Eigen::Matrix<Ad, B::TangentSize, 1> d;
      B::minus(z, h.template cast<Ad>(), d);
      Matrix<B::TangentSize, B::StoredSize> J;
      for (int t = 0; t < B::TangentSize; ++t) J.row(t) = d(t).derivatives().transpose();
      return J;
    }
  }

  template <class B, class = void>
  struct HasMinusDerivative : std::false_type {};
  template <class B>
  struct HasMinusDerivative<B, std::void_t<decltype(B::minusDerivative(Vector<B::StoredSize>()))>>
      : std::true_type {};

  static std::array<bool, M> tangentFree() {
    std::array<bool, M> free;
    free.fill(true);
    for (const int row : Embedding::storedOfTangent()) free[row] = false;
    return free;
  }
};

}  // namespace manifold
}  // namespace estimation
