// The ROS-free heart of a fusion node: it is fed timestamped measurement and control events
// and the passing of time, aligns the inputs per estimation period, runs the estimator and
// hands out one estimate per period. The ROS node and the offline bag replay are thin
// adapters around it, so both behave identically and it is unit-tested without a master.
#pragma once

#include <chrono>
#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <sf_estimation/errors.hpp>
#include <sf_estimation/measurement.hpp>

#include "sf_filter/core/input_counters.hpp"
#include "sf_filter/core/period_average.hpp"
#include "sf_filter/core/period_schedule.hpp"

namespace sf_filter {

using estimation::Index;

/// What advanceTo() observed about the clock.
enum class ClockEvent { Normal, Started, JumpedBackwards, SkippedGap };

template <class Filter>
class FusionCore {
 public:
  static constexpr int N = Filter::StateSize;
  static constexpr int M = Filter::MeasurementSize;
  static constexpr int L = Filter::ControlSize;

  struct Estimate {
    double time = 0.0;  ///< end of the estimated period
    estimation::Vector<N> state;
    estimation::Matrix<N, N> covariance;
    Index presentInputs = 0;  ///< inputs that had at least one value in the period
  };

  struct Options {
    double period = 0.1;  ///< estimation period [s]
    /// A forward clock jump longer than this many periods is skipped (one estimate) instead
    /// of estimating every missed period, so a stalled clock never floods the output.
    std::uint64_t maxCatchUpPeriods = 100;
  };

  FusionCore(Filter filter, const Options& options)
      : filter_(std::move(filter)),
        initial_(filter_),
        options_(options),
        schedule_(options.period),
        inputs_(static_cast<std::size_t>(filter_.measurementSize())),
        counters_(inputs_.size()),
        measurement_(filter_.measurementSize()),
        control_(estimation::Vector<L>::Zero(filter_.controlSize())) {
    if (!(options.period > 0.0) || !std::isfinite(options.period)) {
      throw estimation::ParameterError("estimation period must be positive and finite");
    }
    fillEstimate(0.0, 0);
  }

  /// Runs every period that ended at or before `now`, calling onEstimate(const Estimate&)
  /// for each. Time running backwards (a restarted bag, a reset simulation clock) resets
  /// the filter and restarts the schedule at `now`.
  template <class OnEstimate>
  ClockEvent advanceTo(double now, OnEstimate&& onEstimate) {
    if (!schedule_.started()) {
      schedule_.start(now);
      return ClockEvent::Started;
    }
    if (now < schedule_.currentStart()) {
      reset();
      schedule_.start(now);
      ++clockResets_;
      return ClockEvent::JumpedBackwards;
    }
    const std::uint64_t due = schedule_.periodsDue(now);
    if (due > options_.maxCatchUpPeriods) {
      estimatePeriod(schedule_.currentEnd());
      onEstimate(last_);
      schedule_.skipTo(now);
      return ClockEvent::SkippedGap;
    }
    for (std::uint64_t k = 0; k < due; ++k) {
      estimatePeriod(schedule_.currentEnd());
      schedule_.advance();
      onEstimate(last_);
    }
    return ClockEvent::Normal;
  }

  /// A measurement of input `input` received at `now`, with the variance the message carried
  /// (if any). `stamp` (NaN when the message has no header) must not run backwards per input.
  Rejection addMeasurement(Index input, double now, double value,
                           std::optional<double> variance = std::nullopt,
                           double stamp = std::numeric_limits<double>::quiet_NaN()) {
    if (input < 0 || input >= static_cast<Index>(inputs_.size())) return Rejection::UnknownInput;
    InputCounters& c = counters_[static_cast<std::size_t>(input)];
    ++c.received;
    c.lastArrival = now;
    if (!std::isfinite(value)) {
      ++c.nonFinite;
      return Rejection::NonFinite;
    }
    if (variance && !(std::isfinite(*variance) && *variance > 0.0)) {
      ++c.badVariance;
      return Rejection::BadVariance;
    }
    if (!std::isnan(stamp)) {
      if (stamp < c.lastStamp) {
        ++c.outOfOrder;
        return Rejection::OutOfOrder;
      }
      c.lastStamp = stamp;
    }
    inputs_[static_cast<std::size_t>(input)].add(value, variance);
    return Rejection::None;
  }

