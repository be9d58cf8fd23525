// FILL alignment: Wang et al.'s filling of the gap between low-rate samples with their
// estimates (Algorithm 1, eqs. 5-11). The newest N samples u(j), ..., u(j-N+1) are stored;
// in a period without a sample the substitute is a Bezier curve whose control points are the
// filter's predicted measurement z^(k) = h(x(k|k-1)) (newest, eq. 6) and the stored samples:
//
//   u^(k) = sum_{i=0..n} C(n, i) w1^(n-i) w2^i P_i,   P_0 = z^(k), P_i = u(j-i+1)  (eqs. 7, 11)
//   w1 = (t_k - t_oldest) / T_N,   w2 = omega / T_N,   T_N = t_k + omega - t_oldest
//
// with n the number of stored samples (N once N samples arrived) and t_oldest the time of the
// oldest. The paper places z^(k) at t_k + omega instead of at the time of u(j) (Remark 4.1)
// and writes w~2 = -omega / T_N; substituting t_k + omega for t_u(j) in its eqs. (9) and (10)
// gives w2 = +omega / T_N and T_N = t_k + omega - t_oldest, which is what is done here: the
// weights are then positive and sum to (w1 + w2)^n = 1 (the curve stays in the convex hull of
// its control points, as the paper says), and the two weights it quotes for Fig. 2 (0.821,
// 0.163) are of this form: w1^n and n w1^(n-1) w2 with w1 + w2 = 1. A small omega gives
// z^(k) almost all the weight (the substitute follows the filter's prediction); a larger
// one pulls it towards the stored samples. For an angle input the samples are unwrapped, and
// z^(k) moved to within pi of the newest, before the curve is evaluated, and the substitute
// is wrapped (unwrapped_angles.hpp).
#pragma once

#include "sf_filter/core/alignment/hold_primitives.hpp"
#include "sf_filter/core/alignment/sample_history.hpp"
#include "sf_filter/core/alignment/unwrapped_angles.hpp"

namespace sf_filter {

class GapFilling {
 public:
  /// omega > 0 [s], 1 <= samples <= SampleHistory::kCapacity (AlignmentPolicy validates them).
  /// `angle`: the samples are angles in radians.
  GapFilling(double omega, int samples, bool angle = false)
      : omega_(omega), angle_(angle), history_(samples) {}

  /// Algorithm 1, line 4: the low-rate input was sampled at `time`.
  void sampled(double time, double value) { history_.push(time, value); }

  /// True once a sample is stored (before that there is nothing to fill from).
  bool ready() const { return !history_.empty(); }

  /// Algorithm 1, lines 7-9: the substitute at time t (after the newest sample) given the
  /// filter's predicted measurement z^(k) = h(x(k|k-1)). Requires ready().
  double value(double t, double predicted) const {
    if (!angle_) return fill(history_, t, predicted);
    const SampleHistory u = unwrappedAngles(history_);
    return estimation::wrapAngle(fill(u, t, unwrappedAngle(predicted, u[0].value)));
  }

  void clear() { history_.clear(); }

  double omega() const { return omega_; }
  const SampleHistory& history() const { return history_; }

 private:
  /// Eqs. (7)-(11) on the samples `h`.
  double fill(const SampleHistory& h, double t, double predicted) const {
    const int n = h.size();
    const double oldest = h[n - 1].time;
    const double span = t + omega_ - oldest;
    const double w1 = (t - oldest) / span, w2 = omega_ / span;
    return bernsteinCombination(n, w1, w2,
                                [&](int i) { return i == 0 ? predicted : h[i - 1].value; });
  }

  double omega_;
  bool angle_;
  SampleHistory history_;
};

}  // namespace sf_filter
