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
#pragma once

#include <chrono>
#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include <sf_estimation/errors.hpp>
#include <sf_estimation/measurement.hpp>
#include <sf_estimation/measurement_prediction.hpp>
#include <sf_estimation/numerical_repairs.hpp>

#include "sf_filter/core/alignment/input_aligner.hpp"
#include "sf_filter/core/alignment/input_period.hpp"
#include "sf_filter/core/input_counters.hpp"
#include "sf_filter/core/input_options.hpp"
#include "sf_filter/core/nis_window.hpp"
#include "sf_filter/core/period_schedule.hpp"

namespace sf_filter {

using estimation::Index;

/// Whether the filter exposes its process noise Q and a way to replace its belief (the
/// Kalman-type filters: setBelief, processNoise), so that a rejected step can add Q.
template <class F, class = void>
struct CanInflateByProcessNoise : std::false_type {};
template <class F>
struct CanInflateByProcessNoise<
    F, std::void_t<decltype(std::declval<F&>().setBelief(
           std::declval<const F&>().state(),
           std::declval<const F&>().covariance() + std::declval<const F&>().processNoise()))>>
    : std::true_type {};

/// What advanceTo() observed about the clock.
enum class ClockEvent { Normal, Started, JumpedBackwards, SkippedGap };

template <class Filter>
class FusionCore {
 public:
  static constexpr int N = Filter::StateSize;
  static constexpr int M = Filter::MeasurementSize;
  static constexpr int L = Filter::ControlSize;
  /// The filter gives its predicted measurement (KF, EKF, UKF, PF): gates and FILL possible.
  static constexpr bool kCanPredict = estimation::HasMeasurementPrediction<Filter>::value;
  /// The largest variance a measurement may carry (sf_filter::kMaxVariance, 1e100).
  static constexpr double kMaxVariance = sf_filter::kMaxVariance;

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

  /// Bounds of Options::period [s]: 0.1 ms .. 1 h (a period outside them is a unit mistake:
  /// 1e-6 meant as ms, 50 meant as ms, and would load a core or never estimate).
  static constexpr double kMinPeriod = 1e-4;
  static constexpr double kMaxPeriod = 3600.0;
  /// Upper bound of Options::maxCatchUpPeriods: one advanceTo() never estimates more periods.
  static constexpr std::uint64_t kMaxCatchUpLimit = 100000;

  struct Options {
    double period = 0.1;  ///< estimation period [s], kMinPeriod .. kMaxPeriod
    /// A forward clock jump longer than this many periods is skipped (one estimate) instead
    /// of estimating every missed period, so a stalled clock never floods the output.
    /// 1 .. kMaxCatchUpLimit.
    std::uint64_t maxCatchUpPeriods = 100;
    /// One entry per input, or none: every input AVERAGE, by arrival time, without gate.
    std::vector<InputOptions> inputs;
    /// How long after its end a period stays open for stamped values [s] (see above).
    double maxMeasurementLag = 0.0;
    /// A stamp more than this ahead of the clock reading at arrival is dropped [s] (a sensor
    /// clock far ahead would otherwise block its input: every later stamp looks older).
    /// Infinite: no check.
    double maxFutureStamp = std::numeric_limits<double>::infinity();
    /// Periods over which the NIS is averaged (nis_window.hpp); 0: not computed. Costs one
    /// measurement prediction per period when no gate or FILL needs it anyway.
    std::size_t nisWindow = 0;
    /// A step the estimator rejects (EstimationError) leaves the filter as it was: the period's
    /// estimate is the last good one, flagged Estimate::stepFailed (for the Kalman-type
    /// filters with its covariance inflated by Q: the period passed without a time update). Only
    /// after this many rejected steps in a row does the filter restart from its initial belief (a
    /// fault that waiting does not mend); counted by filterResets(). At least 1 (1: restart at
    /// once).
    std::uint64_t maxConsecutiveFailures = 10;
  };

