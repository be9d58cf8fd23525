// The ROS-free heart of a fusion node: it is fed timestamped measurement and control events
// and the passing of time, aligns the inputs per estimation period, runs the estimator and
// hands out one estimate per period. The ROS node and the offline bag replay are thin
// adapters around it, so both behave identically and it is unit-tested without a master.
//
// Per input (Options::inputs, doc/alignment_policies.md): the alignment policy (AVERAGE by
// default, LAST, SAMPLED, HOLD, FILL), an optional Mahalanobis gate, and alignment by header
// stamp instead of arrival time.
//
// Periods and the measurement lag. Period k covers [start + (k-1) T, start + k T). A value
// aligned by arrival time belongs to the period containing its arrival, one aligned by stamp
// to the period containing its stamp, so a value delayed in transport still counts for the
// period it was measured in. To wait for such values, period k is estimated only once the
// clock reaches its end plus the maximum measurement lag (Options::maxMeasurementLag; 0 by
// default, which is the thesis's node: estimate at the period's end). Until then it stays
// open; the open periods live in a ring of at least floor(lag / T) + 3 slots (a power of
// two) allocated at construction. A stamped value whose period has already been estimated is
// dropped and counted (InputCounters::late). The estimate of period k still carries the time of its
// end, so with a lag the estimates come out `lag` late but refer to the right instants. Controls
// are taken by arrival: period k uses the latest control received before its end.
//
// Clock stalls (issue 15 R3). A value is never sent before it is stamped: when the stamps of
// two inputs run ahead of the clock's reading (one input alone may only have a fast clock), the
// clock stands still and the stamps stand in for it until it moves (only with a finite
// maxFutureStamp, i.e. stamps on the clock's time base). A stamped value then goes into the
// period of its stamp, an unstamped value or a control into the period of the newest stamp;
// the ring keeps Options::maxQueuedPeriods periods ahead of the clock for them. When the clock
// jumps, crossGap() estimates every period holding queued values one by one, also beyond
// maxCatchUpPeriods, as the offline replay (whose clock is the recorded time) does, and skips
// only the rest of the gap. A stamp more than maxFutureStamp
// ahead of the clock and of every other input's stamps sent while it stood still is dropped:
// an input's own stamps never vouch for a stalled clock. Once the clock moves it is the time.
//
// Faults (doc/reliability.md): a value is checked on arrival - finite, its variance finite and
// positive and at most kMaxVariance (1e100), inside the input's plausible range, its stamp not
// older than, equal to or too far ahead of the previous one / the clock - and dropped and counted
// (InputCounters) otherwise, so it never reaches the filter. An input with a timeout that has
// accepted no value for longer is timed out: missing every period, and a HOLD or FILL input then
// substitutes nothing and forgets its history; the first value back is used as usual. Accepted
// means used: only a value that reaches the filter keeps its input alive - one dropped on arrival,
// too late for its period or refused by the gate does not (InputCounters::lastAccepted is set
// when the value's period is estimated, to the value's arrival). The normalised
// innovation squared of each period (nis_window.hpp) tells whether the filter is consistent.
// A step the estimator rejects leaves the filter unchanged (the library's guarantee): the
// period's estimate is the last good one (a Kalman-type filter's covariance inflated by Q),
// flagged and counted; only
// Options::maxConsecutiveFailures rejected steps in a row restart the filter from its initial
// belief (filterResets()).
//
// First readings (Options::initialFromInputs, INITIAL_STATE_FROM_INPUTS). A state variable the
// header cannot know in advance (a velocity: the recording may start in motion) takes the
// aligned value of its input in the first period that has one, set into the belief before that
// period's step with its covariance kept, so that the step predicts with it and weighs the
// reading once; the gates of that period have already been checked against the initial state.
// Armed again by every reset and filter restart. Filters without setBelief (the averaging
// methods) start from the initial state as before. A sampled belief (the particle filter,
// kSampledBelief) takes the reading's own variance for such a variable instead of keeping P:
// particles spread by P0 around a reading far more accurate than P0 would leave a few of them
// with all the weight in the first step.
#pragma once

#include <algorithm>
#include <chrono>
#include <optional>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include <sf_estimation/errors.hpp>
#include <sf_estimation/measurement.hpp>
#include <sf_estimation/measurement_prediction.hpp>
#include <sf_estimation/numerical_repairs.hpp>

