// The part of the fusion core (fusion_core.hpp) that does not depend on the filter's type:
// the checks of arriving values, the schedule of periods, the ring of open periods, the
// alignment of every input per period (policies, gates, timeouts, substitutes), the counters
// and the NIS window. It is compiled once (src/core/fusion_core_base.cpp) and shared by every
// configuration header's node; FusionCore<Filter> adds the filter and its fixed-size step.
// The rules are those of fusion_core.hpp's header comment.
#pragma once

#include <cstdint>
#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>
#include <sf_estimation/types.hpp>

#include "sf_filter/core/arrival_cadence.hpp"
#include "sf_filter/core/fusion_core_options.hpp"
#include "sf_filter/core/fusion_engine.hpp"
#include "sf_filter/core/fusion_statistics.hpp"
#include "sf_filter/core/innovation_record.hpp"
#include "sf_filter/core/input_counters.hpp"
#include "sf_filter/core/input_options.hpp"
#include "sf_filter/core/nis_window.hpp"

namespace sf_filter {

class FusionCoreBase {
 public:
  static constexpr double kMinPeriod = FusionCoreOptions::kMinPeriod;
  static constexpr double kMaxPeriod = FusionCoreOptions::kMaxPeriod;
  static constexpr std::uint64_t kMaxCatchUpLimit = FusionCoreOptions::kMaxCatchUpLimit;
  static constexpr std::uint64_t kMaxQueuedLimit = FusionCoreOptions::kMaxQueuedLimit;
  /// The largest variance a measurement may carry (sf_filter::kMaxVariance, 1e100).
  static constexpr double kMaxVariance = sf_filter::kMaxVariance;

  /// A measurement of input `input` received at `now`, with the variance the message carried
  /// (if any). `stamp` (NaN when the message has no header) must not run backwards per input;
  /// it places the value in its period if the input is aligned by stamp. While the clock stands
  /// still, a value aligned by arrival is placed no earlier than the newest stamp accepted
  /// since (fusion_core.hpp, "Clock stalls").
  Rejection addMeasurement(Index input, double now, double value,
                           std::optional<double> variance = std::nullopt,
                           double stamp = std::numeric_limits<double>::quiet_NaN());
  /// Most inputs one message's covariance block may cover (a 6 x 6 pose or twist covariance).
  static constexpr int kMaxBlockSize = 6;
  /// `count` values of inputs `inputs` read from one message, with the message's covariance
  /// block of them (`covariance`: row-major count x count, the variances on its diagonal).
  /// A block that is not a covariance drops every value, counted as a bad covariance of each
  /// input and returned as what it is: not finite, not symmetric (a relative asymmetry above
  /// estimation::kSymmetryTolerance; a smaller one is rounding, symmetrised), not positive
  /// definite. Otherwise each value is
  /// checked and placed as by addMeasurement (one may be dropped alone), and the covariances
  /// between the values placed in one period go with them to the filter, carried through
  /// the period's alignment (AVERAGE: the mean's weights; newest-value policies: only when
  /// both newest values came from this message; not to substitutes or gated values).
  /// Returns the first rejection, None if every value was accepted. Throws
  /// std::invalid_argument for a count outside 1 .. kMaxBlockSize.
  Rejection addMeasurementBlock(const Index* inputs, const double* values, const double* covariance,
                                int count, double now,
                                double stamp = std::numeric_limits<double>::quiet_NaN());
  /// A control value, received at the clock's last reading; a period uses the latest value of
  /// each control received before its end.
  Rejection addControl(Index control, double value);

