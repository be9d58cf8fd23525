#include "sf_filter/core/fusion_core_base.hpp"

#include <array>
#include <cmath>
#include <cstddef>
#include <stdexcept>

#include <Eigen/Cholesky>

#include <sf_estimation/errors.hpp>
#include <sf_estimation/parameter_checks.hpp>

#include "sf_filter/core/alignment/input_aligner.hpp"
#include "sf_filter/core/alignment/input_period.hpp"
#include "sf_filter/core/period_schedule.hpp"

namespace sf_filter {

/// The schedule, the open periods and the per-input aligners.
struct FusionCoreBase::Ring {
  /// The covariance of two values of one message placed in one period (a < b), with the
  /// values and their ordinals in their inputs' periods, to find their weights in the
  /// aligned values.
  struct CrossTerm {
    Index a = 0, b = 0;
    double covariance = 0.0, valueA = 0.0, valueB = 0.0;
    std::uint32_t ordinalA = 0, ordinalB = 0;
  };

  /// What arrived for one not yet estimated period.
  struct OpenPeriod {
    std::uint64_t index = 0;  ///< the period the slot holds
    std::vector<InputPeriod> inputs;
    Eigen::VectorXd control;
    Eigen::Array<bool, Eigen::Dynamic, 1> controlSet;  ///< controls received in the period
    std::vector<CrossTerm> cross;  ///< cleared, not freed: no allocation once warmed up

    void clear() {
      for (InputPeriod& in : inputs) in.clear();
      controlSet.setConstant(false);
      cross.clear();
    }
  };

  explicit Ring(double period) : schedule(period) {}

  std::uint64_t newestOpenPeriod() const { return schedule.index() + open.size() - 1; }
  OpenPeriod& slotOf(std::uint64_t k) { return open[k & (open.size() - 1)]; }