#include "sf_filter/core/detected.hpp"
#include "sf_filter/core/fusion_core_base.hpp"
#include "sf_filter/core/fusion_core_options.hpp"
#include "sf_filter/core/fusion_engine.hpp"

namespace sf_filter {

/// A filter's setBelief(x, P) (the Kalman filter family): a rejected step can then add Q, and
/// a first reading can replace a state's start.
template <class F>
using SetBeliefCall = decltype(std::declval<F&>().setBelief(std::declval<const F&>().state(),
                                                            std::declval<const F&>().covariance()));
/// setBelief(x, P + Q): the filter also exposes its process noise Q.
template <class F>
using InflateByProcessNoiseCall = decltype(std::declval<F&>().setBelief(
    std::declval<const F&>().state(),
    std::declval<const F&>().covariance() + std::declval<const F&>().processNoise()));

/// Whether the filter can replace its belief (setBelief: the Kalman filter family).
template <class F>
using CanSetBelief = IsDetected<SetBeliefCall, F>;
/// Whether a rejected step can add the filter's Q to its kept belief.
template <class F>
using CanInflateByProcessNoise = IsDetected<InflateByProcessNoiseCall, F>;

/// Whether the filter's belief is a sample (kSampledBelief: the particle filter).
template <class F, class = void>
struct HasSampledBelief : std::false_type {};
template <class F>
struct HasSampledBelief<F, std::enable_if_t<F::kSampledBelief>> : std::true_type {};

/// The fusion core of one filter type: FusionCoreBase (compiled once) does the scheduling,
/// checks and alignment; this template adds only the filter and its fixed-size step.
template <class Filter>
class FusionCore : public FusionCoreBase {
 public:
  static constexpr int N = Filter::StateSize;
  static constexpr int M = Filter::MeasurementSize;
  static constexpr int L = Filter::ControlSize;
  /// The filter gives its predicted measurement (KF, EKF, UKF, PF): gates and FILL possible.
  static constexpr bool kCanPredict = estimation::HasMeasurementPrediction<Filter>::value;

  struct Estimate {
    double time = 0.0;  ///< end of the estimated period
    estimation::Vector<N> state;
    estimation::Matrix<N, N> covariance;
    Index presentInputs = 0;      ///< inputs with a measured value (not gated) in the period
    Index substitutedInputs = 0;  ///< inputs given a HOLD or FILL substitute
    /// The estimator rejected this period's step: state and covariance are the last good
    /// estimate (the filter is unchanged by a rejected step; a Kalman-type filter's covariance
    /// is inflated by Q), or the initial belief when `filterReset` is set too.
    bool stepFailed = false;
    /// This period's failure was the Options::maxConsecutiveFailures-th in a row: the filter
    /// restarted from its initial belief, which state and covariance are.
    bool filterReset = false;
  };

  using Options = FusionCoreOptions;

  FusionCore(Filter filter, const Options& options)
      : FusionCoreBase(options, filter.measurementSize(), filter.controlSize(), kCanPredict),
        filter_(std::move(filter)),
        initial_(filter_),
        measurement_(filter_.measurementSize()),
        prediction_(filter_.measurementSize()),
        measured_(filter_.measurementSize()),
        control_(estimation::Vector<L>::Zero(filter_.controlSize())) {
    for (const Options::FirstReading& f : options.initialFromInputs) {
      if (f.state < 0 || f.state >= static_cast<int>(filter_.state().size())) {
        throw estimation::ParameterError(
            "initial state from inputs: state " + std::to_string(f.state) + " is not one of the " +
            std::to_string(filter_.state().size()) + " state variables");
      }
    }
    armFirstReadings();
    fillEstimate(0.0);
  }

  /// Runs every period that ended at or before `now` - lag, calling
  /// onEstimate(const Estimate&) for each. Time running backwards (a restarted bag, a reset
  /// simulation clock) resets the filter and restarts the schedule at `now`.
  template <class OnEstimate>
  ClockEvent advanceTo(double now, OnEstimate&& onEstimate) {
    const ClockStep step = readClock(now);
    if (step.event == ClockEvent::JumpedBackwards) reset();
    if (step.event == ClockEvent::SkippedGap) {
      return crossGap(step.due, maxCatchUpPeriods(), onEstimate);
    }
    for (std::uint64_t k = 0; k < step.due && step.event == ClockEvent::Normal; ++k) {
      estimatePeriod();
      onEstimate(last_);
    }
    return step.event;
  }