  FusionCore(Filter filter, const Options& options)
      : filter_(std::move(filter)),
        initial_(filter_),
        options_(checked(options, filter_.measurementSize())),
        schedule_(options.period),
        counters_(static_cast<std::size_t>(filter_.measurementSize())),
        measurement_(filter_.measurementSize()),
        prediction_(filter_.measurementSize()),
        measured_(filter_.measurementSize()),
        control_(estimation::Vector<L>::Zero(filter_.controlSize())),
        nis_(kCanPredict ? options_.nisWindow : 0) {
    const Index m = filter_.measurementSize();
    for (Index i = 0; i < m; ++i) aligners_.emplace_back(inputOptions(i).alignment);
    // A power of two, so that the slot of a period is a bit mask away.
    const auto needed = static_cast<std::size_t>(
        std::floor(options_.maxMeasurementLag / options_.period + 1e-9) + 3);
    std::size_t slots = 1;
    while (slots < needed) slots *= 2;
    OpenPeriod empty;
    empty.control = estimation::Vector<L>::Zero(filter_.controlSize());
    empty.controlSet = estimation::Mask<L>::Constant(filter_.controlSize(), false);
    for (Index i = 0; i < m; ++i) {
      empty.inputs.emplace_back(inputOptions(i).alignment.historyLength());
    }
    open_.assign(slots, empty);
    openWindow();
    fillEstimate(0.0, 0, 0);
  }

  /// Runs every period that ended at or before `now` - lag, calling
  /// onEstimate(const Estimate&) for each. Time running backwards (a restarted bag, a reset
  /// simulation clock) resets the filter and restarts the schedule at `now`.
  template <class OnEstimate>
  ClockEvent advanceTo(double now, OnEstimate&& onEstimate) {
    clock_ = now;
    const double lag = options_.maxMeasurementLag;
    if (!schedule_.started()) {
      restartSchedule(now);
      return ClockEvent::Started;
    }
    if (schedule_.before(now - lag)) {
      reset();
      restartSchedule(now);
      ++clockResets_;
      return ClockEvent::JumpedBackwards;
    }
    const std::uint64_t due = schedule_.periodsDue(now - lag);
    if (due > options_.maxCatchUpPeriods) return skipGap(now, onEstimate);
    for (std::uint64_t k = 0; k < due; ++k) {
      estimatePeriod();
      onEstimate(last_);
    }
    return ClockEvent::Normal;
  }

  /// Crosses a forward gap to `now` at the cost of one period, whatever its length: estimates
  /// the current period (with what it holds, a prediction if nothing), calls onEstimate once,
  /// and moves the schedule on by whole periods (keeping the phase) so that now - lag lies in
  /// the current one; the periods in between are not estimated (counted by skippedPeriods()).
  /// advanceTo() does this for a jump of more than maxCatchUpPeriods periods; an adapter that
  /// steps through a gap itself (the offline replay emulating a running clock) calls it for a
  /// gap it must not step through, e.g. one of more than kMaxCatchUpLimit periods. Nothing
  /// happens (Normal) when no period is due, or before the schedule started.
  template <class OnEstimate>
  ClockEvent skipGap(double now, OnEstimate&& onEstimate) {
    if (!schedule_.started()) return advanceTo(now, onEstimate);
    const double lag = options_.maxMeasurementLag;
    const std::uint64_t due = schedule_.periodsDue(now - lag);
    if (due == 0) return ClockEvent::Normal;
    clock_ = now;
    estimatePeriod();
    onEstimate(last_);
    skippedPeriods_ += due - 1;
    ++skippedGaps_;
    schedule_.skipTo(now - lag);
    openWindow();
    return ClockEvent::SkippedGap;
  }

  /// Periods that have ended by `now` (minus the lag) and are not estimated yet: what
  /// advanceTo(now) would estimate, or skip when more than maxCatchUpPeriods().
  std::uint64_t periodsDue(double now) const {
    return schedule_.periodsDue(now - options_.maxMeasurementLag);
  }

