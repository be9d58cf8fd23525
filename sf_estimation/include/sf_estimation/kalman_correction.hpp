// The measurement update shared by KF, EKF and UKF, including missing measurements.
//
// Missing entries: the update must equal the one of the same filter run with only the present
// rows of h, H and R. Instead of building reduced matrices (which would allocate), the rows of
// a missing entry are neutralised: its innovation and its rows of H (or of the cross
// covariance) are zero and its row and column of the noise matrix are those of the identity.
// The innovation covariance is then block-diagonal with an identity block, its inverse is the
// reduced inverse padded with that identity, and the gain's column for the missing entry is
// zero: exactly the reduced update, covariance included.
//
// Products are written as `multiply<Store::Add>(a, b, out)` (small_products.hpp): plain
// loops, vectorised two rows at a time as Eigen's coefficient-based product is, that compile in
// half the time of Eigen's product expressions, which made up most of a grid unit's compile
// time (doc/build_cost.md, "Plain-loop products"). Each entry is summed in the order of
// Eigen's vectorised product; its scalar path summed pairwise, so that results of an odd row
// can differ from the expression form's in the last bit. Dynamic sizes take the same loops,
// which suits the factory's small filters; Eigen's blocked product would only pay off from a
// few dozen states.
#pragma once

#include <Eigen/Cholesky>

#include "sf_estimation/angles.hpp"
#include "sf_estimation/errors.hpp"
#include "sf_estimation/measurement.hpp"
#include "sf_estimation/measurement_noise.hpp"
#include "sf_estimation/numerical_repairs.hpp"
#include "sf_estimation/parameter_checks.hpp"
#include "sf_estimation/small_products.hpp"