  /// advanceTo() for a clock that ran continuously to `now` (the offline replay, whose clock is
  /// the recorded time of the next message, emulates the online node's timer running through a
  /// gap between messages): every due period is estimated, up to `maxPeriods` (at most
  /// kMaxCatchUpLimit) instead of maxCatchUpPeriods(); a longer gap is crossed as advanceTo()
  /// crosses a jump (crossGap), never by estimating millions of empty periods.
  template <class OnEstimate>
  ClockEvent runTo(double now, std::uint64_t maxPeriods, OnEstimate&& onEstimate) {
    const ClockStep step = readClock(now);
    if (step.event == ClockEvent::JumpedBackwards) reset();
    if (step.event == ClockEvent::JumpedBackwards || step.event == ClockEvent::Started) {
      return step.event;
    }
    return crossGap(step.due, std::min(maxPeriods, kMaxCatchUpLimit), onEstimate);
  }

  /// Crosses a forward gap to `now` at the cost of one period, whatever its length: estimates
  /// the current period (with what it holds, a prediction if nothing), calls onEstimate once,
  /// and moves the schedule on by whole periods (keeping the phase) so that now - lag lies in
  /// the current one; the periods in between are not estimated (counted by skippedPeriods()).
  /// Periods holding values that arrived ahead of the clock (queuedAhead()) are estimated
  /// first, one by one, as advanceTo() does. advanceTo() crosses a jump of more than
  /// maxCatchUpPeriods periods so; an adapter that steps through a gap itself (the offline
  /// replay emulating a running clock) calls it for a gap it must not step through, e.g. one of
  /// more than kMaxCatchUpLimit periods. Nothing happens (Normal) when no period is due, or
  /// before the schedule started.
  template <class OnEstimate>
  ClockEvent skipGap(double now, OnEstimate&& onEstimate) {
    if (!scheduleStarted()) return advanceTo(now, onEstimate);
    const std::uint64_t due = periodsDue(now);
    if (due == 0) return ClockEvent::Normal;
    setClock(now);
    return crossGap(due, 0, onEstimate);
  }

  /// Back to the initial belief; pending values, the alignment histories and the control
  /// are discarded.
  void reset() {
    restartFilter();
    clearInputs();
    control_.setZero();
    fillEstimate(last_.time);
  }

  /// Replaces the filter's belief (set_pose); the last estimate shows it at once. Only for
  /// filters with setBelief (the Kalman filter family, and the particle filter, which draws its
  /// particles anew).
  template <class State, class Covariance>
  void setBelief(const State& x, const Covariance& P) {
    filter_.setBelief(x, P);
    last_.state = filter_.state();
    last_.covariance = filter_.covariance();
  }

  const Estimate& lastEstimate() const { return last_; }
  /// The measurement given to the filter in the last estimated period (its present rows after
  /// gating and substitution, its variances and covariances): the batch smoother's record
  /// (batch_period_smoother_of.hpp). Meaningless after a failed step or a restart.
  const estimation::Measurement<M>& lastMeasurement() const { return measurement_; }
  const Filter& filter() const { return filter_; }
  /// What the filter repaired instead of failing (numerical_repairs.hpp), since the core was
  /// made: kept across filter restarts. All zero for methods that repair nothing.
  estimation::NumericalRepairs numericalRepairs() const {
    estimation::NumericalRepairs total = repairsBeforeRestart_;
    if constexpr (estimation::HasNumericalRepairs<Filter>::value) {
      total += filter_.numericalRepairs();
    }
    return total;
  }

 private:
  /// The filter's predicted measurement of the period, computed once when first asked for.
  class LazyPrediction final : public Prediction {
   public:
    explicit LazyPrediction(FusionCore& core) : core_(core) {}
    double gateDistance(Index input, double value, std::optional<double> variance) override {
      return estimation::squaredMahalanobisDistance(get(), input, value, variance);
    }
    double mean(Index input) override { return get().mean(input); }
    /// The filter's belief changed: predict again when next asked.
    void forget() { predicted_ = false; }
    const estimation::MeasurementPrediction<M>& get() {
      if constexpr (kCanPredict) {
        if (!predicted_) core_.filter_.predictMeasurement(core_.prediction_);
        predicted_ = true;
      }
      return core_.prediction_;
    }

