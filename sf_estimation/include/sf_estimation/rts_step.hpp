// One backward step of the Rauch-Tung-Striebel smoother (rts_smoother.hpp) and its two halves,
// the gain and the correction (the fixed-lag smoother keeps the gain of each period), which
// depend only on the state size: compiled once in the library for the state sizes 1..8 and 13
// of the Kalman grid (cmake/kalman_steps.cpp.in), so that a node, whose fusion engine can make
// a smoother (sf_filter's period_smoother_of.hpp), does not instantiate it again.
#pragma once

#include <Eigen/Cholesky>

#include "sf_estimation/angles.hpp"
#include "sf_estimation/errors.hpp"
#include "sf_estimation/parameter_checks.hpp"
#include "sf_estimation/types.hpp"

namespace estimation {

/// The one-step prediction from a period to the next and the cross covariance of the two
/// states, Cov(x_k, x_k+1 | data up to k).
template <int N>
struct OneStepPrediction {
  explicit OneStepPrediction(Index n) : x(n), P(n, n), cross(n, n) {}
  Vector<N> x;
  Matrix<N, N> P;
  Matrix<N, N> cross;
};

/// The smoother gain G = C P(k+1|k)^-1 of a one-step prediction. Throws NumericalError when
/// the predicted covariance is indefinite or the gain is not finite.
template <int N>
void rtsGain(const OneStepPrediction<N>& prediction, Matrix<N, N>& gain) {
  // G^T = P(k+1|k)^-1 C^T, as P(k+1|k) is symmetric. LDLT (pivoted) rather than LLT: a
  // predicted covariance with an exactly known direction (a state without process noise that
  // the transition copies, or a record with P = 0) is only semi-definite. C is zero in such a
  // direction (P(k+1|k) >= F P F^T), and LDLT's solve then leaves the gain zero there (zero
  // pivots are skipped), which is the smoother's answer: nothing to propagate back. A negative
  // pivot (an indefinite prediction from a corrupt record) is refused.
  const Eigen::LDLT<Matrix<N, N>> factor(prediction.P);
  if (factor.info() != Eigen::Success || !factor.isPositive()) {
    throw NumericalError("RtsSmoother: the predicted covariance is indefinite");
  }
  gain = factor.solve(prediction.cross.transpose()).transpose();
  if (!gain.allFinite()) throw NumericalError("RtsSmoother: the smoother gain is not finite");
}

/// The smoothed (xOut, POut) at k from (x, P) filtered at k, the prediction to k+1 with its
/// gain (rtsGain) and (xNext, PNext) smoothed at k+1. Throws NumericalError when the result
/// is not finite.
template <int N>
void rtsCorrect(const Vector<N>& x, const Matrix<N, N>& P, const OneStepPrediction<N>& prediction,
                const Matrix<N, N>& gain, const Vector<N>& xNext, const Matrix<N, N>& PNext,
                const AngleMask<N>& angles, Vector<N>& xOut, Matrix<N, N>& POut) {
  Vector<N> difference = xNext - prediction.x;
  angles.wrap(difference);
  xOut = x + gain * difference;
  angles.wrap(xOut);
  const Matrix<N, N> spread = PNext - prediction.P;
  POut = P + gain * spread * gain.transpose();
  symmetrize(POut);
  if (!xOut.allFinite() || !POut.allFinite()) {
    throw NumericalError("RtsSmoother: the smoothed estimate became non-finite");
  }
}

/// One backward step: (x, P) filtered at k, `prediction` from k to k+1, (xNext, PNext)
/// smoothed at k+1; writes the smoothed (xOut, POut) at k. Throws NumericalError when the
/// predicted covariance is indefinite or the result is not finite.
template <int N>
void rtsBackwardStep(const Vector<N>& x, const Matrix<N, N>& P,
                     const OneStepPrediction<N>& prediction, const Vector<N>& xNext,
                     const Matrix<N, N>& PNext, const AngleMask<N>& angles, Vector<N>& xOut,
                     Matrix<N, N>& POut) {
  Matrix<N, N> gain(x.size(), x.size());
  rtsGain<N>(prediction, gain);
  rtsCorrect<N>(x, P, prediction, gain, xNext, PNext, angles, xOut, POut);
}

// The three steps' instantiations, each prefixed by PREFIX (empty or extern).
#define SF_ESTIMATION_RTS_STEP_INSTANCES(PREFIX, N)                                            \
  PREFIX template void rtsGain<N>(const OneStepPrediction<N>&, Matrix<N, N>&);                 \
  PREFIX template void rtsCorrect<N>(                                                          \
      const Vector<N>&, const Matrix<N, N>&, const OneStepPrediction<N>&, const Matrix<N, N>&, \
      const Vector<N>&, const Matrix<N, N>&, const AngleMask<N>&, Vector<N>&, Matrix<N, N>&);  \
  PREFIX template void rtsBackwardStep<N>(                                                     \
      const Vector<N>&, const Matrix<N, N>&, const OneStepPrediction<N>&, const Vector<N>&,    \
      const Matrix<N, N>&, const AngleMask<N>&, Vector<N>&, Matrix<N, N>&);
#define SF_ESTIMATION_RTS_STEP(N) SF_ESTIMATION_RTS_STEP_INSTANCES(, N)
#if !defined(SF_ESTIMATION_INSTANTIATING_KALMAN_STEPS) && !defined(SF_ESTIMATION_IMPLICIT_INSTANCES)
#define SF_ESTIMATION_EXTERN_RTS_STEP(N) SF_ESTIMATION_RTS_STEP_INSTANCES(extern, N)
SF_ESTIMATION_EXTERN_RTS_STEP(1)
SF_ESTIMATION_EXTERN_RTS_STEP(2)
SF_ESTIMATION_EXTERN_RTS_STEP(3)
SF_ESTIMATION_EXTERN_RTS_STEP(4)
SF_ESTIMATION_EXTERN_RTS_STEP(5)
SF_ESTIMATION_EXTERN_RTS_STEP(6)
SF_ESTIMATION_EXTERN_RTS_STEP(7)
SF_ESTIMATION_EXTERN_RTS_STEP(8)
SF_ESTIMATION_EXTERN_RTS_STEP(13)
#undef SF_ESTIMATION_EXTERN_RTS_STEP
#endif

}  // namespace estimation