  /// A control value; the latest one of each control is used by the next estimate.
  Rejection addControl(Index control, double value) {
    if (control < 0 || control >= control_.size()) return Rejection::UnknownInput;
    if (!std::isfinite(value)) {
      ++controlNonFinite_;
      return Rejection::NonFinite;
    }
    control_(control) = value;
    return Rejection::None;
  }

  /// Back to the initial belief; pending values and the control are discarded.
  void reset() {
    filter_ = initial_;
    for (auto& input : inputs_) input.clear();
    for (auto& c : counters_) c.lastStamp = -std::numeric_limits<double>::infinity();
    control_.setZero();
    fillEstimate(last_.time, 0);
  }

  const Estimate& lastEstimate() const { return last_; }
  const Filter& filter() const { return filter_; }
  const InputCounters& counters(Index input) const {
    return counters_[static_cast<std::size_t>(input)];
  }
  Index inputCount() const { return static_cast<Index>(inputs_.size()); }
  std::uint64_t clockResets() const { return clockResets_; }
  std::uint64_t estimationFailures() const { return estimationFailures_; }
  const std::string& lastFailure() const { return lastFailure_; }
  std::uint64_t controlNonFinite() const { return controlNonFinite_; }
  double period() const { return options_.period; }
  /// Wall time spent in the estimator's steps, and their number (failed steps excluded).
  double estimatorSeconds() const { return estimatorSeconds_; }
  std::uint64_t estimateCount() const { return estimateCount_; }

 private:
  void estimatePeriod(double end) {
    Index present = 0;
    for (Index i = 0; i < measurement_.size(); ++i) {
      PeriodAverage& in = inputs_[static_cast<std::size_t>(i)];
      measurement_.available(i) = !in.empty();
      measurement_.varianceGiven(i) = in.hasVariance();
      if (!in.empty()) {
        ++present;
        measurement_.value(i) = in.mean();
        measurement_.variance(i) = in.hasVariance() ? in.meanVariance() : 0.0;
        counters_[static_cast<std::size_t>(i)].used += in.count();
      }
      in.clear();
    }
    const auto begin = std::chrono::steady_clock::now();
    try {
      filter_.setControl(control_);
      filter_.estimate(measurement_);
      estimatorSeconds_ += std::chrono::duration<double>(std::chrono::steady_clock::now() - begin).count();
      ++estimateCount_;
    } catch (const estimation::EstimationError& e) {
      // The filter rejected the step and kept its belief; a numerical failure is not
      // recoverable by waiting, so the filter restarts from its initial belief.
      ++estimationFailures_;
      lastFailure_ = e.what();
      filter_ = initial_;
    }
    fillEstimate(end, present);
  }

  void fillEstimate(double time, Index present) {
    last_.time = time;
    last_.state = filter_.state();
    last_.covariance = filter_.covariance();
    last_.presentInputs = present;
  }

  Filter filter_;
  Filter initial_;
  Options options_;
  PeriodSchedule schedule_;
  std::vector<PeriodAverage> inputs_;
  std::vector<InputCounters> counters_;
  estimation::Measurement<M> measurement_;
  estimation::Vector<L> control_;
  Estimate last_;
  double estimatorSeconds_ = 0.0;
  std::uint64_t estimateCount_ = 0;
  std::uint64_t clockResets_ = 0;
  std::uint64_t estimationFailures_ = 0;
  std::uint64_t controlNonFinite_ = 0;
  std::string lastFailure_;
};

}  // namespace sf_filter
