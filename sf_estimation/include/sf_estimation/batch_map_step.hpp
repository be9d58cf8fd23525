// The size-only step of the batch MAP smoother (batch_map_smoother.hpp): a residual's weighted
// square r^T C^-1 r. Compiled once in the library for the sizes 1..8 and 13 of the Kalman grid
// (cmake/kalman_steps.cpp.in), as the RTS step is (rts_step.hpp): instantiated in every node,
// whose fusion engine can make a batch smoother, the LDLT factorisations had doubled the
// compile time of a Kalman-type node's unit (doc/smoothing.md, "Build cost").
#pragma once

#include <Eigen/Cholesky>

#include "sf_estimation/types.hpp"

namespace estimation {

/// r^T C^-1 r by C's LDLT factorisation. A zero pivot (a direction C gives no spread, e.g. a
/// state without process noise) is skipped, as in rtsGain: the residual is weighed only in the
/// directions C spans.
template <int S>
double weightedSquare(const Matrix<S, S>& covariance, const Vector<S>& r) {
  const Eigen::LDLT<Matrix<S, S>> factor(covariance);
  return r.dot(factor.solve(r));
}

#define SF_ESTIMATION_BATCH_MAP_STEP_INSTANCES(PREFIX, S) \
  PREFIX template double weightedSquare<S>(const Matrix<S, S>&, const Vector<S>&);
#define SF_ESTIMATION_BATCH_MAP_STEP(S) SF_ESTIMATION_BATCH_MAP_STEP_INSTANCES(, S)
#if !defined(SF_ESTIMATION_INSTANTIATING_KALMAN_STEPS) && !defined(SF_ESTIMATION_IMPLICIT_INSTANCES)
#define SF_ESTIMATION_EXTERN_BATCH_MAP_STEP(S) SF_ESTIMATION_BATCH_MAP_STEP_INSTANCES(extern, S)
SF_ESTIMATION_EXTERN_BATCH_MAP_STEP(1)
SF_ESTIMATION_EXTERN_BATCH_MAP_STEP(2)
SF_ESTIMATION_EXTERN_BATCH_MAP_STEP(3)
SF_ESTIMATION_EXTERN_BATCH_MAP_STEP(4)
SF_ESTIMATION_EXTERN_BATCH_MAP_STEP(5)
SF_ESTIMATION_EXTERN_BATCH_MAP_STEP(6)
SF_ESTIMATION_EXTERN_BATCH_MAP_STEP(7)
SF_ESTIMATION_EXTERN_BATCH_MAP_STEP(8)
SF_ESTIMATION_EXTERN_BATCH_MAP_STEP(13)
#undef SF_ESTIMATION_EXTERN_BATCH_MAP_STEP
#endif

}  // namespace estimation
