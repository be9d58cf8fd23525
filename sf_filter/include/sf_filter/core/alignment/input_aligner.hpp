// The alignment of one input across periods: turns what the input received in a period
// (InputPeriod) into the value the filter gets, by the input's policy (alignment_policy.hpp),
// and keeps the HOLD or FILL history between periods. The fusion core decides in between
// whether the measured value passes the input's gate; only then does it enter the history.
// An angle input is averaged on the circle (period_average.hpp) and extrapolated unwrapped
// (unwrapped_angles.hpp); its mean and substitutes are wrapped to (-pi, pi].
#pragma once

#include <cstdint>
#include <optional>

#include "sf_filter/core/alignment/alignment_policy.hpp"
#include "sf_filter/core/alignment/gap_filling.hpp"
#include "sf_filter/core/alignment/input_period.hpp"
#include "sf_filter/core/alignment/multirate_hold.hpp"

namespace sf_filter {

/// The value one input contributes to one estimation step.
struct AlignedValue {
  double value = 0.0;
  std::optional<double> variance;  ///< none: the filter's configured R
  bool substitute = false;         ///< made by HOLD or FILL, not measured
};

class InputAligner {
 public:
  /// `angle`: the input measures an angle in radians.
  explicit InputAligner(const AlignmentPolicy& policy, bool angle = false)
      : policy_(policy),
        hold_(policy.primitive, policy.order, angle),
        fill_(policy.omega, policy.samples > 0 ? policy.samples : 1, angle) {}

  const AlignmentPolicy& policy() const { return policy_; }

  /// The value measured in the period: the mean (AVERAGE) or the newest value; none if
  /// nothing arrived. Angles without a mean direction (spread evenly around the circle) give
  /// the newest value.
  std::optional<AlignedValue> measured(const InputPeriod& period) const {
    if (period.empty()) return std::nullopt;
    if (policy_.kind == AlignmentKind::Average && period.average().hasMean()) {
      const PeriodAverage& a = period.average();
      return AlignedValue{a.mean(),
                          a.hasVariance() ? std::optional<double>(a.meanVariance()) : std::nullopt};
    }
    return AlignedValue{period.newest().value(), period.newest().variance()};
  }

  /// The derivative of measured(period)'s value by the period's `ordinal`-th reading (1 for
  /// the first), whose value was `value`: the mean's weight for AVERAGE, 1 for the newest
  /// reading and 0 for the others under the other policies. Used to carry the covariances
  /// between inputs of one message into the aligned values. Requires a measured value.
  double weightOf(const InputPeriod& period, std::uint32_t ordinal, double value) const {
    if (policy_.kind == AlignmentKind::Average && period.average().hasMean()) {
      return period.average().weightOf(value);
    }
    return ordinal == period.count() ? 1.0 : 0.0;
  }

  /// Values of the period that measured() leaves out: all but the newest for LAST and
  /// SAMPLED (HOLD and FILL shift every sample into their history).
  std::uint32_t superseded(const InputPeriod& period) const {
    const bool newestOnly =
        policy_.kind == AlignmentKind::Last || policy_.kind == AlignmentKind::Sampled;
    return newestOnly && !period.empty() ? period.count() - 1 : 0;
  }

  /// The period's measured value was used: its samples enter the HOLD or FILL history.
  void accept(const InputPeriod& period) {
    if (!policy_.substitutes()) return;
    const SampleHistory& s = period.samples();
    for (int age = s.size() - 1; age >= 0; --age) {
      if (policy_.kind == AlignmentKind::Hold) hold_.sampled(s[age].time, s[age].value);
      if (policy_.kind == AlignmentKind::Fill) fill_.sampled(s[age].time, s[age].value);
    }
  }

  /// True when the policy substitutes and has a sample to do it from.
  bool canSubstitute() const {
    return (policy_.kind == AlignmentKind::Hold && hold_.ready()) ||
           (policy_.kind == AlignmentKind::Fill && fill_.ready());
  }

  /// The substitute at time t: the hold's extrapolation, or the gap filling with the
  /// filter's predicted measurement `predicted` (FILL only). Requires canSubstitute().
  AlignedValue substitute(double t, double predicted) const {
    const double value =
        policy_.kind == AlignmentKind::Hold ? hold_.value(t) : fill_.value(t, predicted);
    return AlignedValue{value, policy_.variance, true};
  }

  /// Forgets the history (filter reset).
  void reset() {
    hold_.clear();
    fill_.clear();
  }

 private:
  AlignmentPolicy policy_;
  MultiRateHold hold_;
  GapFilling fill_;
};

}  // namespace sf_filter
