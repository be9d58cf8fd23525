// FusionEngine for one filter type: the fusion core on the filter's fixed-size types behind
// the run-time-sized interface the prebuilt node and replay use. Compiled in the translation
// unit of a configuration header; everything here forwards to FusionCore<Filter>.
#pragma once

#include <array>
#include <memory>
#include <string>
#include <type_traits>
#include <utility>

#include <sf_estimation/confidence_weighted_averaging.hpp>
#include <sf_estimation/moving_average.hpp>
#include <sf_estimation/moving_median.hpp>

#include "sf_filter/core/batch_period_smoother_of.hpp"
#include "sf_filter/core/fusion_core.hpp"
#include "sf_filter/core/fusion_engine.hpp"
#include "sf_filter/core/lagged_smoother_of.hpp"
#include "sf_filter/core/period_smoother_of.hpp"

namespace sf_filter {

template <class Filter>
class FusionEngineOf final : public FusionEngine {
  using Core = FusionCore<Filter>;

 public:
  FusionEngineOf(Filter filter, const FusionCoreOptions& options)
      : core_(std::move(filter), options) {}

  ClockEvent advanceTo(double now, EstimateCallback onEstimate) override {
    return core_.advanceTo(now, [&](const typename Core::Estimate& e) { onEstimate(view(e)); });
  }
  ClockEvent runTo(double now, std::uint64_t maxPeriods, EstimateCallback onEstimate) override {
    return core_.runTo(now, maxPeriods,
                       [&](const typename Core::Estimate& e) { onEstimate(view(e)); });
  }
  ClockEvent skipGap(double now, EstimateCallback onEstimate) override {
    return core_.skipGap(now, [&](const typename Core::Estimate& e) { onEstimate(view(e)); });
  }
  Rejection addMeasurement(Index input, double now, double value, std::optional<double> variance,
                           double stamp) override {
    return core_.addMeasurement(input, now, value, variance, stamp);
  }
  Rejection addMeasurementBlock(const Index* inputs, const double* values, const double* covariance,
                                int count, double now, double stamp) override {
    return core_.addMeasurementBlock(inputs, values, covariance, count, now, stamp);
  }
  Rejection addControl(Index control, double value) override {
    return core_.addControl(control, value);
  }
  void reset() override { core_.reset(); }
  bool setPose(const std::array<int, 3>& indices, const std::array<double, 3>& xyYaw,
               const Eigen::Matrix3d& covariance) override {
    if constexpr (CanSetBelief<Filter>::value) {
      const Filter& filter = core_.filter();
      auto x = filter.state();
      auto P = filter.covariance();
      for (int r = 0; r < 3; ++r) {
        x(indices[r]) = xyYaw[static_cast<std::size_t>(r)];
        P.row(indices[r]).setZero();
        P.col(indices[r]).setZero();
      }
      for (int r = 0; r < 3; ++r) {
        for (int c = 0; c < 3; ++c) P(indices[r], indices[c]) = covariance(r, c);
      }
      core_.setBelief(x, P);  // the next period starts from it; the last estimate shows it
      return true;
    } else {
      static_cast<void>(indices);
      static_cast<void>(xyYaw);
      static_cast<void>(covariance);
      return false;
    }
  }

  EstimateRef lastEstimate() const override { return view(core_.lastEstimate()); }
  void fillStatistics(FusionStatistics& out) const override {
    core_.fillStatistics(out);
    out.repairs = core_.numericalRepairs();  // the filter's, known to its type only
  }
  const InputOptions& inputOptions(Index input) const override { return core_.inputOptions(input); }
  Index inputCount() const override { return core_.inputCount(); }
  bool timedOut(Index input) const override { return core_.timedOut(input); }
  double clock() const override { return core_.clock(); }
  const NisWindow& nis() const override { return core_.nis(); }
  const InnovationRecord& innovations() const override { return core_.innovations(); }
  std::uint64_t periodsDue(double now) const override { return core_.periodsDue(now); }
  double period() const override { return core_.period(); }
  std::uint64_t maxCatchUpPeriods() const override { return core_.maxCatchUpPeriods(); }
  double maxMeasurementLag() const override { return core_.maxMeasurementLag(); }

  std::unique_ptr<PeriodSmoother> makeSmoother() const override {
    return makePeriodSmoother(core_);
  }
  std::unique_ptr<PeriodSmoother> makeBatchSmoother() const override {
    return makeBatchPeriodSmoother(core_);
  }
  std::unique_ptr<LaggedSmoother> makeLaggedSmoother(std::size_t lagPeriods) const override {
    return makeLaggedSmootherOf(core_, lagPeriods);
  }

  std::string filterDescription() const override { return core_.filter().description(); }
  Index stateSize() const override { return core_.filter().stateSize(); }
  Index measurementSize() const override { return core_.filter().measurementSize(); }
  Index controlSize() const override { return core_.filter().controlSize(); }

  const Core& core() const { return core_; }

 private:
  static EstimateRef view(const typename Core::Estimate& e) {
    const Index n = e.state.size();
    return EstimateRef{e.time,
                       Eigen::Map<const Eigen::VectorXd>(e.state.data(), n),
                       Eigen::Map<const Eigen::MatrixXd>(e.covariance.data(), n, n),
                       e.presentInputs,
                       e.substitutedInputs,
                       e.stepFailed,
                       e.filterReset};
  }

  Core core_;
};

// The smoothers' factories of a core (period_smoother_of.hpp and its siblings), declared extern
// (PREFIX extern) in a header's node unit and instantiated (PREFIX empty) in its smoothers' unit
// (sf_filter/src/fusion_node_smoothers.cpp): they are replay options, but instantiated at the
// header's sizes with its model they were a third of a Kalman-type unit's compile time and
// memory (doc/build_cost.md, "The smoothers' unit").
#define SF_FILTER_SMOOTHER_INSTANCES(PREFIX, CORE)                                            \
  PREFIX template std::unique_ptr<PeriodSmoother> makePeriodSmoother<CORE>(const CORE&);      \
  PREFIX template std::unique_ptr<PeriodSmoother> makeBatchPeriodSmoother<CORE>(const CORE&); \
  PREFIX template std::unique_ptr<LaggedSmoother> makeLaggedSmootherOf<CORE>(const CORE&,     \
                                                                             std::size_t);

// The window filters have no model and no fixed sizes: their cores are the same in every
// header's node, and compiled once in the core library (src/core/window_filter_engines.cpp).
#ifndef SF_FILTER_INSTANTIATING_WINDOW_FILTER_ENGINES
extern template class FusionCore<estimation::MovingAverage>;
extern template class FusionCore<estimation::MovingMedian>;
extern template class FusionCore<estimation::ConfidenceWeightedAveraging>;
extern template class FusionEngineOf<estimation::MovingAverage>;
extern template class FusionEngineOf<estimation::MovingMedian>;
extern template class FusionEngineOf<estimation::ConfidenceWeightedAveraging>;
#endif

}  // namespace sf_filter