namespace estimation {

/// Zeroes the innovation and the given rows of `rows` for every missing entry.
template <int M, class RowsType>
void neutraliseMissing(const Measurement<M>& z, Vector<M>& innovation, RowsType& rows) {
  for (Index i = 0; i < z.size(); ++i) {
    if (!z.available(i)) {
      innovation(i) = 0.0;
      rows.row(i).setZero();
    }
  }
}

/// K.col(i) /= diagonal(i) for every column i: two rows to a register, and the last row of an odd
/// number of rows two columns to a register. Always inlined: as a call it kept K in memory
/// between the solves (KF nav3red 13 % slower).
template <int N, int M>
__attribute__((always_inline)) inline void divideColumns(const Matrix<M, M>& diagonal,
                                                         Matrix<N, M>& K) {
  using pairs::load;
  using pairs::Pair;
  const Index n = K.rows();
  const Index m = K.cols();
#pragma GCC unroll 8
  for (Index i = 0; i < m; ++i) {
#pragma GCC unroll 8
    for (Index r = 0; r + 2 <= n; r += 2) {
      pairs::store(load(&K(r, i)) / diagonal(i, i), &K(r, i));
    }
  }
  if (n % 2 == 0) return;
  const Index last = n - 1;
  Index i = 0;
#pragma GCC unroll 8
  for (; i + 2 <= m; i += 2) {
    const Pair quotient =
        Pair{K(last, i), K(last, i + 1)} / Pair{diagonal(i, i), diagonal(i + 1, i + 1)};
    K(last, i) = quotient[0];
    K(last, i + 1) = quotient[1];
  }
  if (i < m) K(last, i) /= diagonal(i, i);
}

/// symmetrize(S) for kalmanGain, which loads S's columns two rows at a time paired from the last
/// row up: the means are written that way, column by column (above the diagonal the ones already
/// written into the columns before). Written one at a time, each pair load of two means waited
/// until both stores reached the cache.
template <int M>
__attribute__((always_inline)) inline void symmetrizeInPairs(Matrix<M, M>& S) {
  const auto entry = [&S](Index i, Index j) {
    return i < j ? S(j, i) : (i == j ? S(j, j) : 0.5 * (S(i, j) + S(j, i)));
  };
  const Index m = S.rows();
#pragma GCC unroll 8
  for (Index j = 0; j < m; ++j) {
    Index i = 0;
    if (m % 2 != 0) S(i++, j) = entry(0, j);
#pragma GCC unroll 8
    for (; i < m; i += 2) pairs::store(pairs::Pair{entry(i, j), entry(i + 1, j)}, &S(i, j));
  }
}

/// K = crossCovariance * S^-1. Throws NumericalError when S is not positive definite or the
/// gain is not finite.
///
/// S is factorised as L D L^T (unit lower triangular L, diagonal D; the square-root-free form
/// of Cholesky, with the same positive-definiteness test: every pivot of D > 0). At these
/// sizes the cost is latency, not arithmetic: Cholesky chains a square root and a division
/// per column, through the factorisation and again through both triangular solves, while
/// here the solves need no division but the independent ones by D. Both solves run on whole
/// columns of K (contiguous N-vectors).
template <int N, int M>
void kalmanGain(const Matrix<N, M>& crossCovariance, const Matrix<M, M>& S, Matrix<N, M>& K) {
  // The loops are unrolled for the grid's sizes: rolled, every entry of L and D went through
  // the stack between the columns, a store and a reload in each step of the chain. The
  // divisions, whose throughput is most of the solve's cost, go two to a register wherever two
  // share the step: each lane rounds as its own division.
  using pairs::load;
  using pairs::Pair;
  const Index m = S.rows();
  Matrix<M, M> LD(m, m);  // L below the diagonal, D on it; only S's lower part is read
  Vector<M> scaled(m);    // row k of L times D
#pragma GCC unroll 8
  for (Index k = 0; k < m; ++k) {
    double pivot = S(k, k);
#pragma GCC unroll 8
    for (Index j = 0; j < k; ++j) {
      scaled(j) = LD(k, j) * LD(j, j);
      pivot -= scaled(j) * LD(k, j);
    }
    if (pivot <= 0.0) {
      throw NumericalError("innovation covariance is not positive definite; step rejected");
    }
    LD(k, k) = pivot;
    // Rows paired from the last one up, the same pairs in every column: paired from row k + 1
    // down, a column's pairs straddled the next one's, and each of those loads of L waited
    // until the two stores reached the cache.
    Index i = k + 1;
    if ((m - i) % 2 != 0) {
      double sum = S(i, k);
#pragma GCC unroll 8
      for (Index j = 0; j < k; ++j) sum -= LD(i, j) * scaled(j);
      LD(i, k) = sum / pivot;
      ++i;
    }
#pragma GCC unroll 8
    for (; i < m; i += 2) {
      Pair sum = load(&S(i, k));
#pragma GCC unroll 8
      for (Index j = 0; j < k; ++j) sum -= load(&LD(i, j)) * scaled(j);
      pairs::store(sum / pivot, &LD(i, k));
    }
  }
  // K L D L^T = crossCovariance. K <- crossCovariance L^-T column by column: copied as one
  // block, an odd column's entries were stored at other boundaries than the solve loads them
  // at, and each load waited for the stores to reach the cache.
#pragma GCC unroll 8
  for (Index i = 0; i < m; ++i) {
    K.col(i) = crossCovariance.col(i);
#pragma GCC unroll 8
    for (Index j = 0; j < i; ++j) K.col(i) -= LD(i, j) * K.col(j);
  }
  divideColumns<N, M>(LD, K);  // K <- K D^-1
#pragma GCC unroll 8
  for (Index i = m - 1; i >= 0; --i) {  // K <- K L^-1
#pragma GCC unroll 8
    for (Index j = i + 1; j < m; ++j) K.col(i) -= LD(j, i) * K.col(j);
  }
  if (!K.allFinite()) throw NumericalError("Kalman gain is not finite; step rejected");
}

/// Linear(ised) correction of (x, P) with Jacobian H (rows of missing entries already zero),
/// innovation y (zero for missing entries) and effective noise R. Joseph form keeps P
/// symmetric positive semi-definite even when K is slightly off.
template <int N, int M>
void linearCorrection(Vector<N>& x, Matrix<N, N>& P, const Matrix<M, N>& H, const Vector<M>& y,
                      const Matrix<M, M>& R) {
  const Index n = P.rows();
  const Index m = H.rows();
  Matrix<N, M> PHt(n, m);
  multiply<Store::Assign, true>(P, H, PHt);
  Matrix<M, M> S(m, m);
  multiplyOnto<Store::Add>(R, H, PHt, S);
  symmetrizeInPairs<M>(S);
  Matrix<N, M> K(n, m);
  kalmanGain<N, M>(PHt, S, K);
  multiply<Store::Add>(K, y, x);
  Matrix<N, N> IKH(n, n);
  multiplyOnto<Store::Subtract>(Matrix<N, N>::Identity(n, n), K, H, IKH);
  // (I - K H) P = P - K (P H^T)^T as P is symmetric: reuses P H^T, n^2 m instead of n^3.
  Matrix<N, N> IKHP(n, n);
  multiplyOnto<Store::Subtract, true>(P, K, PHt, IKHP);
  Matrix<N, M> KR(n, m);
  multiply<Store::Assign>(K, R, KR);
  multiply<Store::Assign, true>(IKHP, IKH, P);
  multiply<Store::Add, true>(KR, K, P);
}

/// Correction of (x, P) from the predicted measurement's mean zMean and covariance Pzz (R
/// not included) and the state-measurement cross covariance Pxz, as the UKF has them from its
/// sigma points: K = Pxz (Pzz + R)^-1, x += K y, P -= K (Pzz + R) K^T. The innovation y =
/// z - zMean is wrapped for the angle measurements; missing entries are neutralised as above
/// (Pxz and Pzz are scratch: their missing rows and columns are zeroed).
template <int N, int M>
void crossCovarianceCorrection(const Measurement<M>& z, const Vector<M>& zMean,
                               const AngleMask<M>& angleMeasurements, const Matrix<M, M>& noise,
                               Matrix<N, M>& Pxz, Matrix<M, M>& Pzz, Vector<N>& x,
                               Matrix<N, N>& P) {
  const Index m = z.size();
  Vector<M> y = z.value - zMean;
  angleMeasurements.wrap(y);
  Matrix<M, N> PxzT = Pxz.transpose();
  neutraliseMissing(z, y, PxzT);
  Pxz = PxzT.transpose();
  for (Index i = 0; i < m; ++i) {
    if (!z.available(i)) {
      Pzz.row(i).setZero();
      Pzz.col(i).setZero();
    }
  }
  Matrix<M, M> R(m, m);
  effectiveMeasurementNoise(noise, z, R);
  Matrix<M, M> S = Pzz + R;
  symmetrizeInPairs<M>(S);
  Matrix<N, M> K(x.size(), m);
  kalmanGain<N, M>(Pxz, S, K);
  multiply<Store::Add>(K, y, x);
  Matrix<N, M> KS(x.size(), m);
  multiply<Store::Assign>(K, S, KS);
  multiply<Store::Subtract, true>(KS, K, P);
}

/// Covariance time update P_next = A P A^T + Q, shared by KF and EKF.
template <int N>
void propagateCovariance(const Matrix<N, N>& A, const Matrix<N, N>& P, const Matrix<N, N>& Q,
                         Matrix<N, N>& next) {
  Matrix<N, N> AP(A.rows(), P.cols());
  multiply<Store::Assign>(A, P, AP);
  next.resize(Q.rows(), Q.cols());
  multiplyOnto<Store::Add, true>(Q, AP, A, next);
}

/// Covariance of a linear(ised) measurement of the state, H P H^T, shared by KF and EKF
/// (their measurement predictions for the gate and the NIS check).
template <int N, int M>
void projectCovariance(const Matrix<M, N>& H, const Matrix<N, N>& P, Matrix<M, M>& out) {
  Matrix<M, N> HP(H.rows(), P.cols());
  multiply<Store::Assign>(H, P, HP);
  out.resize(H.rows(), H.rows());
  multiply<Store::Assign, true>(HP, H, out);
}

/// Readies a step's result (x, P) to become the belief: P symmetrised and, if it lost positive
/// semi-definiteness, repaired; angle states of x wrapped. A non-finite x or P is refused with
/// NumericalError naming `method` (the caller then keeps its belief). Returns whether P was
/// repaired.
template <int N>
bool settleBelief(Vector<N>& x, Matrix<N, N>& P, const AngleMask<N>& angleStates,
                  const std::string& method) {
  const bool finite = symmetrizeFinite(P);
  if (!finite || !x.allFinite()) rejectStep(method, "the estimate became non-finite");
  const bool repaired = repairCovariance(P);
  // An unrepaired P is the one just found finite.
  if (repaired && !P.allFinite()) rejectStep(method, "the covariance repair failed");
  angleStates.wrap(x);
  return repaired;
}

// The size-only steps above are compiled once in the library for the state sizes N = 1..8
// and 13, and measurement sizes M = 1..6 that configurations use most (kalman_steps_*.cpp): a
// node's translation unit then does not instantiate them again, which halves a Kalman-type
// configuration's compile time. The UKF's correction is compiled once for N = 1..7 only, the
// sizes of the sigma-point grid (unscented_transform.hpp): a larger UKF compiles its
// transform in its own unit anyway. The grid stops at 8 states, plus 13 for the largest
// shipped header (config/husky_skid_steer_gps.h, an EKF, whose unit compiled them, its
// smoothers' steps included, in 7 s and 190 MB): each further size is one more unit of 20-40 s
// of CPU in every build of the package. Other sizes are instantiated where they are used.
// A target built without the generated units (the fuzzer) defines
// SF_ESTIMATION_IMPLICIT_INSTANCES, which drops these declarations here and in the
// sigma-point headers: every size is then instantiated where it is used.
#define SF_ESTIMATION_FOR_MEASUREMENT_SIZES(X, N) X(N, 1) X(N, 2) X(N, 3) X(N, 4) X(N, 5) X(N, 6)
#define SF_ESTIMATION_LINEAR_CORRECTION(N, M)                                          \
  template void linearCorrection<N, M>(Vector<N>&, Matrix<N, N>&, const Matrix<M, N>&, \
                                       const Vector<M>&, const Matrix<M, M>&);         \
  template void projectCovariance<N, M>(const Matrix<M, N>&, const Matrix<N, N>&, Matrix<M, M>&);
#define SF_ESTIMATION_CROSS_COVARIANCE_CORRECTION(N, M)                                  \
  template void crossCovarianceCorrection<N, M>(                                         \
      const Measurement<M>&, const Vector<M>&, const AngleMask<M>&, const Matrix<M, M>&, \
      Matrix<N, M>&, Matrix<M, M>&, Vector<N>&, Matrix<N, N>&);
#define SF_ESTIMATION_COVARIANCE_PROPAGATION(N)                                  \
  template void propagateCovariance<N>(const Matrix<N, N>&, const Matrix<N, N>&, \
                                       const Matrix<N, N>&, Matrix<N, N>&);      \
  template bool settleBelief<N>(Vector<N>&, Matrix<N, N>&, const AngleMask<N>&, const std::string&);
/// The steps of a state size of the Kalman and the sigma-point grid.
#define SF_ESTIMATION_KALMAN_STEPS(N)                                     \
  SF_ESTIMATION_COVARIANCE_PROPAGATION(N)                                 \
  SF_ESTIMATION_FOR_MEASUREMENT_SIZES(SF_ESTIMATION_LINEAR_CORRECTION, N) \
  SF_ESTIMATION_FOR_MEASUREMENT_SIZES(SF_ESTIMATION_CROSS_COVARIANCE_CORRECTION, N)
/// The steps of a state size of the Kalman grid only (no UKF correction).
#define SF_ESTIMATION_LINEAR_KALMAN_STEPS(N) \
  SF_ESTIMATION_COVARIANCE_PROPAGATION(N)    \
  SF_ESTIMATION_FOR_MEASUREMENT_SIZES(SF_ESTIMATION_LINEAR_CORRECTION, N)
/// The shipped 3D headers' tangent sizes (QUATERNION_STATES) with their measurements, outside
/// the grid: 15 with 15 and 19 (config/imu_odometry_3d.h, imu_odometry_pose_3d.h), 18 with 13
/// (the Armesto headers, their UKF's correction too); one unit per state size
/// (layout_kalman_steps_N.cpp, doc/build_cost.md "The 3D headers' step").
#define SF_ESTIMATION_LAYOUT_KALMAN_STEPS_15(PREFIX)  \
  SF_ESTIMATION_COVARIANCE_PROPAGATION_OF(PREFIX, 15) \
  SF_ESTIMATION_LINEAR_CORRECTION_OF(PREFIX, 15, 15)  \
  SF_ESTIMATION_LINEAR_CORRECTION_OF(PREFIX, 15, 19)
#define SF_ESTIMATION_LAYOUT_KALMAN_STEPS_18(PREFIX)  \
  SF_ESTIMATION_COVARIANCE_PROPAGATION_OF(PREFIX, 18) \
  SF_ESTIMATION_LINEAR_CORRECTION_OF(PREFIX, 18, 13)  \
  SF_ESTIMATION_CROSS_COVARIANCE_CORRECTION_OF(PREFIX, 18, 13)
// The same declarations with a prefix ("extern" or none), one declaration each: "extern"
// applies to the first declaration only.
#define SF_ESTIMATION_LINEAR_CORRECTION_OF(PREFIX, N, M)                                      \
  PREFIX template void linearCorrection<N, M>(Vector<N>&, Matrix<N, N>&, const Matrix<M, N>&, \
                                              const Vector<M>&, const Matrix<M, M>&);         \
  PREFIX template void projectCovariance<N, M>(const Matrix<M, N>&, const Matrix<N, N>&,      \
                                               Matrix<M, M>&);
#define SF_ESTIMATION_CROSS_COVARIANCE_CORRECTION_OF(PREFIX, N, M)                       \
  PREFIX template void crossCovarianceCorrection<N, M>(                                  \
      const Measurement<M>&, const Vector<M>&, const AngleMask<M>&, const Matrix<M, M>&, \
      Matrix<N, M>&, Matrix<M, M>&, Vector<N>&, Matrix<N, N>&);
#define SF_ESTIMATION_COVARIANCE_PROPAGATION_OF(PREFIX, N)                              \
  PREFIX template void propagateCovariance<N>(const Matrix<N, N>&, const Matrix<N, N>&, \
                                              const Matrix<N, N>&, Matrix<N, N>&);      \
  PREFIX template bool settleBelief<N>(Vector<N>&, Matrix<N, N>&, const AngleMask<N>&,  \
                                       const std::string&);
#if !defined(SF_ESTIMATION_INSTANTIATING_KALMAN_STEPS) && !defined(SF_ESTIMATION_IMPLICIT_INSTANCES)
// "extern" applies to the first declaration only; each size's declarations are listed apart.
#define SF_ESTIMATION_EXTERN_LINEAR_CORRECTION(N, M)                                          \
  extern template void linearCorrection<N, M>(Vector<N>&, Matrix<N, N>&, const Matrix<M, N>&, \
                                              const Vector<M>&, const Matrix<M, M>&);         \
  extern template void projectCovariance<N, M>(const Matrix<M, N>&, const Matrix<N, N>&,      \
                                               Matrix<M, M>&);
#define SF_ESTIMATION_EXTERN_CROSS_COVARIANCE_CORRECTION(N, M)                           \
  extern template void crossCovarianceCorrection<N, M>(                                  \
      const Measurement<M>&, const Vector<M>&, const AngleMask<M>&, const Matrix<M, M>&, \
      Matrix<N, M>&, Matrix<M, M>&, Vector<N>&, Matrix<N, N>&);
#define SF_ESTIMATION_EXTERN_LINEAR_STEPS(N)                                            \
  extern template void propagateCovariance<N>(const Matrix<N, N>&, const Matrix<N, N>&, \
                                              const Matrix<N, N>&, Matrix<N, N>&);      \
  extern template bool settleBelief<N>(Vector<N>&, Matrix<N, N>&, const AngleMask<N>&,  \
                                       const std::string&);                             \
  SF_ESTIMATION_FOR_MEASUREMENT_SIZES(SF_ESTIMATION_EXTERN_LINEAR_CORRECTION, N)
#define SF_ESTIMATION_EXTERN_STEPS(N)  \
  SF_ESTIMATION_EXTERN_LINEAR_STEPS(N) \
  SF_ESTIMATION_FOR_MEASUREMENT_SIZES(SF_ESTIMATION_EXTERN_CROSS_COVARIANCE_CORRECTION, N)
SF_ESTIMATION_EXTERN_STEPS(1)
SF_ESTIMATION_EXTERN_STEPS(2)
SF_ESTIMATION_EXTERN_STEPS(3)
SF_ESTIMATION_EXTERN_STEPS(4)
SF_ESTIMATION_EXTERN_STEPS(5)
SF_ESTIMATION_EXTERN_STEPS(6)
SF_ESTIMATION_EXTERN_STEPS(7)
SF_ESTIMATION_EXTERN_LINEAR_STEPS(8)
SF_ESTIMATION_EXTERN_LINEAR_STEPS(13)
SF_ESTIMATION_LAYOUT_KALMAN_STEPS_15(extern)
SF_ESTIMATION_LAYOUT_KALMAN_STEPS_18(extern)
#undef SF_ESTIMATION_EXTERN_STEPS
#undef SF_ESTIMATION_EXTERN_LINEAR_STEPS
#undef SF_ESTIMATION_EXTERN_CROSS_COVARIANCE_CORRECTION
#undef SF_ESTIMATION_EXTERN_LINEAR_CORRECTION
#endif

}  // namespace estimation
