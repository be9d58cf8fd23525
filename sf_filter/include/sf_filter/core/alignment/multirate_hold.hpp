// HOLD alignment: Armesto et al.'s multi-rate hold (Algorithm 1). Every sample of the input
// is shifted into a history of the newest order + 1 samples (lines 3-5); in a period without
// a sample the hold extrapolates the history to the period's time with its primitive function
// (lines 7-10, hold_primitives.hpp) instead of leaving the input missing. An angle input's
// history is unwrapped before and the value wrapped after (unwrapped_angles.hpp).
#pragma once

#include "sf_filter/core/alignment/hold_primitives.hpp"
#include "sf_filter/core/alignment/sample_history.hpp"
#include "sf_filter/core/alignment/unwrapped_angles.hpp"

namespace sf_filter {

class MultiRateHold {
 public:
  /// 0 <= order <= kMaxHoldOrder (AlignmentPolicy validates it; larger orders are clamped).
  /// `angle`: the samples are angles in radians.
  MultiRateHold(HoldPrimitive primitive, int order, bool angle = false)
      : primitive_(primitive),
        angle_(angle),
        order_(order < 0               ? 0
               : order > kMaxHoldOrder ? kMaxHoldOrder
                                       : order),
        history_(order_ + 1) {}

  /// Lines 3-5: the input was sampled at `time`.
  void sampled(double time, double value) { history_.push(time, value); }

  /// True once a sample is stored (before that there is nothing to hold).
  bool ready() const { return !history_.empty(); }

  /// Lines 7-10: the extrapolated value at t (after the newest sample). Requires ready().
  double value(double t) const {
    if (!angle_) return holdValue(primitive_, history_, order_, t);
    return estimation::wrapAngle(holdValue(primitive_, unwrappedAngles(history_), order_, t));
  }

  void clear() { history_.clear(); }

  HoldPrimitive primitive() const { return primitive_; }
  int order() const { return order_; }
  const SampleHistory& history() const { return history_; }

 private:
  HoldPrimitive primitive_;
  bool angle_;
  int order_;
  SampleHistory history_;
};

}  // namespace sf_filter