  /// A measurement of input `input` received at `now`, with the variance the message carried
  /// (if any). `stamp` (NaN when the message has no header) must not run backwards per input;
  /// it places the value in its period if the input is aligned by stamp.
  Rejection addMeasurement(Index input, double now, double value,
                           std::optional<double> variance = std::nullopt,
                           double stamp = std::numeric_limits<double>::quiet_NaN()) {
    if (input < 0 || input >= inputCount()) return Rejection::UnknownInput;
    InputCounters& c = counters_[static_cast<std::size_t>(input)];
    const InputOptions& o = inputOptions(input);
    ++c.received;
    c.lastArrival = now;
    if (!std::isfinite(value)) {
      ++c.nonFinite;
      return Rejection::NonFinite;
    }
    // Beyond kMaxVariance a variance says "no information" and the period's sum of variances
    // could overflow: refused like a non-finite one.
    if (variance && !(*variance > 0.0 && *variance <= kMaxVariance)) {
      ++c.badVariance;
      return Rejection::BadVariance;
    }
    if (!o.inRange(value)) {
      ++c.outOfRange;
      return Rejection::OutOfRange;
    }
    if (stamp == 0.0) stamp = std::numeric_limits<double>::quiet_NaN();  // ROS: not set
    if (!std::isnan(stamp)) {
      if (stamp < c.lastStamp) {
        ++c.outOfOrder;
        return Rejection::OutOfOrder;
      }
      if (stamp == c.lastStamp) {
        ++c.duplicate;
        return Rejection::DuplicateStamp;
      }
      if (stamp > now + options_.maxFutureStamp) {
        ++c.future;
        return Rejection::FutureStamp;
      }
      c.lastStamp = stamp;
    }
    const bool byStamp = o.alignByStamp && !std::isnan(stamp);
    const double time = byStamp ? stamp : now;
    bool estimated = false, beyond = false;
    const std::uint64_t k = openPeriodOf(time, estimated, beyond);
    if (byStamp && estimated) {
      ++c.late;
      return Rejection::TooLate;
    }
    if (byStamp && beyond) ++c.aheadOfClock;
    slotOf(k).inputs[static_cast<std::size_t>(input)].add(value, variance, time, now);
    return Rejection::None;
  }

  /// A control value, received at the clock's last reading; a period uses the latest value of
  /// each control received before its end.
  Rejection addControl(Index control, double value) {
    if (control < 0 || control >= control_.size()) return Rejection::UnknownInput;
    if (!std::isfinite(value)) {
      ++controlNonFinite_;
      return Rejection::NonFinite;
    }
    bool estimated = false, beyond = false;
    OpenPeriod& slot = slotOf(openPeriodOf(clock_, estimated, beyond));
    slot.control(control) = value;
    slot.controlSet(control) = true;
    return Rejection::None;
  }

  /// Back to the initial belief; pending values, the alignment histories and the control
  /// are discarded.
  void reset() {
    restartFilter();
    consecutiveFailures_ = 0;
    for (OpenPeriod& slot : open_) slot.clear();
    for (auto& aligner : aligners_) aligner.reset();
    for (auto& c : counters_) {
      c.lastStamp = -std::numeric_limits<double>::infinity();
      c.lastAccepted = std::numeric_limits<double>::quiet_NaN();
    }
    control_.setZero();
    nis_.clear();
    fillEstimate(last_.time, 0, 0);
  }