  const InputCounters& counters(Index input) const {
    return counters_[static_cast<std::size_t>(input)];
  }
  /// The input's options (the defaults when Options::inputs is empty).
  const InputOptions& inputOptions(Index input) const;
  Index inputCount() const { return static_cast<Index>(counters_.size()); }
  /// Whether input `input` has a timeout and used no value (one that reached the filter: not
  /// dropped, late or gated) arriving later than `timeout` before time t
  /// (counted from the schedule's start, or the last reset, if it never did).
  bool timedOut(Index input, double t) const;
  /// The same at the clock's last reading.
  bool timedOut(Index input) const { return timedOut(input, clock_); }
  /// The last clock reading passed to advanceTo().
  double clock() const { return clock_; }
  /// The clock reading the schedule (re)started at.
  double startTime() const { return startTime_; }
  /// The NIS of the recent periods (empty unless Options::nisWindow > 0 and the filter
  /// predicts its measurement).
  const NisWindow& nis() const { return innovations_.overall().window(); }
  /// The NIS of the run, overall and per input, and the prediction-error cost (recorded under
  /// the same conditions as nis()).
  const InnovationRecord& innovations() const { return innovations_; }
  /// Periods whose NIS could not be computed (innovation covariance not positive definite).
  std::uint64_t nisFailures() const { return totals_.nisFailures; }
  std::uint64_t clockResets() const { return totals_.clockResets; }
  /// Forward gaps crossed with one estimate (advanceTo() or skipGap()), and the periods they
  /// skipped without estimating.
  std::uint64_t skippedGaps() const { return skippedGaps_; }
  std::uint64_t skippedPeriods() const { return skippedPeriods_; }
  /// Steps the estimator rejected (each period's estimate then is the last good one).
  std::uint64_t estimationFailures() const { return totals_.estimationFailures; }
  /// Rejected steps since the last successful one.
  std::uint64_t consecutiveFailures() const { return consecutiveFailures_; }
  /// Restarts of the filter from its initial belief after Options::maxConsecutiveFailures
  /// rejected steps in a row (not counting reset() and clock jumps backwards).
  std::uint64_t filterResets() const { return totals_.filterResets; }
  /// Periods after the current one, up to the newest holding a value or control that arrived
  /// ahead of the clock (0: none): what a forward jump of the clock estimates one by one before
  /// it skips the rest of the gap.
  std::uint64_t queuedAhead() const;
  /// Periods that have ended by `now` (minus the lag) and are not estimated yet: what
  /// advanceTo(now) would estimate, or skip when more than maxCatchUpPeriods().
  std::uint64_t periodsDue(double now) const;
  const std::string& lastFailure() const { return lastFailure_; }
  std::uint64_t controlNonFinite() const { return totals_.controlNonFinite; }
  double period() const { return options_.period; }
  /// Periods a forward clock jump may span and still have each of them estimated.
  std::uint64_t maxCatchUpPeriods() const { return options_.maxCatchUpPeriods; }
  double maxMeasurementLag() const { return options_.maxMeasurementLag; }
  /// Wall time spent in the estimator's steps, and their number (failed steps excluded).
  double estimatorSeconds() const { return totals_.estimatorSeconds; }
  std::uint64_t estimateCount() const { return totals_.estimates; }
  /// The longest estimator step so far [s].
  double maxStepSeconds() const { return maxStepSeconds_; }
  /// The counters above copied into `out` (FusionStatistics), the inputs' totals summed; the
  /// filter's numerical repairs are FusionCore's to add.
  void fillStatistics(FusionStatistics& out) const;

 protected:
  /// `canPredict`: the filter gives its predicted measurement (gates and FILL possible).
  FusionCoreBase(const FusionCoreOptions& options, Index inputs, Index controls, bool canPredict);
  // A copy is independent of the original: the ring and the aligners are copied.

  /// What the filter predicts for this period's measurement, asked for only when a gate, a
  /// FILL substitute or the NIS needs it.
  class Prediction {
   public:
    virtual ~Prediction() = default;
    /// Squared Mahalanobis distance of `value` of input `input` alone (a per-input gate).
    virtual double gateDistance(Index input, double value, std::optional<double> variance) = 0;
    /// The predicted measurement of input `input`.
    virtual double mean(Index input) = 0;
  };

