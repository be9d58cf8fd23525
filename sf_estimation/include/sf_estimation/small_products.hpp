// Products of the small matrices of the Kalman steps, as plain loops over coefficients.
//
// The Kalman grid (kalman_correction.hpp) compiles a dozen product shapes for every pair of
// state and measurement sizes. Each of Eigen's product expressions instantiates its own
// evaluators and assignment kernels, which made up most of a grid unit's compile time
// (doc/build_cost.md, "Plain-loop products"); one function template per shape costs a
// fraction of that. The operands must not alias the destination.
#pragma once

#include <cstring>

#include "sf_estimation/types.hpp"

namespace estimation {

/// How a product reaches its destination: assigned, added or subtracted.
enum class Store { Assign, Add, Subtract };

/// out (=, +=, -=) a * b, or a * b^T with `TransposeB`; `out` has the product's size. Each
/// entry's sum over the inner index is formed in order, from its first product on, and only
/// then assigned to, added to or subtracted from out's entry. Two rows at a time share a vector
/// register (GCC's and Clang's vector extension: SSE2 on x86-64, NEON on ARM), the way Eigen's
/// coefficient-based product packs them, a last odd row alone: GCC does not find that
/// vectorisation in the plain loop by itself. (A matrix of two or more rows is column-major
/// here; Eigen stores only a single row row-major.) The inner loop is unrolled for the grid's
/// sizes (up to 8), as Eigen unrolls its fixed-size products.
template <Store store, bool TransposeB = false, class A, class B, class Out>
inline void multiply(const A& a, const B& b, Out& out) {
  static_assert(!A::IsRowMajor || A::RowsAtCompileTime == 1, "a: column-major or a single row");
  static_assert(!Out::IsRowMajor || Out::RowsAtCompileTime == 1,
                "out: column-major or a single row");
  using Pair = double __attribute__((vector_size(16)));
  const auto load = [](const double* from) {
    Pair pair;
    std::memcpy(&pair, from, sizeof pair);
    return pair;
  };
  const auto rhs = [&b](Index k, Index j) { return TransposeB ? b.coeff(j, k) : b.coeff(k, j); };
  const Index rows = a.rows();
  const Index inner = a.cols();
  const Index cols = TransposeB ? b.rows() : b.cols();
  for (Index j = 0; j < cols; ++j) {
    Index i = 0;
    for (; i + 2 <= rows; i += 2) {
      Pair sum = {0.0, 0.0};
      if (inner > 0) sum = load(&a.coeffRef(i, 0)) * rhs(0, j);
#pragma GCC unroll 8
      for (Index k = 1; k < inner; ++k) sum += load(&a.coeffRef(i, k)) * rhs(k, j);
      double* target = &out.coeffRef(i, j);
      if constexpr (store == Store::Add) sum = load(target) + sum;
      if constexpr (store == Store::Subtract) sum = load(target) - sum;
      std::memcpy(target, &sum, sizeof sum);
    }
    if (i < rows) {
      double sum = inner > 0 ? a.coeff(i, 0) * rhs(0, j) : 0.0;
#pragma GCC unroll 8
      for (Index k = 1; k < inner; ++k) sum += a.coeff(i, k) * rhs(k, j);
      if constexpr (store == Store::Assign) out.coeffRef(i, j) = sum;
      if constexpr (store == Store::Add) out.coeffRef(i, j) += sum;
      if constexpr (store == Store::Subtract) out.coeffRef(i, j) -= sum;
    }
  }
}

}  // namespace estimation
