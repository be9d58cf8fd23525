// Unit tests of the fusion core's fault handling (doc/reliability.md): sensor timeouts (the
// input is missing every period, HOLD stops substituting and forgets its history, the filter
// recovers when values return), the plausible range, stamps that are duplicated, far in the
// future, out of order or jump back with the clock, an outlier burst against the Mahalanobis
// gate with a stated error bound, and the NIS consistency check against chi-square bounds.
// References: the library's Kalman filter stepped by hand on the values that should reach it,
// the chi-square tables, and a simulated train with known Q and R.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <optional>
#include <random>
#include <vector>

#include "sf_filter/core/innovation_record.hpp"
#include "sf_filter/core/nis_window.hpp"
#include "train_core.hpp"

namespace {

using namespace train_core;
using sf_filter::AlignmentPolicy;
using sf_filter::HoldPrimitive;
using sf_filter::InputOptions;
using sf_filter::Rejection;

constexpr double kInf = std::numeric_limits<double>::infinity();

Core makeCore(const std::vector<InputOptions>& inputs, std::size_t nisWindow = 0,
              const Matrix<2, 2>& R = trainR(), double maxFutureStamp = kInf) {
  Core::Options options;
  options.period = kPeriod;
  options.inputs = inputs;
  options.nisWindow = nisWindow;
  options.maxFutureStamp = maxFutureStamp;
  return Core(makeTrain(R), options);
}

std::vector<InputOptions> speedTimeout(double timeout) {
  std::vector<InputOptions> inputs(2);
  inputs[0].timeout = timeout;
  return inputs;
}

// --- sensor timeout ---------------------------------------------------------------------------

TEST(FusionCoreFaults, ASilentInputTimesOutAndTheFilterRecoversWhenItReturns) {
  Core core = makeCore(speedTimeout(0.3));
  Collector out;
  Train reference = makeTrain();
  core.advanceTo(0.0, out);
  // Periods 1-10: a speed of 1 in each; 11-20: silent; 21-30: back.
  for (int k = 1; k <= 30; ++k) {
    const bool silent = k > 10 && k <= 20;
    if (!silent) {
      EXPECT_EQ(core.addMeasurement(0, (k - 1) * kPeriod + 0.05, 1.0), Rejection::None);
    }
    core.advanceTo(k * kPeriod, out);
    reference.estimate(silent ? Measurement<2>::missing() : speedOnly(1.0));
    expectSameBelief(out.estimates.back(), reference);
    // The last value arrived at 0.95: timed out once a period ends more than 0.3 s later,
    // from period 13 (end 1.3) to 20.
    EXPECT_EQ(core.timedOut(0, k * kPeriod), k >= 13 && k <= 20) << "period " << k;
    EXPECT_FALSE(core.timedOut(1));  // no timeout configured
  }
  EXPECT_EQ(core.counters(0).timedOutPeriods, 8u);
  // The variance grew while the speedometer was silent and came back down after it returned.
  const auto var = [&](int k) {
    return out.estimates[static_cast<std::size_t>(k - 1)].covariance(0, 0);
  };
  for (int k = 11; k <= 20; ++k) EXPECT_GT(var(k), var(k - 1)) << k;
  EXPECT_LT(var(21), var(20));
  EXPECT_LT(var(30), 1.5 * var(10));
}

TEST(FusionCoreFaults, AnInputThatNeverSpokeTimesOutFromTheStart) {
  Core core = makeCore(speedTimeout(0.25));
  Collector out;
  core.advanceTo(5.0, out);
  core.advanceTo(5.2, out);
  EXPECT_FALSE(core.timedOut(0));
  core.advanceTo(5.3, out);
  EXPECT_TRUE(core.timedOut(0));
  EXPECT_EQ(core.counters(0).timedOutPeriods, 1u);  // period ending at 5.3
}

TEST(FusionCoreFaults, ATimedOutHoldStopsSubstitutingAndStartsAFreshHistory) {
  std::vector<InputOptions> inputs(2);
  inputs[0].alignment = AlignmentPolicy::hold(HoldPrimitive::Lagrange, 1, 0.5);
  inputs[0].timeout = 0.22;
  Core core = makeCore(inputs);
  Collector out;
  Train reference = makeTrain();
  const auto held = [](double v) {
    Measurement<2> z = speedOnly(v, 0.5);
    return z;
  };
  core.advanceTo(0.0, out);
  core.addMeasurement(0, 0.05, 1.0);  // period 1
  core.addMeasurement(0, 0.15, 2.0);  // period 2
  core.advanceTo(0.2, out);
  reference.estimate(speedOnly(1.0));
  reference.estimate(speedOnly(2.0));
  // Period 3 (end 0.3): 0.15 s after the last value, held: the line through (0.05, 1) and
  // (0.15, 2) at 0.3 gives 3.5.
  core.advanceTo(0.3, out);
  reference.estimate(held(3.5));
  expectSameBelief(out.estimates.back(), reference);
  EXPECT_EQ(out.estimates.back().substitutedInputs, 1);
  // Periods 4 and 5 (ends 0.4, 0.5): more than 0.22 s after 0.15: timed out, missing.
  core.advanceTo(0.5, out);
  reference.estimate(Measurement<2>::missing());
  reference.estimate(Measurement<2>::missing());
  expectSameBelief(out.estimates.back(), reference);
  EXPECT_EQ(out.estimates.back().substitutedInputs, 0);
  EXPECT_EQ(core.counters(0).timedOutPeriods, 2u);
  // Back at 0.55 with 3.0 (period 6); period 7 holds from the fresh history alone: a
  // zero-order hold of 3.0, not the line through the stale (0.15, 2) (which gives 3.375).
  core.addMeasurement(0, 0.55, 3.0);
  core.advanceTo(0.7, out);
  reference.estimate(speedOnly(3.0));
  reference.estimate(held(3.0));
  expectSameBelief(out.estimates.back(), reference);
}

TEST(FusionCoreFaults, GarbageValuesDoNotKeepAnInputAlive) {
  std::vector<InputOptions> inputs = speedTimeout(0.25);
  inputs[0].maximum = 10.0;
  Core core = makeCore(inputs);
  Collector out;
  core.advanceTo(0.0, out);
  core.addMeasurement(0, 0.05, 1.0);
  for (int k = 1; k <= 5; ++k) core.addMeasurement(0, 0.05 + 0.1 * k, std::nan(""));
  core.addMeasurement(0, 0.45, 11.0);
  core.advanceTo(0.5, out);
  EXPECT_TRUE(core.timedOut(0));  // received at 0.45, but nothing accepted since 0.05
  EXPECT_EQ(core.counters(0).received, 7u);
  EXPECT_EQ(core.counters(0).dropped(), 6u);
}

// Only a value that reaches the filter keeps an input alive (doc/reliability.md): a HOLD
// input whose sensor goes on publishing values that all fail the gate times out and stops
// extrapolating its last good samples (before, every gated arrival reset the timeout, so the
// hold substituted 1.0 forever while the sensor said 100).
TEST(FusionCoreFaults, GatedValuesDoNotKeepAHoldInputAlive) {
  std::vector<InputOptions> inputs(2);
  inputs[0].alignment = AlignmentPolicy::hold(HoldPrimitive::Lagrange, 0, 0.5);
  inputs[0].gateThreshold = 9.0;
  inputs[0].timeout = 0.3;
  Core core = makeCore(inputs);
  Collector out;
  Train reference = makeTrain();
  core.advanceTo(0.0, out);
  for (int k = 1; k <= 30; ++k) {
    // Periods 1-10: 1.0 (used); 11-30: 100.0, at least 40 sigma away: gated.
    EXPECT_EQ(core.addMeasurement(0, (k - 1) * kPeriod + 0.05, k <= 10 ? 1.0 : 100.0),
              Rejection::None);
    core.advanceTo(k * kPeriod, out);
    // The last used value arrived at 0.95: periods 11 and 12 (ends 1.1, 1.2) hold it with
    // the policy's variance; from period 13 (end 1.3, 0.35 s later) the input is timed out.
    if (k <= 10) {
      reference.estimate(speedOnly(1.0));
    } else if (k <= 12) {
      reference.estimate(speedOnly(1.0, 0.5));
    } else {
      reference.estimate(Measurement<2>::missing());
    }
    expectSameBelief(out.estimates.back(), reference);
    EXPECT_EQ(core.timedOut(0, k * kPeriod), k >= 13) << "period " << k;
  }
  EXPECT_EQ(core.counters(0).gated, 20u);
  EXPECT_EQ(core.counters(0).substituted, 2u);
  EXPECT_EQ(core.counters(0).timedOutPeriods, 18u);
  EXPECT_DOUBLE_EQ(core.counters(0).lastAccepted, 9 * kPeriod + 0.05);
}

// A stamped value too late for its period never reaches the filter: it does not keep the
// input alive either.
TEST(FusionCoreFaults, LateValuesDoNotKeepAnInputAlive) {
  std::vector<InputOptions> inputs = speedTimeout(0.3);
  inputs[0].alignByStamp = true;
  Core core = makeCore(inputs);
  Collector out;
  core.advanceTo(0.0, out);
  EXPECT_EQ(core.addMeasurement(0, 0.05, 1.0, std::nullopt, 0.01), Rejection::None);
  core.advanceTo(0.1, out);
  EXPECT_EQ(core.counters(0).lastAccepted, 0.05);
  // Periods 2-6: each value stamped 0.12 s before its arrival, in a period already estimated.
  for (int k = 2; k <= 6; ++k) {
    const double arrival = (k - 1) * kPeriod + 0.05;
    EXPECT_EQ(core.addMeasurement(0, arrival, 2.0, std::nullopt, arrival - 0.12),
              Rejection::TooLate);
    core.advanceTo(k * kPeriod, out);
    EXPECT_EQ(core.timedOut(0), k * kPeriod - 0.05 > 0.3) << "period " << k;
  }
  EXPECT_EQ(core.counters(0).late, 5u);
  EXPECT_EQ(core.counters(0).lastAccepted, 0.05);
  EXPECT_EQ(core.counters(0).timedOutPeriods, 3u);  // periods 4-6 (ends 0.4 to 0.6)
}

// A finite but huge variance field (1e308): two of them in a period summed to infinity, the
// step failed and the filter restarted every period. Beyond kMaxVariance (1e100) a variance
// is dropped as bad variance; up to it the period's mean variance is exact.
TEST(FusionCoreFaults, AVarianceBeyondTheMaximumIsDroppedAndNeverOverflows) {
  Core core = makeCore({});
  Collector out;
  Train reference = makeTrain();
  core.advanceTo(0.0, out);
  // Period 1: two values of variance 1e308: both dropped, the speed is missing.
  EXPECT_EQ(core.addMeasurement(0, 0.03, 1.0, 1e308), Rejection::BadVariance);
  EXPECT_EQ(core.addMeasurement(0, 0.06, 2.0, 1e308), Rejection::BadVariance);
  core.advanceTo(0.1, out);
  reference.estimate(Measurement<2>::missing());
  expectSameBelief(out.estimates.back(), reference);
  // Period 2: two values of variance 1e100 (the maximum): their mean 1.5 with variance
  // (1e100 + 1e100) / 2^2 = 5e99.
  EXPECT_EQ(core.addMeasurement(0, 0.13, 1.0, 1e100), Rejection::None);
  EXPECT_EQ(core.addMeasurement(0, 0.16, 2.0, 1e100), Rejection::None);
  core.advanceTo(0.2, out);
  reference.estimate(speedOnly(1.5, 5e99));
  expectSameBelief(out.estimates.back(), reference);
  EXPECT_EQ(core.estimationFailures(), 0u);
  EXPECT_EQ(core.counters(0).badVariance, 2u);
  EXPECT_EQ(core.counters(0).used, 2u);
  EXPECT_EQ(core.lastEstimate().presentInputs, 1);
}

// --- plausible range ------------------------------------------------------------------------

TEST(FusionCoreFaults, ValuesOutsideThePlausibleRangeAreDroppedAndCounted) {
  std::vector<InputOptions> inputs(2);
  inputs[0].minimum = -10.0;
  inputs[0].maximum = 10.0;
  Core core = makeCore(inputs);
  Collector out;
  core.advanceTo(0.0, out);
  EXPECT_EQ(core.addMeasurement(0, 0.01, 10.5), Rejection::OutOfRange);
  EXPECT_EQ(core.addMeasurement(0, 0.02, -1e9), Rejection::OutOfRange);
  EXPECT_EQ(core.addMeasurement(0, 0.03, -10.0), Rejection::None);  // the bounds belong to it
  EXPECT_EQ(core.addMeasurement(1, 0.04, 1e9), Rejection::None);    // input 1 has no range
  core.advanceTo(0.1, out);
  EXPECT_EQ(core.counters(0).outOfRange, 2u);
  EXPECT_EQ(core.counters(0).dropped(), 2u);
  EXPECT_EQ(core.counters(0).used, 1u);
  Train reference = makeTrain();
  Measurement<2> z;
  z.value << -10.0, 1e9;
  reference.estimate(z);
  expectSameBelief(out.estimates.at(0), reference);
}

TEST(FusionCoreFaults, RefusesAnEmptyRangeOrANonPositiveTimeout) {
  std::vector<InputOptions> inputs(2);
  inputs[1].minimum = 2.0;
  inputs[1].maximum = 2.0;
  EXPECT_THROW(makeCore(inputs), estimation::ParameterError);
  inputs[1] = InputOptions{};
  inputs[0].timeout = 0.0;
  EXPECT_THROW(makeCore(inputs), estimation::ParameterError);
  inputs[0].timeout = std::nan("");
  EXPECT_THROW(makeCore(inputs), estimation::ParameterError);
}

// --- stamps ---------------------------------------------------------------------------------

TEST(FusionCoreFaults, ADuplicatedStampIsDroppedAndCounted) {
  Core core = makeCore(std::vector<InputOptions>(2));
  Collector out;
  core.advanceTo(0.0, out);
  EXPECT_EQ(core.addMeasurement(0, 0.01, 1.0, std::nullopt, 0.005), Rejection::None);
  EXPECT_EQ(core.addMeasurement(0, 0.02, 5.0, std::nullopt, 0.005), Rejection::DuplicateStamp);
  core.advanceTo(0.1, out);
  EXPECT_EQ(core.counters(0).duplicate, 1u);
  Train reference = makeTrain();
  reference.estimate(speedOnly(1.0));  // the first of the two, not their mean 3
  expectSameBelief(out.estimates.at(0), reference);
}

TEST(FusionCoreFaults, AZeroStampIsTreatedAsNotSet) {
  Core core = makeCore(std::vector<InputOptions>(2));
  Collector out;
  core.advanceTo(0.0, out);
  EXPECT_EQ(core.addMeasurement(0, 0.01, 1.0, std::nullopt, 0.0), Rejection::None);
  EXPECT_EQ(core.addMeasurement(0, 0.02, 3.0, std::nullopt, 0.0), Rejection::None);
  core.advanceTo(0.1, out);
  Train reference = makeTrain();
  reference.estimate(speedOnly(2.0));
  expectSameBelief(out.estimates.at(0), reference);
}

TEST(FusionCoreFaults, AStampFarInTheFutureIsDroppedAndDoesNotBlockTheInput) {
  Core core = makeCore(std::vector<InputOptions>(2), 0, trainR(), 0.5);
  Collector out;
  core.advanceTo(0.0, out);
  EXPECT_EQ(core.addMeasurement(0, 0.01, 1.0, std::nullopt, 0.01 + 0.6), Rejection::FutureStamp);
  EXPECT_EQ(core.addMeasurement(0, 0.02, 2.0, std::nullopt, 0.02 + 0.4), Rejection::None);
  EXPECT_EQ(core.addMeasurement(0, 0.03, 3.0, std::nullopt, 0.43), Rejection::None);
  core.advanceTo(0.1, out);
  EXPECT_EQ(core.counters(0).future, 1u);
  EXPECT_EQ(core.counters(0).used, 2u);
  // Without the check the future stamp is accepted, and blocks the input: every later,
  // correct stamp looks older.
  Core unchecked = makeCore(std::vector<InputOptions>(2));
  unchecked.advanceTo(0.0, out);
  EXPECT_EQ(unchecked.addMeasurement(0, 0.01, 1.0, std::nullopt, 1000.0), Rejection::None);
  EXPECT_EQ(unchecked.addMeasurement(0, 0.02, 2.0, std::nullopt, 0.02), Rejection::OutOfOrder);
}

TEST(FusionCoreFaults, EveryValueIsAccountedFor) {
  std::vector<InputOptions> inputs(2);
  inputs[0].maximum = 5.0;
  inputs[0].alignment = AlignmentPolicy::last();
  Core core = makeCore(inputs, 0, trainR(), 0.5);
  Collector out;
  core.advanceTo(0.0, out);
  double stamp = 0.001;
  for (int k = 0; k < 40; ++k) {
    const double now = 0.01 + 0.025 * k;
    stamp += 0.025;
    switch (k % 8) {
      case 3:
        core.addMeasurement(0, now, std::nan(""));
        break;
      case 4:
        core.addMeasurement(0, now, 1.0, -1.0);
        break;
      case 5:
        core.addMeasurement(0, now, 9.0);
        break;
      case 6:
        core.addMeasurement(0, now, 1.0, std::nullopt, stamp - 1.0);
        break;
      case 7:
        core.addMeasurement(0, now, 1.0, std::nullopt, stamp + 2.0);
        break;
      default:
        core.addMeasurement(0, now, 1.0, std::nullopt, stamp);
        break;
    }
  }
  core.advanceTo(2.0, out);
  const sf_filter::InputCounters& c = core.counters(0);
  EXPECT_EQ(c.nonFinite, 5u);
  EXPECT_EQ(c.badVariance, 5u);
  EXPECT_EQ(c.outOfRange, 5u);
  EXPECT_EQ(c.outOfOrder, 5u);
  EXPECT_EQ(c.future, 5u);
  EXPECT_EQ(c.received, c.used + c.superseded + c.gated + c.dropped());
  EXPECT_EQ(c.used + c.superseded, 15u);
}

TEST(FusionCoreFaults, AClockJumpBackResetsAndTheEstimatesGoOn) {
  Core core = makeCore(speedTimeout(0.35), 10);
  Collector out;
  core.advanceTo(100.0, out);
  for (int k = 1; k <= 20; ++k) {
    core.addMeasurement(0, 100.0 + (k - 1) * kPeriod + 0.05, 1.0, std::nullopt,
                        100.0 + (k - 1) * kPeriod + 0.04);
    core.advanceTo(100.0 + k * kPeriod, out);
  }
  EXPECT_EQ(core.nis().size(), 10u);
  EXPECT_EQ(core.advanceTo(3.0, out), sf_filter::ClockEvent::JumpedBackwards);
  EXPECT_EQ(core.clockResets(), 1u);
  EXPECT_EQ(core.nis().size(), 0u);  // the window belongs to the old run
  out.estimates.clear();
  // The stamps restart with the clock, and the timeout counts from the new start.
  EXPECT_EQ(core.addMeasurement(0, 3.05, 2.0, std::nullopt, 3.04), Rejection::None);
  for (int k = 1; k <= 5; ++k) core.advanceTo(3.0 + k * kPeriod, out);
  ASSERT_EQ(out.estimates.size(), 5u);
  Train reference = makeTrain();
  reference.estimate(speedOnly(2.0));
  for (int k = 2; k <= 5; ++k) reference.estimate(Measurement<2>::missing());
  expectSameBelief(out.estimates.back(), reference);
  EXPECT_FALSE(core.timedOut(0, 3.39));
  EXPECT_TRUE(core.timedOut(0, 3.41));
}

// --- outliers against the gate --------------------------------------------------------------

/// The train simulated with exactly the filter's model: v(k) = v(k-1) + a(k-1) T + w_v,
/// a(k) = a(k-1) + w_a, w ~ N(0, Q = 0.01 I), sampled once per period with noise of R:
/// speed (input 0, variance 0.5) and acceleration (input 1, variance 0.2).
struct TrainRun {
  std::vector<double> speed, acceleration, trueSpeed;
  explicit TrainRun(int periods, unsigned seed = 11) {
    std::mt19937 rng(seed);
    std::normal_distribution<double> process(0.0, 0.1), speedNoise(0.0, std::sqrt(0.5)),
        accNoise(0.0, std::sqrt(0.2));
    double v = 0.0, a = 0.0;
    for (int k = 1; k <= periods; ++k) {
      v += a * kPeriod + process(rng);
      a += process(rng);
      trueSpeed.push_back(v);
      speed.push_back(v + speedNoise(rng));
      acceleration.push_back(a + accNoise(rng));
    }
  }
};

/// Feeds `run` through a core, speed replaced by `burst` in periods [first, last], and
/// returns the estimates.
std::vector<Core::Estimate> replay(Core& core, const TrainRun& run, int first = 0, int last = -1,
                                   double burst = 0.0) {
  Collector out;
  core.advanceTo(0.0, out);
  for (std::size_t k = 0; k < run.speed.size(); ++k) {
    const int period = static_cast<int>(k) + 1;
    const double now = k * kPeriod + 0.05;
    const bool inBurst = period >= first && period <= last;
    core.addMeasurement(0, now, inBurst ? run.speed[k] + burst : run.speed[k]);
    core.addMeasurement(1, now, run.acceleration[k]);
    core.advanceTo(period * kPeriod, out);
  }
  return out.estimates;
}

TEST(FusionCoreFaults, ABurstOfTenSigmaOutliersIsGatedWithinTheStatedBound) {
  // 10 sigma of the speedometer (sqrt(R) = 0.707) for 1 s (periods 101-110) of 300.
  const int first = 101, last = 110;
  const double burst = 10.0 * std::sqrt(0.5);
  const TrainRun run(300);
  std::vector<InputOptions> gated(2);
  gated[0].gateThreshold = 9.0;
  Core clean = makeCore(gated), faulty = makeCore(gated),
       open = makeCore(std::vector<InputOptions>(2));
  const auto reference = replay(clean, run);
  const auto estimates = replay(faulty, run, first, last, burst);
  const auto ungated = replay(open, run, first, last, burst);
  // Every burst value failed the gate, and only those more than in the clean run.
  EXPECT_EQ(faulty.counters(0).gated - clean.counters(0).gated,
            static_cast<std::uint64_t>(last - first + 1));
  // The gated run is the clean run with the burst's speeds missing, so its deviation from the
  // clean run is the information of the missing values. For a consistent linear-Gaussian
  // filter that deviation has covariance P_missing - P_clean; the stated bound is 3 of its
  // standard deviations, on the speed, in every period.
  double worstRatio = 0.0, worstUngated = 0.0;
  for (std::size_t k = 0; k < estimates.size(); ++k) {
    const double deviation = std::abs(estimates[k].state(0) - reference[k].state(0));
    const double spread = estimates[k].covariance(0, 0) - reference[k].covariance(0, 0);
    if (deviation > 1e-9) {  // below: converged back, the spread is lost in rounding
      ASSERT_GT(spread, 0.0) << "period " << k + 1;
      worstRatio = std::max(worstRatio, deviation / std::sqrt(spread));
    }
    worstUngated = std::max(worstUngated, std::abs(ungated[k].state(0) - reference[k].state(0)));
  }
  EXPECT_LT(worstRatio, 3.0);
  // Without the gate the burst pulls the estimate far beyond that bound (so the check can
  // fail): by more than 3 m/s, 4 sigma of the speedometer.
  double worstGated = 0.0, worstBound = 0.0;
  for (std::size_t k = 0; k < estimates.size(); ++k) {
    worstGated = std::max(worstGated, std::abs(estimates[k].state(0) - reference[k].state(0)));
    worstBound =
        std::max(worstBound, 3.0 * std::sqrt(std::max(0.0, estimates[k].covariance(0, 0) -
                                                               reference[k].covariance(0, 0))));
  }
  EXPECT_GT(worstUngated, 3.0);
  EXPECT_GT(worstUngated, 3.0 * worstBound);
  // Before the burst the runs are identical.
  EXPECT_EQ(estimates[first - 2].state, reference[first - 2].state);
  std::printf("outlier burst: gated deviation at most %.3f m/s (bound %.3f), ungated %.3f m/s\n",
              worstGated, worstBound, worstUngated);
}

// --- NIS ------------------------------------------------------------------------------------

TEST(NisWindow, BoundsAreTheChiSquareQuantilesForUncorrelatedPeriods) {
  // Tables of the chi-square distribution: chi2^-1(0.025; 1) = 0.000982069,
  // chi2^-1(0.975; 1) = 5.023886; chi2^-1(0.025; 100) = 74.22193, chi2^-1(0.975; 100) = 129.5612.
  sf_filter::NisWindow one(1);
  one.add(1.0, 1);
  EXPECT_NEAR(one.bounds().lower, 0.000982069, 1e-8);
  EXPECT_NEAR(one.bounds().upper, 5.023886, 1e-5);
  // Alternating values: a negative lag-1 autocorrelation, which counts as none (n_eff = K).
  sf_filter::NisWindow window(50);
  for (int k = 0; k < 120; ++k) window.add(k % 2 ? 0.5 : 1.5, 2);
  EXPECT_TRUE(window.full());
  EXPECT_EQ(window.degreesOfFreedom(), 100);
  EXPECT_NEAR(window.mean(), 1.0, 1e-12);
  EXPECT_LT(window.autocorrelation(), 0.0);
  EXPECT_EQ(window.effectivePeriods(), 50.0);
  EXPECT_NEAR(window.bounds().lower, 74.22193 / 50, 1e-5);
  EXPECT_NEAR(window.bounds().upper, 129.5612 / 50, 1e-4);
  EXPECT_TRUE(window.inconsistent());  // mean 1 with 2 dof per period: expected 2
  // The oldest periods leave a full window.
  sf_filter::NisWindow sliding(50);
  for (int k = 0; k < 120; ++k) sliding.add(k < 70 ? 100.0 : 1.0, 2);
  EXPECT_EQ(sliding.degreesOfFreedom(), 100);
  EXPECT_NEAR(sliding.mean(), 1.0, 1e-12);
  sf_filter::NisWindow notFull(50);
  notFull.add(100.0, 1);
  EXPECT_FALSE(notFull.inconsistent());  // judged only on a full window
}

TEST(FusionCoreNis, TheNisOfAPeriodIsTheInnovationsMahalanobisDistance) {
  Core core = makeCore(std::vector<InputOptions>(2), 10);
  Collector out;
  core.advanceTo(0.0, out);
  core.addMeasurement(0, 0.05, 2.0);
  core.addMeasurement(1, 0.05, 1.0);
  core.advanceTo(0.1, out);
  // x(1|0) = 0, P(1|0) = A I A^T + Q = [[1.02, 0.1], [0.1, 1.01]], S = P(1|0) + R.
  const double s00 = 1.02 + 0.5, s01 = 0.1, s11 = 1.01 + 0.2;
  const double det = s00 * s11 - s01 * s01;
  const double nis = (2.0 * 2.0 * s11 - 2.0 * 2.0 * 1.0 * s01 + 1.0 * 1.0 * s00) / det;
  EXPECT_EQ(core.nis().size(), 1u);
  EXPECT_EQ(core.nis().degreesOfFreedom(), 2);
  EXPECT_NEAR(core.nis().mean(), nis, 1e-12);
  // A period without a measured value adds nothing.
  core.advanceTo(0.2, out);
  EXPECT_EQ(core.nis().size(), 1u);
  // The run's record: the same NIS, the prediction-error cost log det S + NIS, and each
  // input's own y_i^2 / S_ii with one degree of freedom.
  const sf_filter::InnovationRecord& r = core.innovations();
  EXPECT_EQ(r.overall().periods(), 1u);
  EXPECT_NEAR(r.overall().mean(), nis, 1e-12);
  EXPECT_NEAR(r.predictionErrorCost(), std::log(det) + nis, 1e-12);
  EXPECT_EQ(r.input(0).degreesOfFreedom(), 1);
  EXPECT_NEAR(r.input(0).mean(), 2.0 * 2.0 / s00, 1e-12);
  EXPECT_NEAR(r.input(1).mean(), 1.0 * 1.0 / s11, 1e-12);
}

TEST(NisSeries, JudgesEveryPeriodOfAFullWindowAndKeepsTheRunsTotals) {
  sf_filter::NisSeries series(50);
  for (int k = 0; k < 120; ++k) series.add(k < 70 ? 100.0 : 2.0, 2);
  // Judged from the 50th period on (71 periods; k = 49 .. 119, 0-based). Up to period 69 the
  // values are constant (no autocorrelation: n_eff = 50) and the mean 100 is far above its
  // bounds. From the step on, the lag-1 autocorrelation over the window's horizon of 500
  // periods is above 0.98 (the step dominates the values' variance), so the window counts as
  // its floor of 5 independent periods, nu = 100 * 5 / 50 = 10: bounds 2 chi2^-1(q; 10) / 10 =
  // [2 * 3.246973 / 10, 2 * 20.48318 / 10] = [0.6494, 4.0966] (tables). A window holding j
  // values 100 (j = 119 - k in period k) has the mean (100 j + 2 (50 - j)) / 50: above
  // 4.0966 for j >= 2 (5.92 at j = 2, period 117), inside for j = 1 (3.96, period 118) and
  // j = 0 (period 119). Inconsistent: periods 49 to 117 (0-based), 69 of 71 (the
  // independent-period bounds [1.484, 2.591] would also flag period 118).
  EXPECT_EQ(series.judgedPeriods(), 71u);
  EXPECT_EQ(series.inconsistentPeriods(), 69u);
  EXPECT_EQ(series.periods(), 120u);
  EXPECT_EQ(series.degreesOfFreedom(), 240);
  EXPECT_NEAR(series.mean(), (70 * 100.0 + 50 * 2.0) / 120, 1e-12);
  // The run's bounds: u = NIS / 2 is 50 (70 times), then 1 (50 times); with every period
  // alike, <u> = 3550 / 120, <u^2> = 175050 / 120, the 119 neighbours' <u_k u_k-1> =
  // (69 * 2500 + 50 + 49) / 119: rho = 0.98571 (by hand), n_eff = 120 * 0.01429 / 1.98571 =
  // 0.86, floored at 5: nu = 240 * 5 / 120 = 10, the same bounds as the window's.
  EXPECT_NEAR(series.autocorrelation(), 0.98571, 1e-5);
  EXPECT_EQ(series.effectivePeriods(), 5.0);
  EXPECT_NEAR(series.bounds().lower, 2 * 3.246973 / 10, 1e-5);
  EXPECT_NEAR(series.bounds().upper, 2 * 20.48318 / 10, 1e-4);
  series.restartWindow();
  EXPECT_EQ(series.window().size(), 0u);
  EXPECT_EQ(series.periods(), 120u);
}

TEST(NisSeries, JudgesAsTheDiagnosticsWindowWhenTheDegreesOfFreedomVary) {
  // A sensor slower than the period: 2 or 3 measured entries per period, the window's
  // degrees of freedom change from period to period. Every period's verdict must be the
  // diagnostics' (NisWindow::inconsistent), whatever the cached bounds.
  sf_filter::NisSeries series(20, 3);
  sf_filter::NisWindow reference(20);
  std::mt19937 random(3);
  std::uniform_real_distribution<double> nis(0.0, 6.0);
  std::uint64_t inconsistent = 0;
  for (int k = 0; k < 500; ++k) {
    const int dof = random() % 3 == 0 ? 3 : 2;
    const double e = nis(random);
    series.add(e, dof);
    reference.add(e, dof);
    inconsistent += reference.inconsistent() ? 1 : 0;
  }
  EXPECT_EQ(series.judgedPeriods(), 481u);
  EXPECT_EQ(series.inconsistentPeriods(), inconsistent);
  EXPECT_GT(inconsistent, 0u);
  EXPECT_LT(inconsistent, 481u);
}

TEST(FusionCoreNis, TheCheckLeavesTheEstimatesUnchanged) {
  const TrainRun run(100, 9);
  Core without = makeCore(std::vector<InputOptions>(2)),
       with = makeCore(std::vector<InputOptions>(2), 50);
  const auto a = replay(without, run), b = replay(with, run);
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t k = 0; k < a.size(); ++k) {
    EXPECT_EQ(a[k].state, b[k].state) << k;
    EXPECT_EQ(a[k].covariance, b[k].covariance) << k;
  }
  EXPECT_EQ(without.nis().size(), 0u);
  EXPECT_EQ(with.nis().size(), 50u);
}