  /// The covariance between the aligned values of inputs a < b in the period being estimated
  /// (from addMeasurementBlock); replaces R(a, b) for the step.
  struct PeriodCovariance {
    Index a = 0, b = 0;
    double covariance = 0.0;
  };

  /// One input's value for the period being estimated.
  struct PeriodEntry {
    bool available = false;  ///< measured or substituted
    bool measured = false;   ///< measured (not gated, not a substitute): counts for the NIS
    double value = 0.0;
    std::optional<double> variance;  ///< none: the filter's configured R
  };

  /// What advanceTo() must do after the clock reading `now`: nothing (Started), reset the
  /// filter (JumpedBackwards: the schedule has restarted), estimate `due` periods (Normal), or
  /// estimate one and then skipPeriods(due) (SkippedGap).
  struct ClockStep {
    ClockEvent event = ClockEvent::Normal;
    std::uint64_t due = 0;
  };
  ClockStep readClock(double now);
  bool scheduleStarted() const;
  void setClock(double now) {
    noteReading(now);
    clock_ = now;
  }
  /// After the one estimate that crosses a gap of `due` periods to the clock's reading: the
  /// schedule moves on by whole periods so that the reading lies in the current one.
  void skipPeriods(std::uint64_t due);

  /// Starts the current period: the controls received before its end come into force.
  void beginPeriod();
  /// Aligns every input for the current period (counted), asking `prediction` only when
  /// needed; the results are in periodEntries(). May throw the prediction's
  /// estimation::EstimationError (the caller counts it as a failed step).
  void alignInputs(Prediction& prediction);
  const std::vector<PeriodEntry>& periodEntries() const { return entries_; }
  /// Covariances between measured entries of the period (alignInputs()).
  const std::vector<PeriodCovariance>& periodCovariances() const { return covariances_; }
  Index presentInputs() const { return present_; }
  Index substitutedInputs() const { return substituted_; }
  /// The controls in force for the current period.
  const Eigen::VectorXd& controls() const { return control_; }
  /// End of the current period.
  double periodEnd() const;
  /// Ends the current period: empties its slot and moves the schedule on.
  void finishPeriod();

  /// Statistics of the period's step.
  void recordStep(double seconds);
  /// Counts a rejected step; true when it is the maxConsecutiveFailures-th in a row, which
  /// restarts the filter (counted as a filter reset).
  bool recordFailure(const std::string& what);
  /// The period's innovation over its measured entries (InnovationRecord::addPeriod).
  void addNis(double nis, int degreesOfFreedom, double logDetS) {
    innovations_.addPeriod(nis, degreesOfFreedom, logDetS);
  }
  /// Input `input`'s own NIS in the period (InnovationRecord::addInput).
  void addInputNis(Index input, double nis) {
    innovations_.addInput(static_cast<std::size_t>(input), nis);
  }
  void countNisFailure() { ++totals_.nisFailures; }
  bool nisWanted() const { return innovations_.enabled() && present_ > 0; }

  /// Discards pending values, the alignment histories, the controls and the NIS windows.
  void clearInputs();
  /// The options as checked.
  const FusionCoreOptions& options() const { return options_; }

 private:
  struct Ring;  ///< the open periods and the aligners (src/core/fusion_core_base.cpp)
  /// Owns the Ring and copies it with its owner.
  class RingPtr {
   public:
    explicit RingPtr(double period);
    RingPtr(const RingPtr& other);
    RingPtr& operator=(const RingPtr& other);
    ~RingPtr();
    Ring* operator->() const { return ring_.get(); }
    Ring& operator*() const { return *ring_; }

   private:
    std::unique_ptr<Ring> ring_;
  };

