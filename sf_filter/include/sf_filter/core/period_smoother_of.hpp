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

#include "sf_filter/core/detected.hpp"
#include "sf_filter/core/period_smoother.hpp"

namespace sf_filter {

/// The filter type of a fusion core.
template <class Core>
using FilterOf = std::decay_t<decltype(std::declval<const Core&>().filter())>;

/// sf_estimation's smoother for Filter (estimation::smootherFor).
template <class Filter>
using SmootherFor = decltype(estimation::smootherFor(std::declval<const Filter&>()));
/// Whether sf_estimation has a smoother for Filter.
template <class Filter>
using HasSmoother = IsDetected<SmootherFor, Filter>;

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

/// What a smoother of a core's run holds, whichever the smoother: the core, sf_estimation's
/// smoother, the record of the periods (Recorded: the belief, or with its measurement too), the
/// smoothed track and the recorder that links the periods.
template <class Core, class Smoother, class Recorded>
class RecordedRunSmoother : public PeriodSmoother {
 protected:
  using Filter = FilterOf<Core>;
  static constexpr int N = Filter::StateSize;
  static constexpr int L = Filter::ControlSize;
  using Belief = estimation::FilteredPeriod<N, L>;

  RecordedRunSmoother(const Core& core, Smoother smoother)
      : core_(core), smoother_(std::move(smoother)) {}

 public:
  std::size_t periods() const override { return record_.size(); }
  std::size_t segments() const override { return recorder_.segments(); }
  PeriodBelief smoothed(std::size_t k) const override {
    return viewOf(smoothed_[k].x, smoothed_[k].P);
  }

 protected:
  const Core& core_;
  Smoother smoother_;
  std::vector<Recorded> record_;
  std::vector<estimation::SmoothedPeriod<N>> smoothed_;
  PeriodRecorder<Core, Belief> recorder_;
};

template <class Core>
class PeriodSmootherOf final
    : public RecordedRunSmoother<
          Core, SmootherFor<FilterOf<Core>>,
          estimation::FilteredPeriod<FilterOf<Core>::StateSize, FilterOf<Core>::ControlSize>> {
 public:
  explicit PeriodSmootherOf(const Core& core)
      : PeriodSmootherOf::RecordedRunSmoother(core, estimation::smootherFor(core.filter())) {}

  void record() override { this->record_.push_back(this->recorder_.next(this->core_)); }

  void smooth() override { this->smoother_.smooth(this->record_, this->smoothed_); }

  PeriodBelief filtered(std::size_t k) const override {
    return viewOf(this->record_[k].x, this->record_[k].P);
  }
  std::size_t bytesPerPeriod() const override {
    return sizeof(typename PeriodSmootherOf::Belief) +
           sizeof(estimation::SmoothedPeriod<PeriodSmootherOf::N>);
  }
  SmoothingCorrection correction(std::size_t k) const override {
    return smoothingCorrection(filtered(k), this->smoothed(k), this->smoother_.angleStates());
  }
};

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