  const Estimate& lastEstimate() const { return last_; }
  const Filter& filter() const { return filter_; }
  const InputCounters& counters(Index input) const {
    return counters_[static_cast<std::size_t>(input)];
  }
  /// The input's options (the defaults when Options::inputs is empty).
  const InputOptions& inputOptions(Index input) const {
    return options_.inputs.empty() ? kDefaultInput
                                   : options_.inputs[static_cast<std::size_t>(input)];
  }
  Index inputCount() const { return static_cast<Index>(counters_.size()); }
  /// Whether input `input` has a timeout and used no value (one that reached the filter: not
  /// dropped, late or gated) arriving later than `timeout` before time t
  /// (counted from the schedule's start, or the last reset, if it never did).
  bool timedOut(Index input, double t) const {
    const InputOptions& o = inputOptions(input);
    if (!o.hasTimeout() || !schedule_.started()) return false;
    const double last = counters(input).lastAccepted;
    return t - (std::isnan(last) ? startTime_ : last) > o.timeout;
  }
  /// The same at the clock's last reading.
  bool timedOut(Index input) const { return timedOut(input, clock_); }
  /// The last clock reading passed to advanceTo().
  double clock() const { return clock_; }
  /// The clock reading the schedule (re)started at.
  double startTime() const { return startTime_; }
  /// The NIS of the recent periods (empty unless Options::nisWindow > 0 and the filter
  /// predicts its measurement).
  const NisWindow& nis() const { return nis_; }
  /// Periods whose NIS could not be computed (innovation covariance not positive definite).
  std::uint64_t nisFailures() const { return nisFailures_; }
  std::uint64_t clockResets() const { return clockResets_; }
  /// Forward gaps crossed with one estimate (advanceTo() or skipGap()), and the periods they
  /// skipped without estimating.
  std::uint64_t skippedGaps() const { return skippedGaps_; }
  std::uint64_t skippedPeriods() const { return skippedPeriods_; }
  /// Steps the estimator rejected (each period's estimate then is the last good one).
  std::uint64_t estimationFailures() const { return estimationFailures_; }
  /// Rejected steps since the last successful one.
  std::uint64_t consecutiveFailures() const { return consecutiveFailures_; }
  /// Restarts of the filter from its initial belief after Options::maxConsecutiveFailures
  /// rejected steps in a row (not counting reset() and clock jumps backwards).
  std::uint64_t filterResets() const { return filterResets_; }
  const std::string& lastFailure() const { return lastFailure_; }
  std::uint64_t controlNonFinite() const { return controlNonFinite_; }
  /// What the filter repaired instead of failing (numerical_repairs.hpp), since the core was
  /// made: kept across filter restarts. All zero for methods that repair nothing.
  estimation::NumericalRepairs numericalRepairs() const {
    estimation::NumericalRepairs total = repairsBeforeRestart_;
    if constexpr (estimation::HasNumericalRepairs<Filter>::value) {
      total += filter_.numericalRepairs();
    }
    return total;
  }
  double period() const { return options_.period; }
  /// Periods a forward clock jump may span and still have each of them estimated.
  std::uint64_t maxCatchUpPeriods() const { return options_.maxCatchUpPeriods; }
  double maxMeasurementLag() const { return options_.maxMeasurementLag; }
  /// Wall time spent in the estimator's steps, and their number (failed steps excluded).
  double estimatorSeconds() const { return estimatorSeconds_; }
  std::uint64_t estimateCount() const { return estimateCount_; }
  /// The longest estimator step so far [s].
  double maxStepSeconds() const { return maxStepSeconds_; }

 private:
  /// What arrived for one not yet estimated period.
  struct OpenPeriod {
    std::uint64_t index = 0;  ///< the period the slot holds
    std::vector<InputPeriod> inputs;
    estimation::Vector<L> control;
    estimation::Mask<L> controlSet;  ///< controls received in the period

    void clear() {
      for (InputPeriod& in : inputs) in.clear();
      controlSet.setConstant(false);
    }
  };

  static inline const InputOptions kDefaultInput{};

  static const Options& checked(const Options& o, Index inputs) {
    if (!(o.period >= kMinPeriod && o.period <= kMaxPeriod)) {
      throw estimation::ParameterError(
          "estimation period must be from 0.1 ms to 1 h (1e-4 .. 3600 s), got " +
          std::to_string(o.period) + " s");
    }
    if (o.maxCatchUpPeriods < 1 || o.maxCatchUpPeriods > kMaxCatchUpLimit) {
      throw estimation::ParameterError("maximum catch-up periods must be from 1 to " +
                                       std::to_string(kMaxCatchUpLimit) + ", got " +
                                       std::to_string(o.maxCatchUpPeriods));
    }
    if (!(o.maxMeasurementLag >= 0.0) || !std::isfinite(o.maxMeasurementLag)) {
      throw estimation::ParameterError("maximum measurement lag must be finite and >= 0");
    }
    if (!(o.maxFutureStamp >= 0.0)) {
      throw estimation::ParameterError("maximum future stamp must be >= 0 (infinite: no check)");
    }
    if (o.maxConsecutiveFailures < 1) {
      throw estimation::ParameterError(
          "maximum consecutive failures must be at least 1 (1: restart at the first failure)");
    }
    if (o.nisWindow > 1000000) {
      throw estimation::ParameterError("NIS window is longer than 1e6 periods");
    }
    if (o.maxMeasurementLag / o.period > 10000.0) {
      throw estimation::ParameterError("maximum measurement lag is more than 10000 periods");
    }
    if (!o.inputs.empty() && static_cast<Index>(o.inputs.size()) != inputs) {
      throw estimation::ParameterError("input options: expected " + std::to_string(inputs) +
                                       " entries (one per input), found " +
                                       std::to_string(o.inputs.size()));
    }
    for (std::size_t i = 0; i < o.inputs.size(); ++i) {
      const std::string problem = inputOptionsProblem(o.inputs[i]);
      if (!problem.empty()) {
        throw estimation::ParameterError("input " + std::to_string(i) + ": " + problem);
      }
      if (!kCanPredict && (o.inputs[i].gated() || o.inputs[i].alignment.needsPrediction())) {
        throw estimation::ParameterError(
            "input " + std::to_string(i) + ": " +
            (o.inputs[i].gated() ? "a Mahalanobis gate" : "FILL") +
            " needs the filter's predicted measurement, which this method does not give");
      }
    }
    return o;
  }

