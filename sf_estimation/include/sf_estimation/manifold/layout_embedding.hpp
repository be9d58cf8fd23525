// A tangent-space covariance shown over the stored state, for code that indexes the belief by
// stored entry (the node's fusion core, its CSV and messages): tangent row t of a block sits on
// stored row s of the same block, aligned to the block's end, so that a quaternion's three
// rotation-vector rows land on its x, y, z entries and its w row stays zero. For a flat
// layout both views are the same matrix. toTangent(toStored(P)) == P exactly.
#pragma once

#include <array>

#include "sf_estimation/manifold/state_layout.hpp"
#include "sf_estimation/types.hpp"

namespace estimation {
namespace manifold {

template <class Layout>
struct LayoutEmbedding {
  static constexpr int N = Layout::StoredSize;
  static constexpr int D = Layout::TangentSize;

  /// storedOfTangent()[t]: the stored entry that shows tangent coordinate t.
  static std::array<int, D> storedOfTangent() {
    std::array<int, D> stored{};
    int at = 0, tangentAt = 0;
    visitSizes([&](int storedSize, int tangentSize) {
      for (int k = 0; k < tangentSize; ++k)
        stored[tangentAt + k] = at + storedSize - tangentSize + k;
      at += storedSize;
      tangentAt += tangentSize;
    });
    return stored;
  }

  /// P over the tangent space as an N x N matrix (rows of entries without a tangent zero).
  static Matrix<N, N> toStored(const Matrix<D, D>& P) {
    const std::array<int, D> s = storedOfTangent();
    Matrix<N, N> out = Matrix<N, N>::Zero();
    for (int i = 0; i < D; ++i) {
      for (int j = 0; j < D; ++j) out(s[i], s[j]) = P(i, j);
    }
    return out;
  }

  /// The tangent rows and columns of an N x N matrix given in the form of toStored.
  static Matrix<D, D> toTangent(const Matrix<N, N>& P) {
    const std::array<int, D> s = storedOfTangent();
    Matrix<D, D> out;
    for (int i = 0; i < D; ++i) {
      for (int j = 0; j < D; ++j) out(i, j) = P(s[i], s[j]);
    }
    return out;
  }

 private:
  template <class F>
  static void visitSizes(F&& f) {
    Layout::forEachBlock([&](auto block, auto, auto) {
      using B = decltype(block);
      f(B::StoredSize, B::TangentSize);
    });
  }
};

}  // namespace manifold
}  // namespace estimation