/// The NIS window's verdict on a filter run on the simulated train with R scaled by `scale`
/// (the window covers periods 101-400, after the start-up transient).
sf_filter::NisWindow nisOfRun(double scale) {
  const TrainRun run(400, 5);
  Core core = makeCore(std::vector<InputOptions>(2), 300, trainR() * scale);
  replay(core, run);
  return core.nis();
}

TEST(FusionCoreNis, FlagsAMistunedFilterAndPassesAWellTunedOne) {
  // The simulation's Q and R are the filter's: consistent. An R 20 times too small makes
  // the innovations too large for the filter's S, one 20 times too large too small.
  const sf_filter::NisWindow tuned = nisOfRun(1.0), tooSmall = nisOfRun(0.05),
                             tooLarge = nisOfRun(20.0);
  ASSERT_TRUE(tuned.full());
  EXPECT_FALSE(tuned.inconsistent())
      << tuned.mean() << " in [" << tuned.bounds().lower << ", " << tuned.bounds().upper << "]";
  EXPECT_TRUE(tooSmall.inconsistent());
  EXPECT_GT(tooSmall.mean(), tooSmall.bounds().upper);
  EXPECT_TRUE(tooLarge.inconsistent());
  EXPECT_LT(tooLarge.mean(), tooLarge.bounds().lower);
}

}  // namespace
