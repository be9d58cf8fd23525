// Unit tests of alignment by header stamp and of the maximum measurement lag in the fusion
// core: a delayed value counts for the period it was stamped in, a period is estimated only
// once the clock passed its end plus the lag, values stamped in estimated periods are dropped
// and counted, inputs aligned by arrival and controls keep using arrival time.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <utility>
#include <vector>

#include "train_core.hpp"

namespace {

using namespace train_core;
using sf_filter::InputOptions;
using sf_filter::Rejection;

constexpr double kLag = 0.05;

/// Input 0 (speed) by stamp or by arrival, input 1 by arrival; lag 50 ms. Started at 1.05 s,
/// so that the periods are [1.0, 1.1), [1.1, 1.2), ... (the schedule starts one lag before
/// the first clock reading) and period k is estimated at its end + 50 ms.
Core makeStartedCore(Collector& out, bool speedByStamp = true,
                     std::uint64_t queuedPeriods = Core::Options().maxQueuedPeriods) {
  Core::Options options;
  options.period = kPeriod;
  options.maxMeasurementLag = kLag;
  options.maxQueuedPeriods = queuedPeriods;
  options.inputs.resize(2);
  options.inputs[0].alignByStamp = speedByStamp;
  Core core(makeTrain(), options);
  core.advanceTo(1.05, out);
  return core;
}

/// The estimates of a core with the lag started at `firstReading`, fed the speed 3.0
/// stamped at 1.203 s (arriving at 1.21 s), run to 1.5 s.
std::vector<Core::Estimate> gridRun(double firstReading, bool onGrid) {
  Core::Options options;
  options.period = kPeriod;
  options.maxMeasurementLag = kLag;
  options.periodsOnClockGrid = onGrid;
  options.inputs.resize(2);
  options.inputs[0].alignByStamp = true;
  Core core(makeTrain(), options);
  Collector out;
  core.advanceTo(firstReading, out);
  core.advanceTo(1.21, out);
  EXPECT_EQ(core.addMeasurement(0, 1.21, 3.0, std::nullopt, 1.203), Rejection::None);
  core.advanceTo(1.5, out);
  return out.estimates;
}

// Online the first clock reading is the node's first /clock, offline the first message: a
// few ms apart. Started at 1.055 s instead of 1.052 s, the periods shift by 3 ms and the value
// stamped at 1.203 s falls into another period ([1.105, 1.205) instead of [1.202, 1.302)); on
// the clock grid both runs have the periods [1.0, 1.1), [1.1, 1.2), ... and the same
// estimates.
TEST(FusionCoreStamps, OnTheClockGridTheFirstReadingDoesNotMoveThePeriods) {
  const auto early = gridRun(1.052, true), late = gridRun(1.055, true);
  ASSERT_EQ(early.size(), 4u);  // the periods ending at 1.1, 1.2, 1.3, 1.4 (1.5 at 1.55)
  ASSERT_EQ(late.size(), early.size());
  for (std::size_t k = 0; k < early.size(); ++k) {
    EXPECT_NEAR(early[k].time, 1.1 + 0.1 * static_cast<double>(k), 1e-9) << k;
    EXPECT_EQ(early[k].time, late[k].time) << k;
    EXPECT_EQ(early[k].state, late[k].state) << k;
    EXPECT_EQ(early[k].presentInputs, late[k].presentInputs) << k;
  }
  EXPECT_EQ(early[2].presentInputs, 1);  // [1.2, 1.3) holds the value stamped at 1.203
  // Without the grid the phase is the first reading's: the value is one period earlier in
  // the later-started run.
  const auto earlyPhase = gridRun(1.052, false), latePhase = gridRun(1.055, false);
  EXPECT_NEAR(earlyPhase.at(0).time, 1.102, 1e-9);
  EXPECT_NEAR(latePhase.at(0).time, 1.105, 1e-9);
  EXPECT_EQ(earlyPhase.at(2).presentInputs, 1);
  EXPECT_EQ(latePhase.at(1).presentInputs, 1);
  EXPECT_EQ(latePhase.at(2).presentInputs, 0);
}

TEST(FusionCoreStamps, APeriodIsEstimatedOnlyAfterItsEndPlusTheLag) {
  Collector out;
  Core core = makeStartedCore(out);
  core.advanceTo(1.12, out);
  EXPECT_TRUE(out.estimates.empty());  // period 1 ended at 1.1 but waits until 1.15
  core.advanceTo(1.15, out);
  ASSERT_EQ(out.estimates.size(), 1u);
  EXPECT_NEAR(out.estimates[0].time, 1.1, 1e-12);  // the estimate refers to the period's end
  core.advanceTo(1.25, out);
  ASSERT_EQ(out.estimates.size(), 2u);
  EXPECT_NEAR(out.estimates[1].time, 1.2, 1e-12);
}

TEST(FusionCoreStamps, ADelayedValueCountsForThePeriodOfItsStamp) {
  Collector out;
  Core core = makeStartedCore(out);
  core.advanceTo(1.12, out);
  EXPECT_EQ(core.addMeasurement(0, 1.12, 3.0, std::nullopt, 1.08), Rejection::None);
  core.advanceTo(1.15, out);
  Train reference = makeTrain();
  reference.estimate(speedOnly(3.0));
  expectSameBelief(out.estimates.at(0), reference);
  EXPECT_EQ(out.estimates[0].presentInputs, 1);
}

TEST(FusionCoreStamps, ByArrivalTheSameValueCountsForTheNextPeriod) {
  Collector out;
  Core core = makeStartedCore(out, false);
  core.advanceTo(1.12, out);
  core.addMeasurement(0, 1.12, 3.0, std::nullopt, 1.08);
  core.advanceTo(1.25, out);
  Train reference = makeTrain();
  reference.estimate(Measurement<2>::missing());
  expectSameBelief(out.estimates.at(0), reference);
  reference.estimate(speedOnly(3.0));
  expectSameBelief(out.estimates.at(1), reference);
}

TEST(FusionCoreStamps, AValueStampedInAnEstimatedPeriodIsDroppedAndCounted) {
  Collector out;
  Core core = makeStartedCore(out);
  core.advanceTo(1.16, out);  // period 1 ([1.0, 1.1)) is estimated
  EXPECT_EQ(core.addMeasurement(0, 1.16, 3.0, std::nullopt, 1.09), Rejection::TooLate);
  EXPECT_EQ(core.counters(0).late, 1u);
  EXPECT_EQ(core.counters(0).dropped(), 1u);
  // Stamped in the open period 2: accepted.
  EXPECT_EQ(core.addMeasurement(0, 1.16, 3.0, std::nullopt, 1.11), Rejection::None);
  core.advanceTo(1.25, out);
  EXPECT_EQ(core.counters(0).used, 1u);
}

TEST(FusionCoreStamps, WithoutLagAValueStampedBeforeTheBoundaryIsLate) {
  Core::Options options;
  options.period = kPeriod;
  options.inputs.resize(2);
  options.inputs[0].alignByStamp = true;
  Core core(makeTrain(), options);
  Collector out;
  core.advanceTo(1.0, out);
  core.advanceTo(1.101, out);
  EXPECT_EQ(core.addMeasurement(0, 1.101, 3.0, std::nullopt, 1.099), Rejection::TooLate);
}

TEST(FusionCoreStamps, InputsByArrivalUseThePeriodTheyArriveIn) {
  Collector out;
  Core core = makeStartedCore(out);
  core.advanceTo(1.12, out);
  core.addMeasurement(1, 1.12, 0.7, std::nullopt, 1.05);  // input 1 is aligned by arrival
  core.advanceTo(1.25, out);
  Train reference = makeTrain();
  reference.estimate(Measurement<2>::missing());
  expectSameBelief(out.estimates.at(0), reference);
  reference.estimate(accelerationOnly(0.7));
  expectSameBelief(out.estimates.at(1), reference);
}

TEST(FusionCoreStamps, ControlsApplyFromThePeriodTheyArriveIn) {
  Collector out;
  Core core = makeStartedCore(out);
  core.advanceTo(1.08, out);
  core.addControl(0, 1.0);  // period 1
  core.advanceTo(1.12, out);
  core.addControl(0, 5.0);  // period 2: period 1, estimated at 1.15, still uses 1
  core.advanceTo(1.25, out);
  ASSERT_EQ(out.estimates.size(), 2u);
  Train reference = makeTrain();
  reference.setControl(Vector<1>(1.0));
  reference.estimate(Measurement<2>::missing());
  expectSameBelief(out.estimates[0], reference);
  reference.setControl(Vector<1>(5.0));
  reference.estimate(Measurement<2>::missing());
  expectSameBelief(out.estimates[1], reference);
}

TEST(FusionCoreStamps, AStampBeyondTheOpenPeriodsIsUsedInTheNewestAndCounted) {
  // Without room for queued periods: floor(0.05 / 0.1) + 3 = 3 slots, rounded up to 4: open
  // periods 1 to 4 ([1.3, 1.4)). (With the default 1000 the stamp keeps its own period.)
  Collector out;
  Core core = makeStartedCore(out, true, 0);
  core.advanceTo(1.12, out);
  EXPECT_EQ(core.addMeasurement(0, 1.12, 3.0, std::nullopt, 7.0), Rejection::None);
  EXPECT_EQ(core.counters(0).aheadOfClock, 1u);
  core.advanceTo(1.45, out);
  ASSERT_EQ(out.estimates.size(), 4u);
  for (int k = 0; k < 3; ++k) EXPECT_EQ(out.estimates[k].presentInputs, 0) << k;
  EXPECT_EQ(out.estimates[3].presentInputs, 1);
}

TEST(FusionCoreStamps, AStampAheadOfTheClockWithinTheOpenPeriodsKeepsItsPeriod) {
  Collector out;
  Core core = makeStartedCore(out);
  core.advanceTo(1.12, out);
  EXPECT_EQ(core.addMeasurement(0, 1.12, 3.0, std::nullopt, 1.27), Rejection::None);  // period 3
  EXPECT_EQ(core.counters(0).aheadOfClock, 0u);
  core.advanceTo(1.35, out);
  ASSERT_EQ(out.estimates.size(), 3u);
  EXPECT_EQ(out.estimates[1].presentInputs, 0);
  EXPECT_EQ(out.estimates[2].presentInputs, 1);
}

TEST(FusionCoreStamps, AMessageWithoutStampFallsBackToItsArrival) {
  Collector out;
  Core core = makeStartedCore(out);
  core.advanceTo(1.12, out);
  core.addMeasurement(0, 1.12, 3.0);  // NaN stamp: period 2 by arrival
  core.advanceTo(1.25, out);
  EXPECT_EQ(out.estimates.at(0).presentInputs, 0);
  EXPECT_EQ(out.estimates.at(1).presentInputs, 1);
}

TEST(FusionCoreStamps, TimeRunningBackwardsRestartsOneLagBeforeTheNewTime) {
  Collector out;
  Core core = makeStartedCore(out);
  core.advanceTo(1.12, out);
  core.addMeasurement(0, 1.12, 3.0, std::nullopt, 1.11);
  core.advanceTo(1.5, out);
  EXPECT_EQ(core.advanceTo(0.35, out), sf_filter::ClockEvent::JumpedBackwards);
  out.estimates.clear();
  core.advanceTo(0.45, out);
  ASSERT_EQ(out.estimates.size(), 1u);
  EXPECT_NEAR(out.estimates[0].time, 0.4, 1e-12);
  // Stamps restart too: an older stamp than before the jump is accepted.
  EXPECT_EQ(core.addMeasurement(0, 0.46, 1.0, std::nullopt, 0.41), Rejection::None);
}

TEST(FusionCoreStamps, RefusesANegativeOrNonFiniteLag) {
  Core::Options options;
  options.period = kPeriod;
  options.maxMeasurementLag = -0.01;
  EXPECT_THROW(Core(makeTrain(), options), estimation::ParameterError);
  options.maxMeasurementLag = std::numeric_limits<double>::infinity();
  EXPECT_THROW(Core(makeTrain(), options), estimation::ParameterError);
}

/// The speed input without stamps at 10 Hz, sent 41 ms into each period (as the Pioneer's
/// wheels, 40-43 ms into the bag's 100 ms cycle), value 1 + j / 2 in period j, and the
/// acceleration 0 stamped at 100 Hz (as its IMU), with the clock read every 2 ms (rosbag
/// play's /clock at 1 kHz, -r 2). A value arrives at the first reading after it was sent;
/// while the node stalls (readings after a stall's start and before its end) nothing is read,
/// and what was sent meanwhile arrives after the reading at its end, as roscpp receives it
/// after the jumped /clock (the acceleration first). The speed value of period `skipped` is
/// never sent. The schedule starts one lag before the first reading (0 s): with the lag 0.3 s
/// three periods without values come first. The estimates up to the end of the speeds'
/// `periods` (1 s).
struct CadenceRun {
  bool cadence = true;
  double lag = 0.3;
  std::vector<std::pair<double, double>> stalls{{0.62, 0.82}};
  int skipped = -1;
  int periods = 10;
};

std::vector<Core::Estimate> runCadence(const CadenceRun& run,
                                       sf_filter::InputCounters* speedCounters = nullptr) {
  Core::Options options;
  options.period = kPeriod;
  options.maxMeasurementLag = run.lag;
  options.unstampedCadence = run.cadence;
  Core core(makeTrain(), options);
  Collector out;
  int speeds = 0, accelerations = 0;
  std::vector<std::pair<int, double>> backlog;  // (input, stamp or speed value)
  const double end = 0.1 * run.periods + 0.002 + run.lag;
  for (int step = 0; step <= static_cast<int>(std::lround(end / 0.002)); ++step) {
    const double t = 0.002 * step;
    for (; 0.005 + 0.01 * accelerations <= t; ++accelerations) {
      backlog.emplace_back(1, 0.005 + 0.01 * accelerations);
    }
    for (; speeds < run.periods && 0.041 + 0.1 * speeds <= t; ++speeds) {
      if (speeds != run.skipped) backlog.emplace_back(0, 1.0 + 0.5 * speeds);
    }
    if (std::any_of(run.stalls.begin(), run.stalls.end(),
                    [t](const auto& s) { return t > s.first && t < s.second; })) {
      continue;
    }
    core.advanceTo(t, out);
    std::stable_partition(backlog.begin(), backlog.end(),
                          [](const auto& v) { return v.first == 1; });
    for (const auto& [input, v] : backlog) {
      const Rejection r = input == 1 ? core.addMeasurement(1, t, 0.0, std::nullopt, v)
                                     : core.addMeasurement(0, t, v);
      EXPECT_EQ(r, Rejection::None);
    }
    backlog.clear();
  }
  if (speedCounters) *speedCounters = core.counters(0);
  return out.estimates;
}

constexpr std::size_t kEmpty = 3;  // the periods ending at -0.2, -0.1 and 0 s

/// Checks the first `count` estimates of a cadence run, which start with the kEmpty periods
/// of the lag before the first reading: estimate k against the train stepped by hand with
/// measurementOf(j) in period j = k - kEmpty (the missing measurement while j < 0), in time
/// (the period's end, 0.1 * (j + 1) s) and belief.

template <class MeasurementOf>
void expectHandSteppedTrain(const std::vector<Core::Estimate>& estimates, std::size_t count,
                            MeasurementOf measurementOf) {
  ASSERT_GE(estimates.size(), count);
  Train reference = makeTrain();
  for (std::size_t k = 0; k < count; ++k) {
    const double j = static_cast<double>(k) - static_cast<double>(kEmpty);
    reference.estimate(k < kEmpty ? Measurement<2>::missing() : measurementOf(j));
    EXPECT_NEAR(estimates[k].time, 0.1 * (j + 1.0), 1e-9) << k;
    expectSameBelief(estimates[k], reference);
  }
}

// Issue 38 D10: a node stalled under load read an unstamped value after roscpp's clock had
// jumped past the period it was sent in; placed at its arrival it joined the next period's
// value (AVERAGE merged them) and its own period had none. Placed by its input's cadence (the
// 100 ms its values came at; the acceleration, delivered until the stall and not during it,
// vouches for the stall), each value counts for the period it was sent in, as in the offline
// replay: the reference is the train given the speed 1 + j / 2 in every period j, with the
// acceleration 0 except in the period the stall covers whole ([0.7, 0.8) s), whose
// accelerations arrived (by arrival) in the period after the stall.
TEST(FusionCoreStamps, AnUnstampedValueReadAfterAClockJumpGoesWhereItsCadencePutsIt) {
  CadenceRun run;
  run.cadence = false;
  const std::vector<Core::Estimate> atArrival = runCadence(run);
  ASSERT_EQ(atArrival.size(), kEmpty + 10);
  // the defect this test is about: the speeds of [0.6, 0.7) and [0.7, 0.8) s both missing
  EXPECT_EQ(atArrival[kEmpty + 6].presentInputs, 1);  // the acceleration read at 0.62 s
  EXPECT_EQ(atArrival[kEmpty + 7].presentInputs, 0);
  run.cadence = true;
  const std::vector<Core::Estimate> estimates = runCadence(run);
  ASSERT_EQ(estimates.size(), kEmpty + 10);
  expectHandSteppedTrain(estimates, estimates.size(), [](double j) {
    return j == 7.0 ? speedOnly(1.0 + 0.5 * j) : speedAndAcceleration(1.0 + 0.5 * j, 0.0);
  });
}

// Issue 38 D10, round seven: a stall longer than the lag (0.5 s here, from 0.45 s: as the node
// stalled 0.43-0.65 s of bag time beside stress-ng) estimated the period of the first value
// of the backlog before it was read, and that value kept its arrival. The cadence then went on
// from the arrival, so the backlog's later values, whose periods were still open, were
// placed at their arrival too: three periods without a speed. The cadence goes on from the
// predicted time instead, and each of them counts for the period it was sent in; the reference
// is the train stepped by hand up to the period before the stall's end, where the value of
// [0.5, 0.6) s joined the arrival's (as before).
TEST(FusionCoreStamps, AfterAStallLongerThanTheLagTheBacklogStillGoesWhereItsCadencePutsIt) {
  CadenceRun run;
  run.stalls = {{0.45, 0.95}};
  const std::vector<Core::Estimate> estimates = runCadence(run);
  ASSERT_EQ(estimates.size(), kEmpty + 10);
  expectHandSteppedTrain(estimates, kEmpty + 9, [](double j) {
    return j == 5.0  ? Measurement<2>::missing()
           : j > 5.0 ? speedOnly(1.0 + 0.5 * j)
                     : speedAndAcceleration(1.0 + 0.5 * j, 0.0);
  });
}

// Issue 38 D10, round eight: the cadence was the median of the last eight arrival intervals.
// A stall's value arrives late and the next one on time, a long and a short interval: four
// stalls of 80 ms, one every 200 ms (a traced run beside stress-ng had four of 0.15-0.29 s of
// bag time within 2.3 s), each delaying a speed value 68 ms, left 0.168 s and 0.032 s four
// times in the window, and the median (the upper of the middle two) was 0.168 s. The value of
// period 13, delayed 68 ms as well, was then predicted at 1.242 + 0.168 s, its own arrival
// 1.41 s: it kept that arrival and joined the next period's value. From the times the values
// were sent every interval is 0.1 s, and each value counts for the period it was sent in: the
// reference is the train given the speed 1 + j / 2 and the acceleration 0 in every period j
// (no stall covers a period whole).
TEST(FusionCoreStamps, StallsDoNotStretchTheCadence) {
  CadenceRun run;
  run.periods = 15;
  run.stalls = {{0.53, 0.61}, {0.73, 0.81}, {0.93, 1.01}, {1.13, 1.21}, {1.33, 1.41}};
  const std::vector<Core::Estimate> estimates = runCadence(run);
  ASSERT_EQ(estimates.size(), kEmpty + 15);
  for (std::size_t k = 0; k < estimates.size(); ++k) {
    EXPECT_EQ(estimates[k].presentInputs, k < kEmpty ? 0 : 2) << k;
  }
  expectHandSteppedTrain(estimates, estimates.size(),
                         [](double j) { return speedAndAcceleration(1.0 + 0.5 * j, 0.0); });
}

// The cadence moves nothing when the evidence is missing: a value the sensor skipped (the
// 200 ms gap at 21.64 s of bags/pioneer_seed1.bag's wheels) while the acceleration kept
// arriving, and a stall longer than the lag (the period of the prediction already estimated).
// The estimates are those of the values placed at their arrival.
TEST(FusionCoreStamps, ASkippedValueOrAnEstimatedPeriodKeepsTheArrival) {
  CadenceRun skipped;
  skipped.stalls.clear();
  skipped.skipped = 5;
  CadenceRun beyondLag;
  beyondLag.lag = 0.0;
  for (CadenceRun run : {skipped, beyondLag}) {
    const std::vector<Core::Estimate> estimates = runCadence(run);
    run.cadence = false;
    const std::vector<Core::Estimate> atArrival = runCadence(run);
    ASSERT_EQ(estimates.size(), atArrival.size());
    for (std::size_t k = 0; k < estimates.size(); ++k) {
      EXPECT_EQ(estimates[k].state, atArrival[k].state) << k;
    }
  }
}

// Issue 38 D10, round nine: where a stall kept an unstamped value at its arrival, a period
// after the one it was sent in, the estimates from that period on may differ from the offline
// replay's, and the node says so (InputCounters::placedLate, firstPlacedLate in /diagnostics:
// the online test holds the equality with the replay only before it). The stall of 0.62-0.82
// s delays the speeds sent at 0.641 and 0.741 s past their periods' ends; by hand the cadence
// (every 0.1 s from the previous value, read at 0.542 s: the first reading after it was sent)
// predicts 0.642 s for the first. Counted:
// both, without the cadence placement (a header's node) and with it when the lag (0) let their
// periods be estimated; neither when the lag kept them open; none without a stall, nor for a
// value the sensor skipped while the acceleration kept arriving.
TEST(FusionCoreStamps, AValueAStallKeptAfterItsPeriodIsReported) {
  CadenceRun placed;
  CadenceRun atArrival;
  atArrival.cadence = false;
  CadenceRun beyondLag;
  beyondLag.lag = 0.0;
  for (const CadenceRun& run : {atArrival, beyondLag}) {
    sf_filter::InputCounters c;
    runCadence(run, &c);
    EXPECT_EQ(c.placedLate, 2u) << run.cadence << " " << run.lag;
    EXPECT_NEAR(c.firstPlacedLate, 0.642, 1e-9) << run.cadence << " " << run.lag;
  }
  CadenceRun noStall;
  noStall.cadence = false;
  noStall.stalls.clear();
  CadenceRun skipped = noStall;
  skipped.skipped = 5;
  for (const CadenceRun& run : {placed, noStall, skipped}) {
    sf_filter::InputCounters c;
    runCadence(run, &c);
    EXPECT_EQ(c.placedLate, 0u) << run.cadence << " " << run.skipped;
    EXPECT_TRUE(std::isnan(c.firstPlacedLate));
  }
}

}  // namespace
