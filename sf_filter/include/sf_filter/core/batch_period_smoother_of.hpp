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

/// Whether sf_estimation has a batch smoother for Filter (estimation::batchSmootherFor).
template <class Filter, class = void>
struct HasBatchSmoother : std::false_type {};
template <class Filter>
struct HasBatchSmoother<
    Filter, std::void_t<decltype(estimation::batchSmootherFor(std::declval<const Filter&>()))>>
    : std::true_type {};

template <class Core>
class BatchPeriodSmootherOf final : public PeriodSmoother {
  using Filter = std::decay_t<decltype(std::declval<const Core&>().filter())>;
  using Smoother = decltype(estimation::batchSmootherFor(std::declval<const Filter&>()));
  static constexpr int N = Filter::StateSize;
  static constexpr int M = Filter::MeasurementSize;
  static constexpr int L = Filter::ControlSize;
  using Period = estimation::MeasuredPeriod<N, M, L>;
  using Belief = estimation::FilteredPeriod<N, L>;

 public:
  explicit BatchPeriodSmootherOf(const Core& core)
      : core_(core), smoother_(estimation::batchSmootherFor(core.filter())) {}

  void record() override {
    record_.push_back(Period{recorder_.next(core_), core_.lastMeasurement()});
  }

  void smooth() override {
    const estimation::BatchMapReport r = smoother_.smooth(record_, smoothed_);
    outcome_ = BatchOutcome{r.iterations, r.halvings, r.initialCost, r.cost, r.converged};
  }

  std::size_t periods() const override { return record_.size(); }
  std::size_t segments() const override { return recorder_.segments(); }
  PeriodBelief filtered(std::size_t k) const override {
    return viewOf(record_[k].belief.x, record_[k].belief.P);
  }
  PeriodBelief smoothed(std::size_t k) const override {
    return viewOf(smoothed_[k].x, smoothed_[k].P);
  }
  /// The record (with the measurement), the result and the smoother's working track.
  std::size_t bytesPerPeriod() const override {
    return sizeof(Period) + sizeof(estimation::SmoothedPeriod<N>) +
           Smoother::bytesPerPeriodWorking();
  }
  std::optional<BatchOutcome> batchOutcome() const override { return outcome_; }
  SmoothingCorrection correction(std::size_t k) const override {
    return smoothingCorrection(filtered(k), smoothed(k), core_.filter().angleStates());
  }

 private:
  const Core& core_;
  Smoother smoother_;
  std::vector<Period> record_;
  std::vector<estimation::SmoothedPeriod<N>> smoothed_;
  PeriodRecorder<Core, Belief> recorder_;
  std::optional<BatchOutcome> outcome_;
};

/// The batch smoother of a core's run, or null for a filter without one.
template <class Core>
std::unique_ptr<PeriodSmoother> makeBatchPeriodSmoother(const Core& core) {
  return makeSmootherIf<PeriodSmoother, BatchPeriodSmootherOf,
                        HasBatchSmoother<FilterOf<Core>>::value>(core);
}

}  // namespace sf_filter