   private:
    FusionCore& core_;
    bool predicted_ = false;
  };

  /// Crosses a gap of `due` periods to the clock's reading: the one rule of advanceTo(),
  /// runTo() and skipGap(). The periods that hold values queued ahead of the clock (up to the
  /// ring's capacity, Options::maxQueuedPeriods) are estimated one by one, as a running clock
  /// would have; the rest of the gap is estimated period by period if it is no longer than
  /// `limit` periods, and otherwise crossed with one estimate, the periods after it skipped.
  template <class OnEstimate>
  ClockEvent crossGap(std::uint64_t due, std::uint64_t limit, OnEstimate& onEstimate) {
    if (due == 0) return ClockEvent::Normal;
    const std::uint64_t queued = std::min(queuedAhead(), due - 1);
    for (std::uint64_t k = 0; k < queued; ++k) {
      estimatePeriod();
      onEstimate(last_);
    }
    const std::uint64_t rest = due - queued;
    if (rest <= limit) {
      for (std::uint64_t k = 0; k < rest; ++k) {
        estimatePeriod();
        onEstimate(last_);
      }
      return ClockEvent::Normal;
    }
    estimatePeriod();
    onEstimate(last_);
    skipPeriods(rest);
    return ClockEvent::SkippedGap;
  }

  /// Back to the initial belief, keeping the count of the repairs made so far.
  void restartFilter() {
    repairsBeforeRestart_ = numericalRepairs();
    filter_ = initial_;
    armFirstReadings();
  }

  void armFirstReadings() {
    firstReadingsDue_.assign(options().initialFromInputs.size(), CanSetBelief<Filter>::value);
    firstReadingsLeft_ = CanSetBelief<Filter>::value ? firstReadingsDue_.size() : 0;
  }

  /// Options::initialFromInputs: the state variables whose input has its first measured value
  /// in this period take it, before the step (which then predicts with it and weighs the
  /// reading once, the covariance being kept). True when the belief changed.
  bool takeFirstReadings() {
    if constexpr (CanSetBelief<Filter>::value) {
      if (firstReadingsLeft_ == 0) return false;
      bool changed = false;
      estimation::Vector<N> x = filter_.state();
      estimation::Matrix<N, N> P = filter_.covariance();
      for (std::size_t k = 0; k < firstReadingsDue_.size(); ++k) {
        const Options::FirstReading& f = options().initialFromInputs[k];
        const PeriodEntry& e = periodEntries()[static_cast<std::size_t>(f.input)];
        if (!firstReadingsDue_[k] || !e.measured) continue;
        x(f.state) = e.value;
        if constexpr (HasSampledBelief<Filter>::value) {
          P.row(f.state).setZero();
          P.col(f.state).setZero();
          P(f.state, f.state) = e.variance.value_or(filter_.measurementNoise()(f.input, f.input));
        }
        firstReadingsDue_[k] = false;
        --firstReadingsLeft_;
        changed = true;
      }
      if (changed) filter_.setBelief(x, P);
      return changed;
    } else {
      return false;
    }
  }

