// Unit tests of the ROS-free fusion core: temporal alignment by averaging, missing inputs,
// controls, the fixed-rate schedule, time jumps and dropped values. The reference is the
// same Kalman filter stepped by hand with the measurement the thesis's alignment defines.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <iomanip>
#include <limits>
#include <string>
#include <vector>

#include "sf_filter/core/message_arrival.hpp"
#include "sf_filter/core/period_schedule.hpp"
#include "train_core.hpp"

namespace {

using namespace train_core;

TEST(FusionCore, AveragesTheValuesOfAPeriodAndMarksSilentInputsMissing) {
  Core core = makeCore();
  Collector out;
  core.advanceTo(0.0, out);
  for (double t : {0.01, 0.03, 0.05}) core.advanceTo(t, out);
  core.addMeasurement(0, 0.01, 1.0);
  core.addMeasurement(0, 0.03, 2.0);
  core.addMeasurement(0, 0.05, 6.0);
  core.advanceTo(0.1, out);
  ASSERT_EQ(out.estimates.size(), 1u);
  EXPECT_DOUBLE_EQ(out.estimates[0].time, 0.1);
  EXPECT_EQ(out.estimates[0].presentInputs, 1);

  // Reference: the mean (1 + 2 + 6) / 3 = 3 for the speed, the acceleration missing.
  Train reference = makeTrain();
  Measurement<2> z;
  z.value << 3.0, 0.0;
  z.available << true, false;
  reference.estimate(z);
  EXPECT_TRUE(out.estimates[0].state.isApprox(reference.state(), 1e-14));
  EXPECT_TRUE(out.estimates[0].covariance.isApprox(reference.covariance(), 1e-14));
  EXPECT_EQ(core.counters(0).used, 3u);
  EXPECT_EQ(core.counters(1).used, 0u);
}

TEST(FusionCore, APeriodWithoutValuesIsATimeUpdateOnly) {
  Core core = makeCore();
  Collector out;
  core.advanceTo(0.0, out);
  core.advanceTo(0.1, out);
  Train reference = makeTrain();
  reference.estimate(Measurement<2>::missing());
  ASSERT_EQ(out.estimates.size(), 1u);
  EXPECT_TRUE(out.estimates[0].state.isApprox(reference.state()));
  // P = A I A^T + Q: [[1 + 0.01 + 0.01, 0.1], [0.1, 1.01]]
  EXPECT_NEAR(out.estimates[0].covariance(0, 0), 1.02, 1e-14);
  EXPECT_NEAR(out.estimates[0].covariance(0, 1), 0.1, 1e-14);
  EXPECT_NEAR(out.estimates[0].covariance(1, 1), 1.01, 1e-14);
}

TEST(FusionCore, UsesTheLatestControlValue) {
  Core core = makeCore();
  Collector out;
  core.advanceTo(0.0, out);
  core.addControl(0, 5.0);
  core.addControl(0, 2.0);
  core.advanceTo(0.1, out);
  // x = A 0 + B u = (2, 0): no measurement, so the prediction is the estimate.
  EXPECT_DOUBLE_EQ(out.estimates.at(0).state(0), 2.0);
  EXPECT_DOUBLE_EQ(out.estimates.at(0).state(1), 0.0);
  // The control persists into later periods until a new one arrives.
  core.advanceTo(0.2, out);
  EXPECT_DOUBLE_EQ(out.estimates.at(1).state(0), 4.0);
}

TEST(FusionCore, KeepsAFixedRateScheduleWithoutDrift) {
  Core core = makeCore();
  Collector out;
  core.advanceTo(10.0, out);
  // Late wake-ups must not shift later period ends.
  core.advanceTo(10.137, out);
  core.advanceTo(10.35, out);
  core.advanceTo(10.4, out);
  ASSERT_EQ(out.estimates.size(), 4u);
  for (std::size_t k = 0; k < out.estimates.size(); ++k) {
    EXPECT_NEAR(out.estimates[k].time, 10.0 + 0.1 * static_cast<double>(k + 1), 1e-12);
  }
}

TEST(FusionCore, TimeRunningBackwardsResetsTheFilter) {
  Core core = makeCore();
  Collector out;
  core.advanceTo(0.0, out);
  core.addMeasurement(0, 0.05, 4.0);
  core.advanceTo(0.3, out);
  EXPECT_NE(core.lastEstimate().state(0), 0.0);
  EXPECT_EQ(core.advanceTo(0.05, out), sf_filter::ClockEvent::JumpedBackwards);
  EXPECT_EQ(core.clockResets(), 1u);
  EXPECT_EQ(core.lastEstimate().state, Vector<2>::Zero());
  EXPECT_EQ(core.lastEstimate().covariance, (Matrix<2, 2>::Identity()));
  // The schedule restarts at the new time.
  out.estimates.clear();
  core.advanceTo(0.15, out);
  ASSERT_EQ(out.estimates.size(), 1u);
  EXPECT_NEAR(out.estimates[0].time, 0.15, 1e-12);
}

TEST(FusionCore, AMessageReceivedBeforeRoscppHadAClockIsNoJumpBackwards) {
  // An online soccer run (CI, 2026-12-03): the node's /clock subscription started the schedule
  // at the bag's first instant while roscpp's own clock, on another thread, still read 0; a
  // message received then has receipt time 0 and the clock reads 0. Taken as the reading, 0 is
  // time running backwards (the filter reset, its WARN throttled away at time 0).
  const double t0 = 1.7e9;
  for (const bool throughArrival : {false, true}) {
    Core::Options options;
    options.period = 0.001;
    Core core(makeTrain(), options);
    Collector out;
    ASSERT_EQ(core.advanceTo(t0, out), sf_filter::ClockEvent::Started);
    const double reading = throughArrival ? sf_filter::messageArrival(0.0, 0.0, core.clock()) : 0.0;
    const sf_filter::ClockEvent event = core.advanceTo(reading, out);
    if (!throughArrival) {
      EXPECT_EQ(event, sf_filter::ClockEvent::JumpedBackwards) << "the defect this test is about";
      continue;
    }
    EXPECT_EQ(reading, t0);
    EXPECT_EQ(event, sf_filter::ClockEvent::Normal);
    EXPECT_EQ(core.clockResets(), 0u);
    core.addMeasurement(0, reading, 4.0);
    EXPECT_EQ(core.advanceTo(t0 + 0.001, out), sf_filter::ClockEvent::Normal);
    ASSERT_EQ(out.estimates.size(), 1u);
    EXPECT_EQ(out.estimates[0].presentInputs, 1);
  }
}

TEST(MessageArrival, IsTheReceiptTimeElseTheClockNeverBeforeTheCoresClock) {
  EXPECT_EQ(sf_filter::messageArrival(12.5, 13.0, 12.0), 12.5);  // receipt time
  EXPECT_EQ(sf_filter::messageArrival(0.0, 13.0, 12.0), 13.0);   // no receipt time: the clock
  EXPECT_EQ(sf_filter::messageArrival(11.0, 13.0, 12.0), 12.0);  // behind a clock reading
  EXPECT_EQ(sf_filter::messageArrival(0.0, 0.0, 12.0), 12.0);    // no valid clock yet
}

TEST(FusionCore, TwoMessagesAtAPeriodEndAreNoJumpBackwards) {
  // ROS times near 1.7e9 s resolve to 2.4e-7 s. With a 1 ms period starting at 1.7e9 s the
  // start of period 51, computed as its end minus the period, rounds above the end of period
  // 50: (t0 + 51 p) - p > t0 + 50 p. A second message at that end (two sensors sampled at the
  // same instant, or one message and the replay's bag clock) must not reset the filter.
  Core::Options options;
  options.period = 0.001;
  Core core(makeTrain(), options);
  Collector out;
  const double t0 = 1.7e9;
  const double end50 = t0 + 50 * 0.001;
  ASSERT_GT((t0 + 51 * 0.001) - 0.001, end50) << "the rounding this test is about";
  core.advanceTo(t0, out);
  EXPECT_EQ(core.advanceTo(end50, out), sf_filter::ClockEvent::Normal);
  core.addMeasurement(0, end50, 4.0);
  EXPECT_EQ(core.advanceTo(end50, out), sf_filter::ClockEvent::Normal);
  core.addMeasurement(1, end50, 1.0);
  EXPECT_EQ(core.clockResets(), 0u);
  ASSERT_EQ(out.estimates.size(), 50u);
  // Both values belong to period 51.
  core.advanceTo(t0 + 51 * 0.001, out);
  ASSERT_EQ(out.estimates.size(), 51u);
  EXPECT_EQ(out.estimates.back().presentInputs, 2);
  // A real jump back, by more than the tolerance, still resets.
  EXPECT_EQ(core.advanceTo(end50 - 1e-5, out), sf_filter::ClockEvent::JumpedBackwards);
}

/// A ROS time as ros::Time::toSec() gives it.
double rosSeconds(std::uint32_t sec, std::uint32_t nsec) {
  return static_cast<double>(sec) + 1e-9 * static_cast<double>(nsec);
}

/// The clock readings of the online runs of launch/soccer_fusion_block.launch whose nodes
/// reset (logged there): the schedule starts at the bag's first instant, the /clock rosbag
/// play publishes during its -d delay; readings every millisecond (mid-period, so that only
/// the last one matters) lead to the logged reading, which the timer and a subscription then
/// both pass. With `lag`, the schedule is the lag earlier. Returns what the second one gave.
sf_filter::ClockEvent secondReadingOfTheOnlineReset(double lag, std::uint32_t nsec) {
  Core::Options options;
  options.period = 0.001;
  options.maxMeasurementLag = lag;
  Core core(makeTrain(), options);
  Collector out;
  EXPECT_EQ(core.advanceTo(rosSeconds(1700000000, 0), out), sf_filter::ClockEvent::Started);
  const std::uint64_t last = 4000000000ull + nsec;  // ns since the start
  for (std::uint64_t ns = 500000; ns < last; ns += 1000000) {
    const double reading = rosSeconds(static_cast<std::uint32_t>(1700000000 + ns / 1000000000),
                                      static_cast<std::uint32_t>(ns % 1000000000));
    EXPECT_EQ(core.advanceTo(reading, out), sf_filter::ClockEvent::Normal) << ns << " ns";
  }
  const double t = rosSeconds(1700000004, nsec);
  EXPECT_EQ(core.advanceTo(t, out), sf_filter::ClockEvent::Normal);
  const sf_filter::ClockEvent second = core.advanceTo(t, out);
  EXPECT_EQ(core.clockResets(), second == sf_filter::ClockEvent::JumpedBackwards ? 1u : 0u);
  return second;
}

TEST(FusionCore, TheSameClockReadingTwiceIsNoJumpBackwards) {
  // The readings the nodes logged at their resets: 1700000004.576998915 in vision_kf (no lag)
  // and 1700000004.487999034 in cwa_x (1.5 ms lag). Each lies within the tolerance (1 us)
  // below a period's end, which makes it due, but above the start of the next period
  // computed as its end minus the period (rounded 2.4e-7 s higher), so the same reading
  // passed again looked like time running backwards and reset the filter.
  EXPECT_EQ(secondReadingOfTheOnlineReset(0.0, 576998915), sf_filter::ClockEvent::Normal);
  EXPECT_EQ(secondReadingOfTheOnlineReset(0.0015, 487999034), sf_filter::ClockEvent::Normal);
}

TEST(PeriodSchedule, AReadingItAdvancedToIsInTheCurrentPeriodAndNotBefore) {
  // Over many readings near 1.7e9 s with a 1 ms period (jittered within 2 us of the period
  // ends, where the rounding of the ends matters, and anywhere): after advancing by
  // periodsDue(t), t is in the current period, neither due nor before it, and every period
  // estimated had ended by t (by due()'s convention, with the same end times).
  std::uint64_t state = 12345;
  const auto next = [&state] {  // a fixed linear congruential sequence, so the test repeats
    state = state * 6364136223846793005ull + 1442695040888963407ull;
    return state >> 33;
  };
  const double period = 0.001;
  for (int run = 0; run < 20; ++run) {
    sf_filter::PeriodSchedule schedule(period);
    const double start = rosSeconds(1700000000, static_cast<std::uint32_t>(next() % 1000000000));
    schedule.start(start);
    double t = start;
    for (int i = 0; i < 20000; ++i) {
      const std::uint64_t step = next() % 2000000;  // 0 .. 2 ms in ns
      t += 1e-9 * static_cast<double>(step);
      if (i % 2 == 0) {  // near an end of the schedule
        const double k = std::round((t - start) / period);
        const double jittered =
            start + k * period + 1e-9 * (static_cast<double>(next() % 4000) - 2000.0);
        t = std::max(t, jittered);  // a clock does not run backwards
      }
      const std::uint64_t due = schedule.periodsDue(t);
      for (std::uint64_t d = 0; d < due; ++d) {
        ASSERT_TRUE(schedule.due(t)) << "a period counted as due that had not ended";
        schedule.advance();
      }
      ASSERT_FALSE(schedule.due(t)) << std::setprecision(17) << t;
      ASSERT_FALSE(schedule.before(t)) << std::setprecision(17) << t << " after " << due;
      ASSERT_TRUE(schedule.inCurrent(t)) << std::setprecision(17) << t;
      ASSERT_EQ(schedule.indexOf(t), static_cast<std::int64_t>(schedule.index()));
    }
  }
}

TEST(FusionCore, DropsAndCountsNonFiniteValuesAndBadVariances) {
  Core core = makeCore();
  Collector out;
  core.advanceTo(0.0, out);
  EXPECT_EQ(core.addMeasurement(0, 0.01, std::nan("")), sf_filter::Rejection::NonFinite);
  EXPECT_EQ(core.addMeasurement(0, 0.01, std::numeric_limits<double>::infinity()),
            sf_filter::Rejection::NonFinite);
  EXPECT_EQ(core.addMeasurement(1, 0.01, 1.0, 0.0), sf_filter::Rejection::BadVariance);
  EXPECT_EQ(core.addMeasurement(1, 0.01, 1.0, -2.0), sf_filter::Rejection::BadVariance);
  EXPECT_EQ(core.addMeasurement(1, 0.01, 1.0, std::nan("")), sf_filter::Rejection::BadVariance);
  EXPECT_EQ(core.addControl(0, std::nan("")), sf_filter::Rejection::NonFinite);
  core.advanceTo(0.1, out);
  EXPECT_EQ(core.counters(0).nonFinite, 2u);
  EXPECT_EQ(core.counters(1).badVariance, 3u);
  EXPECT_EQ(core.counters(0).dropped() + core.counters(1).dropped(), 5u);
  EXPECT_EQ(core.controlNonFinite(), 1u);
  // Nothing reached the filter: the estimate is the pure time update.
  Train reference = makeTrain();
  reference.estimate(Measurement<2>::missing());
  EXPECT_TRUE(out.estimates.at(0).state.isApprox(reference.state()));
  EXPECT_TRUE(out.estimates.at(0).covariance.isApprox(reference.covariance()));
}

TEST(FusionCore, AMessageVarianceReplacesRForThatPeriod) {
  Core core = makeCore();
  Collector out;
  core.advanceTo(0.0, out);
  core.addMeasurement(1, 0.02, 1.0, 0.04);
  core.addMeasurement(1, 0.04, 3.0, 0.08);
  core.advanceTo(0.1, out);
  // Mean 2 with variance (0.04 + 0.08) / 2^2 = 0.03 instead of R(1,1) = 0.2.
  Train reference = makeTrain();
  Measurement<2> z;
  z.value << 0.0, 2.0;
  z.available << false, true;
  z.varianceGiven << false, true;
  z.variance << 0.0, 0.03;
  reference.estimate(z);
  EXPECT_TRUE(out.estimates.at(0).state.isApprox(reference.state(), 1e-14));
  EXPECT_TRUE(out.estimates.at(0).covariance.isApprox(reference.covariance(), 1e-14));
}

TEST(FusionCore, DropsStampsRunningBackwardsPerInput) {
  Core core = makeCore();
  Collector out;
  core.advanceTo(0.0, out);
  EXPECT_EQ(core.addMeasurement(0, 0.01, 1.0, std::nullopt, 5.0), sf_filter::Rejection::None);
  EXPECT_EQ(core.addMeasurement(0, 0.02, 9.0, std::nullopt, 4.9), sf_filter::Rejection::OutOfOrder);
  // Another input has its own history.
  EXPECT_EQ(core.addMeasurement(1, 0.02, 0.0, std::nullopt, 4.0), sf_filter::Rejection::None);
  core.advanceTo(0.1, out);
  EXPECT_EQ(core.counters(0).outOfOrder, 1u);
  EXPECT_EQ(core.counters(0).used, 1u);
}

TEST(FusionCore, ALongGapIsSkippedWithOneEstimate) {
  Core::Options options;
  options.period = kPeriod;
  options.maxCatchUpPeriods = 10;
  Core core(makeTrain(), options);
  Collector out;
  core.advanceTo(0.0, out);
  EXPECT_EQ(core.advanceTo(100.05, out), sf_filter::ClockEvent::SkippedGap);
  EXPECT_EQ(out.estimates.size(), 1u);
  // The phase is kept: the next period ends at 100.1.
  core.advanceTo(100.1, out);
  ASSERT_EQ(out.estimates.size(), 2u);
  EXPECT_NEAR(out.estimates[1].time, 100.1, 1e-9);
}

TEST(FusionCore, RefusesANonPositivePeriod) {
  Core::Options options;
  options.period = 0.0;
  EXPECT_THROW(Core(makeTrain(), options), estimation::ParameterError);
}

/// The message of the ParameterError the options raise ("" if none).
std::string optionsError(const Core::Options& options) {
  try {
    Core core(makeTrain(), options);
  } catch (const estimation::ParameterError& e) {
    return e.what();
  }
  return "";
}

// The period is bounded to 0.1 ms .. 1 h, refused with the unit named: 1e-6 s (a unit mistake)
// took a full core and flooded the log, 1e13 s never estimated.
TEST(FusionCore, RefusesAPeriodOutside0Point1MsTo1HourNamingTheUnit) {
  Core::Options options;
  for (const double period : {1e-6, 9.9e-5, 3600.5, 1e13, std::nan("")}) {
    options.period = period;
    const std::string error = optionsError(options);
    EXPECT_NE(error.find("from 0.1 ms to 1 h"), std::string::npos) << period << ": " << error;
    EXPECT_NE(error.find(" s"), std::string::npos) << error;
  }
  for (const double period : {1e-4, 0.05, 3600.0}) {
    options.period = period;
    EXPECT_EQ(optionsError(options), "") << period;
  }
  options.period = kPeriod;
  options.maxCatchUpPeriods = 0;
  EXPECT_NE(optionsError(options).find("catch-up"), std::string::npos);
  options.maxCatchUpPeriods = Core::kMaxCatchUpLimit + 1;
  EXPECT_NE(optionsError(options).find("catch-up"), std::string::npos);
}

// A gap of 1.7e9 s (a bag with one message at 1 s and the rest at 1.7e9 s) is crossed with one
// estimate - the prediction of the current period - whatever its length, by advanceTo() and by
// skipGap(), which an adapter stepping through gaps itself calls for a gap too long to step.
TEST(FusionCore, AGapOfAnyLengthCostsOneEstimate) {
  for (const bool explicitSkip : {false, true}) {
    Core core = makeCore();
    Collector out;
    Train reference = makeTrain();
    core.advanceTo(1.0, out);
    core.addMeasurement(0, 1.05, 2.0);
    const double later = 1.7e9 + 0.05;
    // Periods end at 1 + k T; the one holding `later` is k = 17 000 000 000 - 9 (end
    // 1.7e9 + 0.1); all before it are due: 1.7e10 - 10.
    const std::uint64_t due = 16999999990u;
    EXPECT_EQ(core.periodsDue(later), due);
    const auto event = explicitSkip ? core.skipGap(later, out) : core.advanceTo(later, out);
    EXPECT_EQ(event, sf_filter::ClockEvent::SkippedGap);
    ASSERT_EQ(out.estimates.size(), 1u);
    reference.estimate(speedOnly(2.0));  // period 1 with its value
    expectSameBelief(out.estimates[0], reference);
    EXPECT_EQ(core.skippedGaps(), 1u);
    EXPECT_EQ(core.skippedPeriods(), due - 1);
    EXPECT_EQ(core.periodsDue(later), 0u);
    // The phase is kept: the next period ends at 1.7e9 + 0.1.
    core.advanceTo(1.7e9 + 0.1, out);
    ASSERT_EQ(out.estimates.size(), 2u);
    EXPECT_NEAR(out.estimates[1].time, 1.7e9 + 0.1, 1e-6);
  }
}

// Issue 15 R3: rosbag play on a loaded machine falls behind and then publishes its messages
// without /clock until it has caught up, so the node's clock stands still at 0 while 16 s of
// stamped values arrive, and then jumps 160 periods (more than maxCatchUpPeriods = 100). The
// stamps stand in for the stalled clock: each value is queued in its own period and the jump
// estimates the 160 periods one by one, as the offline replay of the recording does (its clock
// is the recorded time). Reference: the Kalman filter stepped by hand with each period's pair.
// Before, every value went into the period of its arrival (the first) and the jump cost one
// estimate, their average; with the node's 0.5 s tolerance the values more than 0.5 s ahead
// of the clock were even dropped as future stamps.
TEST(FusionCore, AStalledClockEstimatesTheQueuedPeriodsWhenItJumps) {
  Core::Options options;
  options.period = kPeriod;
  options.maxFutureStamp = 0.5;  // the node's default
  Core core(makeTrain(), options);
  Collector out;
  core.advanceTo(0.0, out);
  constexpr int kPeriods = 160;  // 16 s
  auto speed = [](int k) { return 0.1 * k; };
  auto acceleration = [](int k) { return 1.0 + 0.01 * k; };
  for (int k = 0; k < kPeriods; ++k) {
    core.advanceTo(0.0, out);  // the node reads the stalled clock at every message
    EXPECT_EQ(core.addMeasurement(0, 0.0, speed(k), std::nullopt, kPeriod * k + 0.05),
              sf_filter::Rejection::None);
    EXPECT_EQ(core.addMeasurement(1, 0.0, acceleration(k), std::nullopt, kPeriod * k + 0.06),
              sf_filter::Rejection::None);
  }
  EXPECT_TRUE(out.estimates.empty());
  EXPECT_EQ(core.queuedAhead(), static_cast<std::uint64_t>(kPeriods - 1));
  EXPECT_EQ(core.advanceTo(16.0, out), sf_filter::ClockEvent::Normal);
  ASSERT_EQ(out.estimates.size(), static_cast<std::size_t>(kPeriods));
  Train reference = makeTrain();
  for (int k = 0; k < kPeriods; ++k) {
    reference.estimate(speedAndAcceleration(speed(k), acceleration(k)));
    EXPECT_NEAR(out.estimates[k].time, kPeriod * (k + 1), 1e-9);
    expectSameBelief(out.estimates[k], reference);
  }
  EXPECT_EQ(core.skippedGaps(), 0u);
  EXPECT_EQ(core.counters(0).used, static_cast<std::uint64_t>(kPeriods));
  EXPECT_EQ(core.counters(0).future, 0u);
}

// The limits of R3. One input alone whose stamps run ahead is a sensor clock running ahead,
// not a stalled clock: its values stay where they arrive, and it cannot carry itself further
// ahead (only another input's stamps vouch for a stalled clock), so its values more than
// maxFutureStamp ahead are dropped as before. Once the clock moves again it is the time: the
// stamps that stood in for it no longer move the values arriving. Beyond the ring's capacity
// (maxQueuedPeriods) values go into its last period and the rest of the gap is skipped with one
// estimate.
TEST(FusionCore, StampsStandInForTheClockOnlyWhileItStandsStillAndWithinTheRing) {
  Core::Options options;
  options.period = kPeriod;
  options.maxFutureStamp = 0.5;
  {
    Core core(makeTrain(), options);
    Collector out;
    core.advanceTo(0.0, out);
    EXPECT_EQ(core.addMeasurement(0, 0.0, 1.0, std::nullopt, 0.4), sf_filter::Rejection::None);
    EXPECT_EQ(core.addMeasurement(0, 0.0, 1.0, std::nullopt, 0.8),
              sf_filter::Rejection::FutureStamp);
  }
  {
    Core core(makeTrain(), options);
    Collector out;
    core.advanceTo(0.0, out);
    core.advanceTo(0.01, out);
    core.addMeasurement(1, 0.01, 0.5, std::nullopt, 0.31);  // a sensor clock 0.3 s fast
    core.advanceTo(0.02, out);
    core.addMeasurement(0, 0.02, 2.0);
    core.advanceTo(0.1, out);
    ASSERT_EQ(out.estimates.size(), 1u);
    Train reference = makeTrain();
    reference.estimate(speedAndAcceleration(2.0, 0.5));  // both in period 1, where they arrived
    expectSameBelief(out.estimates[0], reference);
  }
  {
    Core core(makeTrain(), options);
    Collector out;
    core.advanceTo(0.0, out);
    // The clock stands still: the first stamp ahead (one input alone) stays where it arrives,
    // the second input's stamp ahead says that the clock stalls, and its value is queued.
    core.addMeasurement(1, 0.0, 0.5, std::nullopt, 0.21);  // period 1
    core.addMeasurement(0, 0.0, 1.0, std::nullopt, 0.25);  // period 3
    core.advanceTo(0.02, out);                             // the clock moves again
    core.addMeasurement(0, 0.02, 2.0);                     // period 1, not 3
    core.advanceTo(0.3, out);
    ASSERT_EQ(out.estimates.size(), 3u);
    Train reference = makeTrain();
    reference.estimate(speedAndAcceleration(2.0, 0.5));
    expectSameBelief(out.estimates[0], reference);
    reference.estimate(Measurement<2>::missing());
    reference.estimate(speedOnly(1.0));
    expectSameBelief(out.estimates[2], reference);
  }
  {
    options.maxQueuedPeriods = 20;
    Core core(makeTrain(), options);
    Collector out;
    core.advanceTo(0.0, out);
    for (int k = 0; k < 160; ++k) {
      core.addMeasurement(0, 0.0, 1.0, std::nullopt, kPeriod * k + 0.05);
      core.addMeasurement(1, 0.0, 0.0, std::nullopt, kPeriod * k + 0.06);
    }
    // The ring holds the current period and 20 + 3 more (32 slots: 31 after the current).
    const std::uint64_t queued = core.queuedAhead();
    EXPECT_GE(queued, 20u);
    EXPECT_LT(queued, 160u);
    EXPECT_EQ(core.advanceTo(16.0, out), sf_filter::ClockEvent::SkippedGap);
    EXPECT_EQ(out.estimates.size(), queued + 1);
    EXPECT_EQ(core.skippedGaps(), 1u);
    EXPECT_EQ(core.skippedPeriods(), 160u - queued - 1);
    EXPECT_EQ(core.counters(0).aheadOfClock, 160u - queued - 1);
  }
}

}  // namespace
