// LaggedSmoother for one filter type: the fixed-lag RTS smoother (KF, EKF) or fixed-lag
// unscented RTS smoother (UKF) of a FusionCore<Filter>, on the filter's fixed-size types, fed
// the same record as the offline smoother (period_smoother_of.hpp's PeriodRecorder).
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <type_traits>
#include <utility>
#include <vector>

#include <sf_estimation/errors.hpp>
#include <sf_estimation/fixed_lag_smoother.hpp>

#include "sf_filter/core/lagged_smoother.hpp"
#include "sf_filter/core/period_smoother_of.hpp"

namespace sf_filter {

template <class Core>
class LaggedSmootherOf final : public LaggedSmoother {
  using Filter = std::decay_t<decltype(std::declval<const Core&>().filter())>;
  using Smoother =
      decltype(estimation::fixedLagSmootherFor(std::declval<const Filter&>(), std::size_t{}));
  static constexpr int N = Filter::StateSize;
  static constexpr int L = Filter::ControlSize;
  using Period = estimation::FilteredPeriod<N, L>;

 public:
  LaggedSmootherOf(const Core& core, std::size_t lag)
      : core_(core),
        smoother_(estimation::fixedLagSmootherFor(core.filter(), lag)),
        periods_(lag + 1) {}

  std::optional<LaggedBelief> add() override {
    Period period = recorder_.next(core_);
    const estimation::SmoothedPeriod<N>* smoothed = nullptr;
    try {
      smoothed = hold(period);
    } catch (const estimation::NumericalError&) {
      // The link to the held periods was refused (nothing was added): start anew from this
      // period, as the offline pass starts a new segment.
      ++failures_;
      smoother_.clear();
      added_ = 0;
      period.predicted = false;
      smoothed = hold(period);
    }
    if (!smoothed) return std::nullopt;
    const PeriodStamp& lagged = periods_[(added_ - 1 - lag()) % periods_.size()];
    const Period& filtered = smoother_.laggedFiltered();
    last_ = smoothingCorrection(viewOf(filtered.x, filtered.P), viewOf(smoothed->x, smoothed->P),
                                smoother_.angleStates());
    total_.add(last_);
    return LaggedBelief{lagged.time, lagged.presentInputs, viewOf(smoothed->x, smoothed->P)};
  }

  std::size_t lag() const override { return smoother_.lag(); }
  std::size_t periodsHeld() const override { return smoother_.periodsHeld(); }
  std::size_t segments() const override { return recorder_.segments() + failures_; }
  std::uint64_t failures() const override { return failures_; }
  std::size_t bytes() const override {
    return periods_.size() * (Smoother::bytesPerSlot() + sizeof(PeriodStamp));
  }
  SmoothingCorrection lastCorrection() const override { return last_; }
  const SmoothingCorrectionTotal& corrections() const override { return total_; }

 private:
  const estimation::SmoothedPeriod<N>* hold(const Period& period) {
    const auto& e = core_.lastEstimate();
    periods_[added_ % periods_.size()] = PeriodStamp{e.time, e.presentInputs};
    const estimation::SmoothedPeriod<N>* smoothed = smoother_.add(period);
    ++added_;
    return smoothed;
  }

  const Core& core_;
  Smoother smoother_;
  /// What the smoothed belief does not hold of each held period, in the smoother's ring order.
  struct PeriodStamp {
    double time = 0.0;
    Index presentInputs = 0;
  };
  std::vector<PeriodStamp> periods_;
  std::size_t added_ = 0;
  std::uint64_t failures_ = 0;
  SmoothingCorrection last_;
  SmoothingCorrectionTotal total_;
  PeriodRecorder<Core, Period> recorder_;
};

/// The fixed-lag smoother of a core over lagPeriods periods, or null for a filter without one.
template <class Core>
std::unique_ptr<LaggedSmoother> makeLaggedSmootherOf(const Core& core, std::size_t lagPeriods) {
  return makeSmootherIf<LaggedSmoother, LaggedSmootherOf, HasSmoother<FilterOf<Core>>::value>(
      core, lagPeriods);
}

}  // namespace sf_filter
