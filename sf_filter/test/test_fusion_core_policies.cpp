// Unit tests of the alignment policies and the Mahalanobis gate inside the fusion core: each
// period's measurement is checked against the same Kalman filter stepped by hand with the
// value the policy defines (newest value, hold extrapolation, gap filling, gated = missing).
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include <sf_estimation/moving_average.hpp>

#include "train_core.hpp"

namespace {

using namespace train_core;
using sf_filter::AlignmentPolicy;
using sf_filter::HoldPrimitive;
using sf_filter::InputOptions;

Core makeCore(const std::vector<InputOptions>& inputs) {
  Core::Options options;
  options.period = kPeriod;
  options.inputs = inputs;
  return Core(makeTrain(), options);
}

InputOptions aligned(const AlignmentPolicy& policy, double gate = INFINITY) {
  InputOptions o;
  o.alignment = policy;
  o.gateThreshold = gate;
  return o;
}

TEST(FusionCorePolicies, LastUsesTheNewestValueOfThePeriod) {
  Core core = makeCore({aligned(AlignmentPolicy::last()), {}});
  Collector out;
  core.advanceTo(0.0, out);
  core.addMeasurement(0, 0.01, 1.0);
  core.addMeasurement(0, 0.03, 2.0);
  core.addMeasurement(0, 0.05, 6.0);
  core.addMeasurement(1, 0.06, 0.5);
  core.addMeasurement(1, 0.07, 1.5);  // input 1 still averages: 1.0
  core.advanceTo(0.1, out);
  Train reference = makeTrain();
  Measurement<2> z;
  z.value << 6.0, 1.0;
  reference.estimate(z);
  ASSERT_EQ(out.estimates.size(), 1u);
  expectSameBelief(out.estimates[0], reference);
  EXPECT_EQ(core.counters(0).used, 1u);
  EXPECT_EQ(core.counters(0).superseded, 2u);
  EXPECT_EQ(core.counters(1).used, 2u);
  EXPECT_EQ(core.counters(1).superseded, 0u);
}

TEST(FusionCorePolicies, SampledUsesTheSampleWithItsOwnVarianceAndIsMissingWithout) {
  Core core = makeCore({aligned(AlignmentPolicy::sampled()), {}});
  Collector out;
  core.advanceTo(0.0, out);
  core.addMeasurement(0, 0.02, 1.0, 0.3);
  core.addMeasurement(0, 0.04, 6.0, 0.04);
  core.advanceTo(0.1, out);
  core.advanceTo(0.2, out);  // nothing sampled: time update only
  Train reference = makeTrain();
  reference.estimate(speedOnly(6.0, 0.04));
  expectSameBelief(out.estimates.at(0), reference);
  reference.estimate(Measurement<2>::missing());
  expectSameBelief(out.estimates.at(1), reference);
  EXPECT_EQ(out.estimates[1].presentInputs, 0);
  EXPECT_EQ(out.estimates[1].substitutedInputs, 0);
}

TEST(FusionCorePolicies, HoldExtrapolatesTheHistoryInAPeriodWithoutValue) {
  // First-order hold with its own variance 0.8: samples 1 at 0.05 s and 2 at 0.15 s; the
  // third period (end 0.3 s) has none: 2 + (0.3 - 0.15) / 0.1 * (2 - 1) = 3.5.
  Core core = makeCore({aligned(AlignmentPolicy::hold(HoldPrimitive::Lagrange, 1, 0.8)), {}});
  Collector out;
  core.advanceTo(0.0, out);
  core.advanceTo(0.05, out);
  core.addMeasurement(0, 0.05, 1.0);
  core.advanceTo(0.15, out);
  core.addMeasurement(0, 0.15, 2.0);
  core.advanceTo(0.3, out);
  ASSERT_EQ(out.estimates.size(), 3u);
  Train reference = makeTrain();
  reference.estimate(speedOnly(1.0));
  reference.estimate(speedOnly(2.0));
  reference.estimate(speedOnly(3.5, 0.8));
  expectSameBelief(out.estimates[2], reference);
  EXPECT_EQ(out.estimates[2].presentInputs, 0);
  EXPECT_EQ(out.estimates[2].substitutedInputs, 1);
  EXPECT_EQ(core.counters(0).substituted, 1u);
  EXPECT_EQ(core.counters(0).used, 2u);
}

TEST(FusionCorePolicies, HoldLeavesTheInputMissingBeforeItsFirstSample) {
  Core core = makeCore({aligned(AlignmentPolicy::hold(HoldPrimitive::Taylor, 2)), {}});
  Collector out;
  core.advanceTo(0.0, out);
  core.advanceTo(0.1, out);
  Train reference = makeTrain();
  reference.estimate(Measurement<2>::missing());
  expectSameBelief(out.estimates.at(0), reference);
  EXPECT_EQ(core.counters(0).substituted, 0u);
}

TEST(FusionCorePolicies, FillCombinesTheFilterPredictionWithTheStoredSample) {
  // omega = 0.05 s, N = 2, variance 0.3. One sample, 1 at 0.05 s; in the second period (end
  // 0.2 s) the substitute is the Bezier of degree 1 through z^ and that sample:
  //   T_N = 0.2 + 0.05 - 0.05 = 0.2, w1 = (0.2 - 0.05) / 0.2 = 0.75, w2 = 0.25.
  Core core = makeCore({aligned(AlignmentPolicy::fill(0.05, 2, 0.3)), {}});
  Collector out;
  core.advanceTo(0.0, out);
  core.addMeasurement(0, 0.05, 1.0);
  core.advanceTo(0.1, out);
  core.advanceTo(0.2, out);
  Train reference = makeTrain();
  reference.estimate(speedOnly(1.0));
  estimation::MeasurementPrediction<2> p;
  reference.predictMeasurement(p);  // z^ of the second period
  reference.estimate(speedOnly(0.75 * p.mean(0) + 0.25 * 1.0, 0.3));
  expectSameBelief(out.estimates.at(1), reference);
  EXPECT_EQ(out.estimates[1].substitutedInputs, 1);
}

TEST(FusionCorePolicies, GateTreatsAnImprobableValueAsMissing) {
  // First period: x- = 0, P-(0,0) = 1 + 0.01 + 0.01 = 1.02, S = 1.02 + R(0,0) = 1.52; a speed
  // of 3 gives d^2 = 9 / 1.52 = 5.92: accepted under a threshold of 6, gated under 5.9.
  for (double threshold : {6.0, 5.9}) {
    Core core = makeCore({aligned(AlignmentPolicy::average(), threshold), {}});
    Collector out;
    core.advanceTo(0.0, out);
    core.addMeasurement(0, 0.02, 2.0);
    core.addMeasurement(0, 0.04, 4.0);  // mean 3
    core.advanceTo(0.1, out);
    Train reference = makeTrain();
    const bool accepted = threshold > 9.0 / 1.52;
    reference.estimate(accepted ? speedOnly(3.0) : Measurement<2>::missing());
    expectSameBelief(out.estimates.at(0), reference);
    EXPECT_EQ(core.counters(0).gated, accepted ? 0u : 2u) << threshold;
    EXPECT_EQ(core.counters(0).used, accepted ? 2u : 0u) << threshold;
    EXPECT_EQ(out.estimates[0].presentInputs, accepted ? 1 : 0);
  }
}

TEST(FusionCorePolicies, GateUsesTheMessageVariance) {
  // Speed 3 with its own variance 4: S = 1.02 + 4, d^2 = 9 / 5.02 = 1.79 < 2: accepted,
  // where R = 0.5 would give 5.92.
  Core core = makeCore({aligned(AlignmentPolicy::last(), 2.0), {}});
  Collector out;
  core.advanceTo(0.0, out);
  core.addMeasurement(0, 0.02, 3.0, 4.0);
  core.advanceTo(0.1, out);
  EXPECT_EQ(core.counters(0).gated, 0u);
  Train reference = makeTrain();
  reference.estimate(speedOnly(3.0, 4.0));
  expectSameBelief(out.estimates.at(0), reference);
}

TEST(FusionCorePolicies, AGatedValueStaysOutOfTheHoldHistory) {
  // Zero-order hold with a gate of 9: 1 passes (d^2 = 1 / 1.52), 100 is gated and replaced by
  // the held 1 (with R, no substitute variance configured).
  Core core = makeCore({aligned(AlignmentPolicy::hold(HoldPrimitive::Bezier, 0), 9.0), {}});
  Collector out;
  core.advanceTo(0.0, out);
  core.addMeasurement(0, 0.05, 1.0);
  core.advanceTo(0.1, out);
  core.addMeasurement(0, 0.15, 100.0);
  core.advanceTo(0.2, out);
  Train reference = makeTrain();
  reference.estimate(speedOnly(1.0));
  reference.estimate(speedOnly(1.0));
  expectSameBelief(out.estimates.at(1), reference);
  EXPECT_EQ(core.counters(0).gated, 1u);
  EXPECT_EQ(core.counters(0).substituted, 1u);
}

TEST(FusionCorePolicies, EveryReceivedValueIsAccountedFor) {
  // received = used + superseded + gated + dropped() once every period is estimated.
  Core core = makeCore({aligned(AlignmentPolicy::last(), 4.0),
                        aligned(AlignmentPolicy::hold(HoldPrimitive::Taylor, 1), 4.0)});
  Collector out;
  core.advanceTo(0.0, out);
  double t = 0.0;
  for (int k = 0; k < 200; ++k) {
    t += 0.013;
    core.advanceTo(t, out);
    const double v = std::sin(0.3 * k) + (k % 17 == 0 ? 50.0 : 0.0);  // some outliers
    core.addMeasurement(k % 3 == 0 ? 1 : 0, t, k % 29 == 0 ? NAN : v);
  }
  core.advanceTo(t + 0.1, out);
  std::uint64_t gated = 0;
  for (Eigen::Index i = 0; i < 2; ++i) {
    const sf_filter::InputCounters& c = core.counters(i);
    EXPECT_EQ(c.received, c.used + c.superseded + c.gated + c.dropped()) << "input " << i;
    gated += c.gated;
  }
  EXPECT_GT(gated, 0u);
  EXPECT_GT(core.counters(0).superseded, 0u);
  EXPECT_GT(core.counters(0).nonFinite, 0u);
}

TEST(FusionCorePolicies, RefusesOptionsTheFilterCannotServe) {
  Core::Options options;
  options.period = kPeriod;
  options.inputs = {InputOptions{}};  // two inputs
  EXPECT_THROW(Core(makeTrain(), options), estimation::ParameterError);
  options.inputs = {aligned(AlignmentPolicy::hold(HoldPrimitive::Lagrange, 99)), {}};
  try {
    Core(makeTrain(), options);
    FAIL() << "accepted a hold of order 99";
  } catch (const estimation::ParameterError& e) {
    EXPECT_NE(std::string(e.what()).find("input 0: HOLD order 99 is out of range"),
              std::string::npos);
  }

  // A moving average has no predicted measurement: no gate, no FILL.
  using Average = sf_filter::FusionCore<estimation::MovingAverage>;
  Average::Options averaging;
  averaging.period = kPeriod;
  averaging.inputs = {aligned(AlignmentPolicy::last(), 9.0)};
  EXPECT_THROW(Average(estimation::MovingAverage(1, 3), averaging), estimation::ParameterError);
  averaging.inputs = {aligned(AlignmentPolicy::fill(0.001, 5))};
  EXPECT_THROW(Average(estimation::MovingAverage(1, 3), averaging), estimation::ParameterError);
  averaging.inputs = {aligned(AlignmentPolicy::hold(HoldPrimitive::Lagrange, 1))};
  EXPECT_NO_THROW(Average(estimation::MovingAverage(1, 3), averaging));
}

}  // namespace
