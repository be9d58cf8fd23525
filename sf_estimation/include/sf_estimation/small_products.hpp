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

namespace pairs {

/// Two doubles in one vector register (GCC's and Clang's vector extension: SSE2 on x86-64, NEON
/// on ARM); each lane rounds as the scalar operation does.
using Pair = double __attribute__((vector_size(16)));

inline Pair load(const double* from) {
  Pair pair;
  std::memcpy(&pair, from, sizeof pair);
  return pair;
}

inline void store(const Pair& pair, double* to) { std::memcpy(to, &pair, sizeof pair); }

}  // namespace pairs

/// out = base (+, -) a * b, or a * b^T with `TransposeB` (base is not read for Store::Assign);
/// `out` and `base` have the product's size, and `base` may be `out` itself. Each entry's sum over
/// the inner index is formed in order, from its first product on, and only then assigned to,
/// added to or subtracted from base's entry. Two rows at a time share a vector register, the way
/// Eigen's coefficient-based product packs them, a last odd row alone: GCC does not find that
/// vectorisation in the plain loop by itself. (A matrix of two or more rows is column-major here;
/// Eigen stores only a single row row-major.) The inner loop is unrolled for the grid's sizes (up
/// to 8), as Eigen unrolls its fixed-size products.
template <Store store, bool TransposeB = false, class Base, class A, class B, class Out>
inline void multiplyOnto(const Base& base, const A& a, const B& b, Out& out) {
  static_assert(!A::IsRowMajor || A::RowsAtCompileTime == 1, "a: column-major or a single row");
  static_assert(!Out::IsRowMajor || Out::RowsAtCompileTime == 1,
                "out: column-major or a single row");
  static_assert(
      !Base::IsRowMajor || Base::RowsAtCompileTime == 1 || !(Base::Flags & Eigen::DirectAccessBit),
      "base: column-major, a single row or an expression");
  using pairs::load;
  using pairs::Pair;
  // An expression without storage (the identity) as the base gives its entries by value.
  const auto basePair = [&base](Index i, Index j) {
    if constexpr (bool(Base::Flags & Eigen::DirectAccessBit)) {
      return load(&base.coeffRef(i, j));
    } else {
      return Pair{base.coeff(i, j), base.coeff(i + 1, j)};
    }
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
      if constexpr (store == Store::Add) sum = basePair(i, j) + sum;
      if constexpr (store == Store::Subtract) sum = basePair(i, j) - sum;
      pairs::store(sum, &out.coeffRef(i, j));
    }
    if (i < rows) {
      double sum = inner > 0 ? a.coeff(i, 0) * rhs(0, j) : 0.0;
#pragma GCC unroll 8
      for (Index k = 1; k < inner; ++k) sum += a.coeff(i, k) * rhs(k, j);
      if constexpr (store == Store::Add) sum = base.coeff(i, j) + sum;
      if constexpr (store == Store::Subtract) sum = base.coeff(i, j) - sum;
      out.coeffRef(i, j) = sum;
    }
  }
}

/// out (=, +=, -=) a * b, or a * b^T with `TransposeB` (multiplyOnto with out as the base).
template <Store store, bool TransposeB = false, class A, class B, class Out>
inline void multiply(const A& a, const B& b, Out& out) {
  multiplyOnto<store, TransposeB>(out, a, b, out);
}

}  // namespace estimation
