// PeriodSmoother for one filter type computing the batch MAP track of a FusionCore<Filter>'s
// run (sf_estimation/batch_map_smoother.hpp, the replay's --smooth batch): it records, beside
// each period's belief and control, the measurement the filter was given in it
// (FusionCore::lastMeasurement), which the RTS pass does not need. Made by
// FusionEngine::makeBatchSmoother() only when asked for, so no other run records it. KF, EKF
// and UKF (HasBatchSmoother): the UKF's MAP track is defined by the same f, h, Q and R.
#pragma once

#include <memory>
#include <optional>
#include <type_traits>
#include <utility>
#include <vector>

#include <sf_estimation/batch_map_smoother.hpp>

#include "sf_filter/core/period_smoother.hpp"
#include "sf_filter/core/period_smoother_of.hpp"

namespace sf_filter {

/// sf_estimation's batch smoother for Filter (estimation::batchSmootherFor).
template <class Filter>
using BatchSmootherFor = decltype(estimation::batchSmootherFor(std::declval<const Filter&>()));
/// Whether sf_estimation has a batch smoother for Filter.
template <class Filter>
using HasBatchSmoother = IsDetected<BatchSmootherFor, Filter>;

/// The measured period of a core's filter: belief, control and the measurement given.
template <class Filter>
using MeasuredPeriodOf =
    estimation::MeasuredPeriod<Filter::StateSize, Filter::MeasurementSize, Filter::ControlSize>;

template <class Core>
class BatchPeriodSmootherOf final
    : public RecordedRunSmoother<Core, BatchSmootherFor<FilterOf<Core>>,
                                 MeasuredPeriodOf<FilterOf<Core>>> {
  using Base = typename BatchPeriodSmootherOf::RecordedRunSmoother;
  using Period = MeasuredPeriodOf<FilterOf<Core>>;

 public:
  explicit BatchPeriodSmootherOf(const Core& core)
      : Base(core, estimation::batchSmootherFor(core.filter())) {}

  void record() override {
    this->record_.push_back(
        Period{this->recorder_.next(this->core_), this->core_.lastMeasurement()});
  }

  void smooth() override {
    const estimation::BatchMapReport r = this->smoother_.smooth(this->record_, this->smoothed_);
    outcome_ = BatchOutcome{r.iterations, r.halvings, r.initialCost, r.cost, r.converged};
  }

  PeriodBelief filtered(std::size_t k) const override {
    return viewOf(this->record_[k].belief.x, this->record_[k].belief.P);
  }
  /// The record (with the measurement), the result and the smoother's working track.
  std::size_t bytesPerPeriod() const override {
    return sizeof(Period) + sizeof(estimation::SmoothedPeriod<Base::N>) +
           BatchSmootherFor<FilterOf<Core>>::bytesPerPeriodWorking();
  }
  std::optional<BatchOutcome> batchOutcome() const override { return outcome_; }
  SmoothingCorrection correction(std::size_t k) const override {
    return smoothingCorrection(filtered(k), this->smoothed(k), this->core_.filter().angleStates());
  }

 private:
  std::optional<BatchOutcome> outcome_;
};

/// The batch smoother of a core's run, or null for a filter without one.
template <class Core>
std::unique_ptr<PeriodSmoother> makeBatchPeriodSmoother(const Core& core) {
  return makeSmootherIf<PeriodSmoother, BatchPeriodSmootherOf,
                        HasBatchSmoother<FilterOf<Core>>::value>(core);
}

}  // namespace sf_filter