  /// The open period time t belongs to. A time in a period already estimated gives the
  /// current period and sets `estimated`; one beyond the newest open period gives that one
  /// and sets `beyond`. Before the schedule starts every time gives the first period.
  std::uint64_t openPeriodOf(double t, bool& estimated, bool& beyond) const {
    const std::uint64_t current = schedule.index();
    if (!schedule.started() || schedule.inCurrent(t)) return current;  // the usual case
    const std::int64_t k = schedule.indexOf(t);
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

  PeriodSchedule schedule;
  std::vector<InputAligner> aligners;
  std::vector<OpenPeriod> open;  ///< ring of the open periods, slot k % size for period k
  /// The newest period a value or control was placed in (0: none since the schedule started).
  std::uint64_t newestPlaced = 0;
};

namespace {
const InputOptions kDefaultInput{};

/// The controls of `slot` that were set replace those in force.
template <class Slot>
void takeControls(const Slot& slot, Eigen::VectorXd& control) {
  for (Index j = 0; j < control.size(); ++j) {
    if (slot.controlSet(j)) control(j) = slot.control(j);
  }
}

/// FusionCoreBase::checked()'s checks of the per-input options and the inputs they name.
void checkInputOptions(const FusionCoreOptions& o, Index inputs, bool canPredict) {
  if (!o.inputs.empty() && static_cast<Index>(o.inputs.size()) != inputs) {
    throw estimation::ParameterError("input options: expected " + std::to_string(inputs) +
                                     " entries (one per input), found " +
                                     std::to_string(o.inputs.size()));
  }
  for (const FusionCoreOptions::FirstReading& f : o.initialFromInputs) {
    if (f.input < 0 || f.input >= inputs) {
      throw estimation::ParameterError("initial state from inputs: input " +
                                       std::to_string(f.input) + " is not one of the " +
                                       std::to_string(inputs) + " inputs");
    }
  }
  for (std::size_t i = 0; i < o.inputs.size(); ++i) {
    const std::string problem = inputOptionsProblem(o.inputs[i]);
    if (!problem.empty()) {
      throw estimation::ParameterError("input " + std::to_string(i) + ": " + problem);
    }
    if (!canPredict && (o.inputs[i].gated() || o.inputs[i].alignment.needsPrediction())) {
      throw estimation::ParameterError(
          "input " + std::to_string(i) + ": " +
          (o.inputs[i].gated() ? "a Mahalanobis gate" : "FILL") +
          " needs the filter's predicted measurement, which this method does not give");
    }
  }
}
}  // namespace

FusionCoreBase::FusionCoreBase(const FusionCoreOptions& options, Index inputs, Index controls,
                               bool canPredict)
    : options_(checked(options, inputs, canPredict)),
      ring_(options_.period),
      counters_(static_cast<std::size_t>(inputs)),
      entries_(static_cast<std::size_t>(inputs)),
      control_(Eigen::VectorXd::Zero(controls)),
      innovations_(canPredict ? options_.nisWindow : 0, static_cast<std::size_t>(inputs),
                   options_.nisTolerance) {
  for (Index i = 0; i < inputs; ++i) {
    ring_->aligners.emplace_back(inputOptions(i).alignment, inputOptions(i).angle);
  }
  leadStamps_.assign(static_cast<std::size_t>(inputs), -std::numeric_limits<double>::infinity());
  cadences_.assign(static_cast<std::size_t>(inputs), ArrivalCadence{});
  // A power of two, so that the slot of a period is a bit mask away. Beyond the periods the
  // lag keeps open, maxQueuedPeriods slots hold values that arrive ahead of a stalled clock.
  const auto needed =
      static_cast<std::size_t>(std::floor(options_.maxMeasurementLag / options_.period + 1e-9) + 3 +
                               static_cast<double>(options_.maxQueuedPeriods));
  std::size_t slots = 1;
  while (slots < needed) slots *= 2;
  Ring::OpenPeriod empty;
  empty.control = Eigen::VectorXd::Zero(controls);
  empty.controlSet = Eigen::Array<bool, Eigen::Dynamic, 1>::Constant(controls, false);
  for (Index i = 0; i < inputs; ++i) {
    empty.inputs.emplace_back(inputOptions(i).alignment.historyLength(), inputOptions(i).angle);
  }
  ring_->open.assign(slots, empty);
  openWindow();
}

FusionCoreBase::RingPtr::RingPtr(double period) : ring_(std::make_unique<Ring>(period)) {}
FusionCoreBase::RingPtr::RingPtr(const RingPtr& other)
    : ring_(std::make_unique<Ring>(*other.ring_)) {}
FusionCoreBase::RingPtr& FusionCoreBase::RingPtr::operator=(const RingPtr& other) {
  if (this != &other) ring_ = std::make_unique<Ring>(*other.ring_);
  return *this;
}
FusionCoreBase::RingPtr::~RingPtr() = default;

const InputOptions& FusionCoreBase::inputOptions(Index input) const {
  return options_.inputs.empty() ? kDefaultInput : options_.inputs[static_cast<std::size_t>(input)];
}

bool FusionCoreBase::timedOut(Index input, double t) const {
  const InputOptions& o = inputOptions(input);
  if (!o.hasTimeout() || !ring_->schedule.started()) return false;
  const double last = counters(input).lastAccepted;
  return t - (std::isnan(last) ? startTime_ : last) > o.timeout;
}

Rejection FusionCoreBase::addMeasurement(Index input, double now, double value,
                                         std::optional<double> variance, double stamp) {
  std::uint64_t period = 0;
  return place(input, now, value, variance, stamp, period);
}

Rejection FusionCoreBase::checkBlock(BlockMatrix& block) {
  if (!block.allFinite()) return Rejection::NonFiniteCovariance;
  // Asymmetric by rounding (a localiser's covariance computed in floating point): made exact,
  // as the library accepts it (estimation::kSymmetryTolerance); beyond that a fault.
  if (!estimation::nearlySymmetric(block)) return Rejection::AsymmetricCovariance;
  estimation::symmetrize(block);
  if (Eigen::LLT<BlockMatrix>(block).info() != Eigen::Success) {
    return Rejection::IndefiniteCovariance;
  }
  return Rejection::None;
}

Rejection FusionCoreBase::addMeasurementBlock(const Index* inputs, const double* values,
                                              const double* covariance, int count, double now,
                                              double stamp) {
  if (count < 1 || count > kMaxBlockSize) {
    throw std::invalid_argument("a covariance block covers 1 to " + std::to_string(kMaxBlockSize) +
                                " inputs, got " + std::to_string(count));
  }
  for (int r = 0; r < count; ++r) {
    if (inputs[r] < 0 || inputs[r] >= inputCount()) return Rejection::UnknownInput;
  }
  BlockMatrix block(count, count);
  for (int r = 0; r < count; ++r) {
    for (int c = 0; c < count; ++c) block(r, c) = covariance[r * count + c];
  }
  const Rejection why = checkBlock(block);
  if (why != Rejection::None) {
    for (int r = 0; r < count; ++r) {
      InputCounters& c = counters_[static_cast<std::size_t>(inputs[r])];
      ++c.received;
      c.lastArrival = now;
      ++c.badCovariance;
    }
    return why;
  }
  Rejection first = Rejection::None;
  std::array<std::uint64_t, kMaxBlockSize> period{};
  std::array<bool, kMaxBlockSize> placed{};
  for (int r = 0; r < count; ++r) {
    const Rejection why =
        place(inputs[r], now, values[r], block(r, r), stamp, period[static_cast<std::size_t>(r)]);
    placed[static_cast<std::size_t>(r)] = why == Rejection::None;
    if (first == Rejection::None) first = why;
  }
  for (int r = 0; r < count; ++r) {
    for (int c = r + 1; c < count; ++c) {
      const auto i = static_cast<std::size_t>(r), j = static_cast<std::size_t>(c);
      if (!placed[i] || !placed[j] || period[i] != period[j] || inputs[r] == inputs[c]) continue;
      Ring::OpenPeriod& slot = ring_->slotOf(period[i]);
      const bool ordered = inputs[r] < inputs[c];
      const int a = ordered ? r : c, b = ordered ? c : r;
      Ring::CrossTerm t;
      t.a = inputs[a];
      t.b = inputs[b];
      t.covariance = block(r, c);
      t.valueA = values[a];
      t.valueB = values[b];
      t.ordinalA = slot.inputs[static_cast<std::size_t>(t.a)].count();
      t.ordinalB = slot.inputs[static_cast<std::size_t>(t.b)].count();
      slot.cross.push_back(t);
    }
  }
  return first;
}

Rejection FusionCoreBase::place(Index input, double now, double value,
                                std::optional<double> variance, double stamp,
                                std::uint64_t& period) {
  if (input < 0 || input >= inputCount()) return Rejection::UnknownInput;
  InputCounters& c = counters_[static_cast<std::size_t>(input)];
  const InputOptions& o = inputOptions(input);
  ++c.received;
  c.lastArrival = now;
  noteReading(now);
  // Every input's deliveries are noted: the cadence also tells, with ~unstamped_cadence off,
  // which unstamped values a stall placed late (InputCounters::placedLate).
  cadences_[static_cast<std::size_t>(input)].noteDelivery(now);
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
    const Rejection r = acceptStamp(input, c, stamp, now);
    if (r != Rejection::None) return r;
  }
  const bool byStamp = o.alignByStamp && !std::isnan(stamp);
  const double arrival = arrivalTime(now, stamp);
  double time = arrival;
  if (byStamp) {
    time = stamp;
  } else if (std::isnan(stamp)) {
    time = cadenceTime(input, c, arrival, now);
  }
  bool estimated = false, beyond = false;
  const std::uint64_t k = placeValue(time, estimated, beyond);
  if (byStamp && estimated) {
    ++c.late;
    return Rejection::TooLate;
  }
  if (beyond) ++c.aheadOfClock;
  ring_->slotOf(k).inputs[static_cast<std::size_t>(input)].add(value, variance, time, arrival);
  period = k;
  return Rejection::None;
}

Rejection FusionCoreBase::acceptStamp(Index input, InputCounters& c, double stamp, double now) {
  if (stamp < c.lastStamp) {
    ++c.outOfOrder;
    return Rejection::OutOfOrder;
  }
  if (stamp == c.lastStamp) {
    ++c.duplicate;
    return Rejection::DuplicateStamp;
  }
  if (tooFarAhead(input, stamp, now)) {
    ++c.future;
    return Rejection::FutureStamp;
  }
  c.lastStamp = stamp;
  c.delays.add(now - stamp);
  // A value is never sent before it is stamped: stamps of two inputs ahead of the clock's
  // reading tell that the clock stands still while the values come (rosbag play catching up
  // publishes them without /clock); one input alone may only have a clock running ahead.
  // Only when stamps are checked against the clock (a finite maxFutureStamp): they are then
  // on its time base.
  if (stamp > reading_ && std::isfinite(options_.maxFutureStamp)) {
    double& lead = leadStamps_[static_cast<std::size_t>(input)];
    if (std::isinf(lead)) ++leaders_;
    if (stamp > lead) lead = stamp;
    if (stamp > leadStamp_) leadStamp_ = stamp;
  }
  return Rejection::None;
}

void FusionCoreBase::fillStatistics(FusionStatistics& out) const {
  out.inputs.assign(counters_.begin(), counters_.end());
  out.sumInputs();
  static_cast<EstimationTotals&>(out) = totals_;
  out.skippedGaps = skippedGaps_;
  out.skippedPeriods = skippedPeriods_;
  out.maxStepSeconds = maxStepSeconds_;
  out.lastFailure = lastFailure_;
  out.clock = clock_;
  out.startTime = startTime_;
}

bool FusionCoreBase::tooFarAhead(Index input, double stamp, double now) const {
  // Another input's stamp vouches for a stalled clock; an input's own stamps do not, so a
  // sensor whose clock runs ahead cannot carry itself further ahead value by value.
  double reference = now;
  for (std::size_t j = 0; j < leadStamps_.size(); ++j) {
    if (j != static_cast<std::size_t>(input) && leadStamps_[j] > reference) {
      reference = leadStamps_[j];
    }
  }
  return stamp > reference + options_.maxFutureStamp;
}

std::uint64_t FusionCoreBase::placeValue(double t, bool& estimated, bool& beyond) {
  const std::uint64_t k = ring_->openPeriodOf(t, estimated, beyond);
  if (k > ring_->newestPlaced) ring_->newestPlaced = k;
  return k;
}

double FusionCoreBase::arrivalTime(double now, double stamp) const {
  if (leaders_ < 2) return now;  // the clock is the time
  // Stalled: a stamped value at its stamp, anything else after the newest stamp.
  const double time = std::isnan(stamp) ? leadStamp_ : stamp;
  return now < time ? time : now;
}

double FusionCoreBase::cadenceTime(Index input, InputCounters& c, double arrival, double now) {
  ArrivalCadence& cadence = cadences_[static_cast<std::size_t>(input)];
  const double expected = cadence.lateExpected(arrival);
  double time = arrival, sent = arrival;
  if (!std::isnan(expected) && othersSilentSince(input, expected, now)) {
    bool estimated = false, beyond = false, arrivalEstimated = false, arrivalBeyond = false;
    const std::uint64_t k = ring_->openPeriodOf(expected, estimated, beyond);
    const bool earlier =
        estimated || k < ring_->openPeriodOf(arrival, arrivalEstimated, arrivalBeyond);
    if (earlier && !estimated && options_.unstampedCadence) {
      time = expected;
    } else if (earlier) {
      // kept at its arrival, a period after the one it was sent in: reported, so that a
      // comparison with the offline replay knows from where on the node could not follow it
      ++c.placedLate;
      if (std::isnan(c.firstPlacedLate)) c.firstPlacedLate = expected;
    }
    // The cadence goes on from when the value was sent, also when its period was estimated
    // already (a stall longer than the lag): the backlog's next values then still reach
    // their periods that are open (issue 38 D10, round seven).
    sent = expected;
  }
  cadence.note(arrival, sent);
  return time;
}

bool FusionCoreBase::othersSilentSince(Index input, double t, double now) const {
  bool evidence = false;
  for (std::size_t j = 0; j < cadences_.size(); ++j) {
    if (j == static_cast<std::size_t>(input) || !cadences_[j].delivered()) continue;
    if (!(cadences_[j].deliveredBefore(now) < t)) return false;
    evidence = true;
  }
  return evidence;
}

std::uint64_t FusionCoreBase::queuedAhead() const {
  const std::uint64_t current = ring_->schedule.index();
  return ring_->newestPlaced > current ? ring_->newestPlaced - current : 0;
}

Rejection FusionCoreBase::addControl(Index control, double value) {
  if (control < 0 || control >= control_.size()) return Rejection::UnknownInput;
  if (!std::isfinite(value)) {
    ++totals_.controlNonFinite;
    return Rejection::NonFinite;
  }
  bool estimated = false, beyond = false;
  Ring::OpenPeriod& slot = ring_->slotOf(
      placeValue(arrivalTime(clock_, std::numeric_limits<double>::quiet_NaN()), estimated, beyond));
  slot.control(control) = value;
  slot.controlSet(control) = true;
  return Rejection::None;
}

FusionCoreBase::ClockStep FusionCoreBase::readClock(double now) {
  noteReading(now);
  clock_ = now;
  const double lag = options_.maxMeasurementLag;
  PeriodSchedule& schedule = ring_->schedule;
  if (!schedule.started()) {
    restartSchedule(now);
    return {ClockEvent::Started, 0};
  }
  if (schedule.before(now - lag)) {
    restartSchedule(now);
    ++totals_.clockResets;
    return {ClockEvent::JumpedBackwards, 0};
  }
  const std::uint64_t due = schedule.periodsDue(now - lag);
  return {due > options_.maxCatchUpPeriods ? ClockEvent::SkippedGap : ClockEvent::Normal, due};
}

bool FusionCoreBase::scheduleStarted() const { return ring_->schedule.started(); }

std::uint64_t FusionCoreBase::periodsDue(double now) const {
  return ring_->schedule.periodsDue(now - options_.maxMeasurementLag);
}

void FusionCoreBase::skipPeriods(std::uint64_t due) {
  skippedPeriods_ += due - 1;
  ++skippedGaps_;
  ring_->schedule.skipTo(clock_ - options_.maxMeasurementLag);
  openWindow();
}

void FusionCoreBase::beginPeriod() {
  takeControls(ring_->slotOf(ring_->schedule.index()), control_);
}

void FusionCoreBase::alignInputs(Prediction& prediction) {
  const double end = periodEnd();
  Ring::OpenPeriod& slot = ring_->slotOf(ring_->schedule.index());
  present_ = substituted_ = 0;
  for (PeriodEntry& e : entries_) e = PeriodEntry{};
  for (Index i = 0; i < inputCount(); ++i) {
    const auto ii = static_cast<std::size_t>(i);
    const InputPeriod& in = slot.inputs[ii];
    InputAligner& aligner = ring_->aligners[ii];
    InputCounters& c = counters_[ii];
    std::optional<AlignedValue> v = aligner.measured(in);
    if (v && inputOptions(i).gated() &&
        prediction.gateDistance(i, v->value, v->variance) > inputOptions(i).gateThreshold) {
      c.gated += in.count();
      v.reset();
    }
    PeriodEntry& entry = entries_[ii];
    if (v) {
      ++present_;
      entry.measured = true;
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
      const double predicted = aligner.policy().needsPrediction() ? prediction.mean(i) : 0.0;
      v = aligner.substitute(end, predicted);
      ++substituted_;
      ++c.substituted;
    }
    entry.available = v.has_value();
    if (v) {
      entry.value = v->value;
      entry.variance = v->variance;
    }
  }
  alignCovariances();
}

void FusionCoreBase::alignCovariances() {
  covariances_.clear();
  const Ring::OpenPeriod& slot = ring_->slotOf(ring_->schedule.index());
  for (const Ring::CrossTerm& t : slot.cross) {
    const auto a = static_cast<std::size_t>(t.a), b = static_cast<std::size_t>(t.b);
    // Only between measured values that carry the message's variances (not substitutes, not
    // gated, not a period that mixed in values without one).
    if (!entries_[a].measured || !entries_[b].measured || !entries_[a].variance ||
        !entries_[b].variance) {
      continue;
    }
    const double weight = ring_->aligners[a].weightOf(slot.inputs[a], t.ordinalA, t.valueA) *
                          ring_->aligners[b].weightOf(slot.inputs[b], t.ordinalB, t.valueB);
    if (weight == 0.0) continue;
    PeriodCovariance* pair = nullptr;
    for (PeriodCovariance& p : covariances_) {
      if (p.a == t.a && p.b == t.b) pair = &p;
    }
    if (!pair) {
      covariances_.push_back(PeriodCovariance{t.a, t.b, 0.0});
      pair = &covariances_.back();
    }
    pair->covariance += weight * t.covariance;
  }
}

double FusionCoreBase::periodEnd() const { return ring_->schedule.currentEnd(); }

void FusionCoreBase::finishPeriod() {
  const std::uint64_t k = ring_->schedule.index();
  Ring::OpenPeriod& slot = ring_->slotOf(k);
  slot.clear();
  slot.index = k + ring_->open.size();
  ring_->schedule.advance();
}

void FusionCoreBase::recordStep(double seconds) {
  totals_.estimatorSeconds += seconds;
  if (seconds > maxStepSeconds_) maxStepSeconds_ = seconds;
  ++totals_.estimates;
  consecutiveFailures_ = 0;
}

bool FusionCoreBase::recordFailure(const std::string& what) {
  ++totals_.estimationFailures;
  lastFailure_ = what;
  if (++consecutiveFailures_ < options_.maxConsecutiveFailures) return false;
  ++totals_.filterResets;
  consecutiveFailures_ = 0;
  return true;
}

void FusionCoreBase::clearInputs() {
  for (Ring::OpenPeriod& slot : ring_->open) slot.clear();
  for (InputAligner& aligner : ring_->aligners) aligner.reset();
  for (InputCounters& c : counters_) {
    c.lastStamp = -std::numeric_limits<double>::infinity();
    c.lastAccepted = std::numeric_limits<double>::quiet_NaN();
  }
  control_.setZero();
  innovations_.restartWindows();
  present_ = substituted_ = 0;
  consecutiveFailures_ = 0;
  ring_->newestPlaced = 0;
  for (ArrivalCadence& cadence : cadences_) cadence.clear();
  clearLeadStamps();
}

const FusionCoreOptions& FusionCoreBase::checked(const FusionCoreOptions& o, Index inputs,
                                                 bool canPredict) {
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
  if (o.maxConsecutiveFailures < 1) {
    throw estimation::ParameterError(
        "maximum consecutive failures must be at least 1 (1: restart at the first failure)");
  }
  if (!(o.maxMeasurementLag >= 0.0) || !std::isfinite(o.maxMeasurementLag)) {
    throw estimation::ParameterError("maximum measurement lag must be finite and >= 0");
  }
  if (!(o.maxFutureStamp >= 0.0)) {
    throw estimation::ParameterError("maximum future stamp must be >= 0 (infinite: no check)");
  }
  if (o.nisWindow > 1000000) {
    throw estimation::ParameterError("NIS window is longer than 1e6 periods");
  }
  if (!(o.nisTolerance >= 1.0 && o.nisTolerance <= FusionCoreOptions::kMaxNisTolerance)) {
    throw estimation::ParameterError("NIS tolerance must be a factor from 1 to 100");
  }
  if (o.maxQueuedPeriods > kMaxQueuedLimit) {
    throw estimation::ParameterError("maximum queued periods must be at most " +
                                     std::to_string(kMaxQueuedLimit) + ", got " +
                                     std::to_string(o.maxQueuedPeriods));
  }
  if (o.maxMeasurementLag / o.period > 10000.0) {
    throw estimation::ParameterError("maximum measurement lag is more than 10000 periods");
  }
  checkInputOptions(o, inputs, canPredict);
  return o;
}

void FusionCoreBase::restartSchedule(double now) {
  startTime_ = now;
  if (options_.periodsOnClockGrid) {
    ring_->schedule.startOnGrid(now - options_.maxMeasurementLag);
  } else {
    ring_->schedule.start(now - options_.maxMeasurementLag);
  }
  ring_->newestPlaced = 0;
  reading_ = now;
  clearLeadStamps();
  openWindow();
}

void FusionCoreBase::noteReading(double now) {
  if (now <= reading_) return;
  reading_ = now;
  clearLeadStamps();  // the clock moves: it is the time again
}

void FusionCoreBase::clearLeadStamps() {
  for (double& lead : leadStamps_) lead = -std::numeric_limits<double>::infinity();
  leadStamp_ = -std::numeric_limits<double>::infinity();
  leaders_ = 0;
}

/// Assigns the slots to the open periods from the current one on. A slot still holding an
/// older period (skipped by a gap or a restart) is emptied; its controls are kept.
void FusionCoreBase::openWindow() {
  for (std::uint64_t k = ring_->schedule.index(); k <= ring_->newestOpenPeriod(); ++k) {
    Ring::OpenPeriod& slot = ring_->slotOf(k);
    if (slot.index == k) continue;
    takeControls(slot, control_);
    slot.clear();
    slot.index = k;
  }
}

}  // namespace sf_filter