  /// Back to the initial belief, keeping the count of the repairs made so far.
  void restartFilter() {
    repairsBeforeRestart_ = numericalRepairs();
    filter_ = initial_;
  }

  void restartSchedule(double now) {
    startTime_ = now;
    schedule_.start(now - options_.maxMeasurementLag);
    openWindow();
  }

  std::uint64_t newestOpenPeriod() const { return schedule_.index() + open_.size() - 1; }

  OpenPeriod& slotOf(std::uint64_t k) { return open_[k & (open_.size() - 1)]; }

  /// The open period time t belongs to. A time in a period already estimated gives the
  /// current period and sets `estimated`; one beyond the newest open period gives that one
  /// and sets `beyond`. Before the schedule starts every time gives the first period.
  std::uint64_t openPeriodOf(double t, bool& estimated, bool& beyond) const {
    const std::uint64_t current = schedule_.index();
    if (!schedule_.started() || schedule_.inCurrent(t)) return current;  // the usual case
    const std::int64_t k = schedule_.indexOf(t);
    if (k < static_cast<std::int64_t>(current)) {
      estimated = true;
      return current;
    }
    if (k > static_cast<std::int64_t>(newestOpenPeriod())) {
      beyond = true;
      return newestOpenPeriod();
    }
    return static_cast<std::uint64_t>(k);
  }

  /// Assigns the slots to the open periods from the current one on. A slot still holding an
  /// older period (skipped by a gap or a restart) is emptied; its controls are kept.
  void openWindow() {
    for (std::uint64_t k = schedule_.index(); k <= newestOpenPeriod(); ++k) {
      OpenPeriod& slot = slotOf(k);
      if (slot.index == k) continue;
      takeControls(slot);
      slot.clear();
      slot.index = k;
    }
  }

  void takeControls(const OpenPeriod& slot) {
    for (Index j = 0; j < control_.size(); ++j) {
      if (slot.controlSet(j)) control_(j) = slot.control(j);
    }
  }

