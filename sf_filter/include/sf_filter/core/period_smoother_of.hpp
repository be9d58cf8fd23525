// PeriodSmoother for one filter type: the record of a FusionCore<Filter>'s run on the
// filter's fixed-size types and its RTS smoother (KF, EKF) or unscented RTS smoother (UKF).
// Filters without a smoother (particle filter, window filters) have none (HasSmoother).
#pragma once

#include <cstdint>
#include <memory>
#include <type_traits>
#include <utility>
#include <vector>

#include <sf_estimation/rts_smoother.hpp>
#include <sf_estimation/unscented_rts_smoother.hpp>

#include "sf_filter/core/period_smoother.hpp"

namespace sf_filter {

/// Whether sf_estimation has a smoother for Filter (estimation::smootherFor).
template <class Filter, class = void>
struct HasSmoother : std::false_type {};
template <class Filter>
struct HasSmoother<Filter,
                   std::void_t<decltype(estimation::smootherFor(std::declval<const Filter&>()))>>
    : std::true_type {};

/// Turns a core's last estimates into the smoothers' record (estimation::FilteredPeriod): a
/// period is linked to the previously recorded one only when the filter reached it by a time
/// update from it. A rejected step (the belief kept and widened by Q), a restart or a clock
/// reset since the last record (the filter back at its initial belief) is not such an update.
template <class Core, class Period>
class PeriodRecorder {
 public:
  Period next(const Core& core) {
    const auto& e = core.lastEstimate();
    const bool predicted =
        linked_ && !e.stepFailed && !e.filterReset && core.clockResets() == clockResets_;
    clockResets_ = core.clockResets();
    linked_ = true;
    if (!predicted) ++segments_;
    return Period{e.state, e.covariance, core.filter().control(), predicted};
  }
  /// The next period starts a new segment (its predecessor was not recorded).
  void cut() { linked_ = false; }
  std::size_t segments() const { return segments_; }

 private:
  bool linked_ = false;
  std::uint64_t clockResets_ = 0;
  std::size_t segments_ = 0;
};

template <class Core>
class PeriodSmootherOf final : public PeriodSmoother {
  using Filter = std::decay_t<decltype(std::declval<const Core&>().filter())>;
  using Smoother = decltype(estimation::smootherFor(std::declval<const Filter&>()));
  static constexpr int N = Filter::StateSize;
  static constexpr int L = Filter::ControlSize;
  using Period = estimation::FilteredPeriod<N, L>;

 public:
  explicit PeriodSmootherOf(const Core& core)
      : core_(core), smoother_(estimation::smootherFor(core.filter())) {}

  void record() override { record_.push_back(recorder_.next(core_)); }

  void smooth() override { smoother_.smooth(record_, smoothed_); }

  std::size_t periods() const override { return record_.size(); }
  std::size_t segments() const override { return recorder_.segments(); }
  PeriodBelief filtered(std::size_t k) const override { return viewOf(record_[k].x, record_[k].P); }
  PeriodBelief smoothed(std::size_t k) const override {
    return viewOf(smoothed_[k].x, smoothed_[k].P);
  }
  std::size_t bytesPerPeriod() const override {
    return sizeof(Period) + sizeof(estimation::SmoothedPeriod<N>);
  }
  SmoothingCorrection correction(std::size_t k) const override {
    return smoothingCorrection(filtered(k), smoothed(k), smoother_.angleStates());
  }

 private:
  const Core& core_;
  Smoother smoother_;
  std::vector<Period> record_;
  std::vector<estimation::SmoothedPeriod<N>> smoothed_;
  PeriodRecorder<Core, Period> recorder_;
};

/// The filter type of a fusion core.
template <class Core>
using FilterOf = std::decay_t<decltype(std::declval<const Core&>().filter())>;

/// A Smoother<Core> of `core` (and `args`), seen as Base, when `available` (the core's filter
/// has that smoother); null otherwise. The smoothers' factories are functions, not members of
/// FusionEngineOf, so that a header's node can compile them in a unit of their own
/// (SF_FILTER_SMOOTHER_INSTANCES in fusion_engine_of.hpp).
template <class Base, template <class> class Smoother, bool available, class Core, class... Args>
std::unique_ptr<Base> makeSmootherIf(const Core& core, Args... args) {
  if constexpr (available) {
    return std::make_unique<Smoother<Core>>(core, args...);
  } else {
    return nullptr;
  }
}

/// The offline smoother of a core's run, or null for a filter without one.
template <class Core>
std::unique_ptr<PeriodSmoother> makePeriodSmoother(const Core& core) {
  return makeSmootherIf<PeriodSmoother, PeriodSmootherOf, HasSmoother<FilterOf<Core>>::value>(core);
}

}  // namespace sf_filter