  /// Aligns the current period's inputs, estimates, and moves the schedule on.
  void estimatePeriod() {
    const double end = periodEnd();
    bool failed = false, restarted = false;
    beginPeriod();
    control_ = controls();
    try {
      filter_.setControl(control_);
      LazyPrediction prediction(*this);
      alignInputs(prediction);
      if (takeFirstReadings()) prediction.forget();
      const auto& entries = periodEntries();
      for (Index i = 0; i < filter_.measurementSize(); ++i) {
        const auto& e = entries[static_cast<std::size_t>(i)];
        measurement_.available(i) = e.available;
        measurement_.varianceGiven(i) = e.available && e.variance.has_value();
        measurement_.value(i) = e.available ? e.value : 0.0;
        measurement_.variance(i) = e.available && e.variance ? *e.variance : 0.0;
        measured_.available(i) = e.measured;
      }
      if (covariancesGiven_) measurement_.covarianceGiven.setConstant(false);
      covariancesGiven_ = !periodCovariances().empty();
      for (const PeriodCovariance& c : periodCovariances()) {
        measurement_.covarianceGiven(c.a, c.b) = measurement_.covarianceGiven(c.b, c.a) = true;
        measurement_.covariance(c.a, c.b) = measurement_.covariance(c.b, c.a) = c.covariance;
      }
      if (nisWanted()) {
        // The check must never change the estimate: a prediction it alone asked for and that
        // fails only skips the period's NIS (the step itself then decides about a failure).
        try {
          addNis(prediction.get());
        } catch (const estimation::EstimationError&) {
          countNisFailure();
        }
      }
      const auto begin = std::chrono::steady_clock::now();
      filter_.estimate(measurement_);
      recordStep(std::chrono::duration<double>(std::chrono::steady_clock::now() - begin).count());
    } catch (const estimation::EstimationError& e) {
      // The filter rejected the step and kept its belief, which stays the estimate. A fault
      // that persists for maxConsecutiveFailures periods is not mended by waiting: only then
      // does the filter restart from its initial belief.
      failed = true;
      restarted = recordFailure(e.what());
      if (restarted) {
        restartFilter();
      } else {
        inflateByProcessNoise();
      }
    }
    finishPeriod();
    fillEstimate(end, failed, restarted);
  }

  /// After a rejected step: the period passed without a time update, so a Kalman-type
  /// filter's covariance grows by Q (its state is kept). Other filters keep their belief as it
  /// is. Only on the failure path (the belief check may allocate); a sum the filter refuses
  /// (beyond the maximum covariance entry) leaves the belief unchanged.
  void inflateByProcessNoise() {
    if constexpr (CanInflateByProcessNoise<Filter>::value) {
      try {
        filter_.setBelief(filter_.state(), filter_.covariance() + filter_.processNoise());
      } catch (const estimation::EstimationError&) {
      }
    }
  }

  /// The NIS and log det S of the period's measured (not substituted) entries, and each
  /// measured input's own NIS, into the innovation record. Throws NumericalError when the
  /// innovation covariance is not positive definite.
  void addNis(const estimation::MeasurementPrediction<M>& prediction) {
    for (Index i = 0; i < filter_.measurementSize(); ++i) {
      measured_.value(i) = measurement_.value(i);
      measured_.varianceGiven(i) = measurement_.varianceGiven(i);
      measured_.variance(i) = measurement_.variance(i);
    }
    measured_.covarianceGiven = measurement_.covarianceGiven;
    measured_.covariance = measurement_.covariance;
    const estimation::InnovationLikelihood l =
        estimation::innovationLikelihood(prediction, measured_);
    FusionCoreBase::addNis(l.squaredDistance, static_cast<int>(measured_.availableCount()),
                           l.logDeterminant);
    for (Index i = 0; i < filter_.measurementSize(); ++i) {
      if (!measured_.available(i)) continue;
      addInputNis(i, estimation::squaredMahalanobisDistance(
                         prediction, i, measured_.value(i),
                         measured_.varianceGiven(i) ? std::optional<double>(measured_.variance(i))
                                                    : std::nullopt));
    }
  }

  void fillEstimate(double time, bool failed = false, bool reset = false) {
    last_.time = time;
    last_.stepFailed = failed;
    last_.filterReset = reset;
    last_.state = filter_.state();
    last_.covariance = filter_.covariance();
    last_.presentInputs = presentInputs();
    last_.substitutedInputs = substitutedInputs();
  }

  Filter filter_;
  Filter initial_;
  estimation::Measurement<M> measurement_;
  estimation::MeasurementPrediction<M> prediction_;
  estimation::Measurement<M> measured_;  ///< the period's measured entries, for the NIS
  bool covariancesGiven_ = false;        ///< measurement_ holds covariances to clear
  /// Per Options::initialFromInputs entry: its state still waits for the input's first value.
  std::vector<bool> firstReadingsDue_;
  std::size_t firstReadingsLeft_ = 0;  ///< entries of firstReadingsDue_ still true
  estimation::Vector<L> control_;      ///< the controls in force, in the filter's type
  Estimate last_;
  estimation::NumericalRepairs repairsBeforeRestart_;  ///< of the filters before restarts
};

}  // namespace sf_filter