  /// Aligns the current period's inputs, estimates, and moves the schedule on.
  void estimatePeriod() {
    const std::uint64_t k = schedule_.index();
    const double end = schedule_.currentEnd();
    OpenPeriod& slot = slotOf(k);
    takeControls(slot);
    Index present = 0, substituted = 0;
    bool failed = false, reset = false;
    try {
      filter_.setControl(control_);
      bool predicted = false;
      const auto prediction = [&]() -> const estimation::MeasurementPrediction<M>& {
        if constexpr (kCanPredict) {
          if (!predicted) filter_.predictMeasurement(prediction_);
          predicted = true;
        }
        return prediction_;
      };
      for (Index i = 0; i < inputCount(); ++i) {
        const auto ii = static_cast<std::size_t>(i);
        const InputPeriod& in = slot.inputs[ii];
        InputAligner& aligner = aligners_[ii];
        InputCounters& c = counters_[ii];
        std::optional<AlignedValue> v = aligner.measured(in);
        measured_.available(i) = false;
        if (v && inputOptions(i).gated() &&
            estimation::squaredMahalanobisDistance(prediction(), i, v->value, v->variance) >
                inputOptions(i).gateThreshold) {
          c.gated += in.count();
          v.reset();
        }
        if (v) {
          ++present;
          measured_.available(i) = true;
          const std::uint32_t superseded = aligner.superseded(in);
          c.superseded += superseded;
          c.used += in.count() - superseded;
          aligner.accept(in);
          // Only a value that reaches the filter keeps the input alive (not one that arrives
          // late or fails the gate): a sensor publishing nothing usable times out.
          if (!(in.newestArrival() <= c.lastAccepted)) c.lastAccepted = in.newestArrival();
        } else if (timedOut(i, end)) {
          ++c.timedOutPeriods;
          aligner.reset();  // a returning sensor starts a fresh history
        } else if (aligner.canSubstitute()) {
          const double predictedValue =
              aligner.policy().needsPrediction() ? prediction().mean(i) : 0.0;
          v = aligner.substitute(end, predictedValue);
          ++substituted;
          ++c.substituted;
        }
        measurement_.available(i) = v.has_value();
        measurement_.varianceGiven(i) = v && v->variance.has_value();
        measurement_.value(i) = v ? v->value : 0.0;
        measurement_.variance(i) = v && v->variance ? *v->variance : 0.0;
      }
      if (nis_.enabled() && present > 0) {
        // The check must never change the estimate: a prediction it alone asked for and that
        // fails only skips the period's NIS (the step itself then decides about a failure).
        try {
          addNis(prediction());
        } catch (const estimation::EstimationError&) {
          ++nisFailures_;
        }
      }
      const auto begin = std::chrono::steady_clock::now();
      filter_.estimate(measurement_);
      const double step =
          std::chrono::duration<double>(std::chrono::steady_clock::now() - begin).count();
      estimatorSeconds_ += step;
      if (step > maxStepSeconds_) maxStepSeconds_ = step;
      ++estimateCount_;
      consecutiveFailures_ = 0;
    } catch (const estimation::EstimationError& e) {
      // The filter rejected the step and kept its belief, which stays the estimate. A fault
      // that persists for maxConsecutiveFailures periods is not mended by waiting: only then
      // does the filter restart from its initial belief.
      ++estimationFailures_;
      lastFailure_ = e.what();
      failed = true;
      if (++consecutiveFailures_ >= options_.maxConsecutiveFailures) {
        restartFilter();
        ++filterResets_;
        consecutiveFailures_ = 0;
        reset = true;
      } else {
        inflateByProcessNoise();
      }
    }
    slot.clear();
    slot.index = k + open_.size();
    fillEstimate(end, present, substituted, failed, reset);
    schedule_.advance();
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

  /// The NIS of the period's measured (not substituted) entries, into the window. Throws
  /// NumericalError when the innovation covariance is not positive definite.
  void addNis(const estimation::MeasurementPrediction<M>& prediction) {
    for (Index i = 0; i < inputCount(); ++i) {
      measured_.value(i) = measurement_.value(i);
      measured_.varianceGiven(i) = measurement_.varianceGiven(i);
      measured_.variance(i) = measurement_.variance(i);
    }
    nis_.add(estimation::squaredMahalanobisDistance(prediction, measured_),
             static_cast<int>(measured_.availableCount()));
  }

  void fillEstimate(double time, Index present, Index substituted, bool failed = false,
                    bool reset = false) {
    last_.time = time;
    last_.stepFailed = failed;
    last_.filterReset = reset;
    last_.state = filter_.state();
    last_.covariance = filter_.covariance();
    last_.presentInputs = present;
    last_.substitutedInputs = substituted;
  }

  Filter filter_;
  Filter initial_;
  Options options_;
  PeriodSchedule schedule_;
  std::vector<InputCounters> counters_;
  std::vector<InputAligner> aligners_;
  std::vector<OpenPeriod> open_;  ///< ring of the open periods, slot k % size for period k
  estimation::Measurement<M> measurement_;
  estimation::MeasurementPrediction<M> prediction_;
  estimation::Measurement<M> measured_;  ///< the period's measured entries, for the NIS
  estimation::Vector<L> control_;        ///< the controls in force (of the last estimated period)
  NisWindow nis_;
  Estimate last_;
  double clock_ = 0.0;      ///< last reading passed to advanceTo
  double startTime_ = 0.0;  ///< clock reading the schedule (re)started at
  double maxStepSeconds_ = 0.0;
  std::uint64_t nisFailures_ = 0;
  double estimatorSeconds_ = 0.0;
  std::uint64_t estimateCount_ = 0;
  std::uint64_t clockResets_ = 0;
  std::uint64_t skippedGaps_ = 0;
  std::uint64_t skippedPeriods_ = 0;
  std::uint64_t estimationFailures_ = 0;
  std::uint64_t consecutiveFailures_ = 0;
  std::uint64_t filterResets_ = 0;
  std::uint64_t controlNonFinite_ = 0;
  estimation::NumericalRepairs repairsBeforeRestart_;  ///< of the filters before restarts
  std::string lastFailure_;
};

}  // namespace sf_filter