  using BlockMatrix =
      Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, kMaxBlockSize, kMaxBlockSize>;
  /// Why a message's covariance block is no covariance (None: it is, and is now symmetric to
  /// the bit): not finite, asymmetric beyond estimation::kSymmetryTolerance, not positive
  /// definite.
  static Rejection checkBlock(BlockMatrix& block);
  /// addMeasurement, telling the period the value was placed in.
  Rejection place(Index input, double now, double value, std::optional<double> variance,
                  double stamp, std::uint64_t& period);
  /// The period's covariances from its slot's cross terms (alignInputs()).
  void alignCovariances();
  static const FusionCoreOptions& checked(const FusionCoreOptions& o, Index inputs,
                                          bool canPredict);
  void restartSchedule(double now);
  void openWindow();
  /// Whether a stamp of input `input` is further ahead than maxFutureStamp of the clock reading
  /// `now` and of the newest stamp every other input sent while the clock stood still.
  bool tooFarAhead(Index input, double stamp, double now) const;
  /// place()'s checks of a set stamp against the input's previous one and the clock; notes the
  /// stamp (delay, lead stamps) when it is accepted.
  Rejection acceptStamp(Index input, InputCounters& c, double stamp, double now);
  /// The open period of time t (ring.openPeriodOf), remembered as queued when it lies ahead.
  std::uint64_t placeValue(double t, bool& estimated, bool& beyond);
  /// The time a value aligned by arrival (or a control: `stamp` NaN) belongs to: its arrival,
  /// or while two inputs' stamps say that the clock stands still, no earlier than its own stamp
  /// (a stamped value) or the newest stamp (anything else).
  double arrivalTime(double now, double stamp) const;
  /// The time an unstamped value of input `input` aligned by arrival at `arrival` (received
  /// at `now`) belongs to: its arrival, or with Options::unstampedCadence the time its input's
  /// cadence predicts when it came late, every other input was silent since (a stalled
  /// delivery, not a skipped value) and that period is still open. Notes the value, and in
  /// `c` a value kept at its arrival although sent in an earlier period (placedLate).
  double cadenceTime(Index input, InputCounters& c, double arrival, double now);
  /// Whether every other input that delivered at all delivered nothing from time t until the
  /// values received at `now`, and at least one did deliver: a stall, vouched for by others.
  bool othersSilentSince(Index input, double t, double now) const;
  void clearLeadStamps();
  /// A clock reading (advanceTo's, or an arrival's): one later than all before means the clock
  /// moves, and the lead stamps are forgotten.
  void noteReading(double now);

  FusionCoreOptions options_;
  RingPtr ring_;
  std::vector<InputCounters> counters_;
  std::vector<PeriodEntry> entries_;
  std::vector<PeriodCovariance> covariances_;
  Eigen::VectorXd control_;  ///< the controls in force (of the last estimated period)
  InnovationRecord innovations_;
  Index present_ = 0, substituted_ = 0;
  double clock_ = 0.0;  ///< last reading passed to readClock
  /// Per input: its newest stamp accepted while the clock stood still, ahead of the clock
  /// (-inf: none since the clock last moved). Stamps stand in for a stalled clock.
  std::vector<double> leadStamps_;
  double leadStamp_ = -std::numeric_limits<double>::infinity();  ///< the largest of them
  std::vector<ArrivalCadence> cadences_;  ///< per input (placement and placedLate)
  int leaders_ = 0;  ///< inputs with a lead stamp: two or more mean the clock stands still
  /// The latest clock reading seen, by readClock() or as an arrival time.
  double reading_ = -std::numeric_limits<double>::infinity();
  double startTime_ = 0.0;  ///< clock reading the schedule (re)started at
  double maxStepSeconds_ = 0.0;
  EstimationTotals totals_;  ///< repairs aside: the filter's, added by the engine
  std::uint64_t skippedGaps_ = 0;
  std::uint64_t skippedPeriods_ = 0;
  std::uint64_t consecutiveFailures_ = 0;
  std::string lastFailure_;
};

}  // namespace sf_filter
