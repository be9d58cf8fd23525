// Angle inputs under the alignment policies at the +-pi seam, against values computed by hand:
// AVERAGE takes the circular mean with the variance of its linearisation (period_average.hpp),
// HOLD and FILL extrapolate the unwrapped angle and wrap the result (unwrapped_angles.hpp). The
// linear forms of the same numbers are wrong by about pi, which is what the inputs did before.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include <sf_estimation/angles.hpp>
#include <sf_estimation/kalman_filter.hpp>

#include "sf_filter/core/alignment/gap_filling.hpp"
#include "sf_filter/core/alignment/input_aligner.hpp"
#include "sf_filter/core/alignment/multirate_hold.hpp"
#include "sf_filter/core/fusion_core.hpp"
#include "sf_filter/core/period_average.hpp"

namespace {

constexpr double kPi = 3.14159265358979323846;
using estimation::wrapAngle;
using sf_filter::AlignmentPolicy;
using sf_filter::GapFilling;
using sf_filter::HoldPrimitive;
using sf_filter::InputAligner;
using sf_filter::InputPeriod;
using sf_filter::MultiRateHold;
using sf_filter::PeriodAverage;

/// a and b are the same angle to within `tolerance` rad.
void expectSameAngle(double a, double b, double tolerance = 1e-12) {
  EXPECT_NEAR(wrapAngle(a - b), 0.0, tolerance) << a << " vs " << b;
}

TEST(AngleAverage, ReadingsEitherSideOfTheSeamAverageToPi) {
  // 3.1 and -3.1: sin 3.1 + sin(-3.1) = 0, cos 3.1 + cos(-3.1) < 0: atan2 gives pi. With
  // variances 0.01 and 0.03 (a - m = -+0.0416, R = 2 cos 0.0416):
  //   var = (0.01 + 0.03) cos^2(0.0416) / (4 cos^2(0.0416)) = 0.01.
  PeriodAverage a(true);
  a.add(3.1, 0.01);
  a.add(-3.1, 0.03);
  ASSERT_TRUE(a.hasMean());
  EXPECT_DOUBLE_EQ(a.mean(), kPi);  // wrapped to (-pi, pi]: +pi, not -pi
  ASSERT_TRUE(a.hasVariance());
  EXPECT_NEAR(a.meanVariance(), 0.01, 1e-15);
  PeriodAverage linear;  // what a non-angle input does with the same numbers
  linear.add(3.1, 0.01);
  linear.add(-3.1, 0.03);
  EXPECT_NEAR(linear.mean(), 0.0, 1e-15);
}

TEST(AngleAverage, TwoReadingsAverageToTheirBisector) {
  // pi - 0.1 and -pi + 0.3 are 0.2 apart across the seam: the mean is pi + 0.1 = -pi + 0.1.
  PeriodAverage a(true);
  a.add(kPi - 0.1, std::nullopt);
  a.add(-kPi + 0.3, std::nullopt);
  expectSameAngle(a.mean(), -kPi + 0.1);
  EXPECT_GT(a.mean(), -kPi);
  EXPECT_FALSE(a.hasVariance());  // no variance from the messages: the filter's R
}

TEST(AngleAverage, VarianceGrowsWithTheSpreadOfTheReadings) {
  // pi - 0.2, pi, -pi + 0.2, variance 0.09 each: m = pi by symmetry, R = 1 + 2 cos 0.2,
  //   var = 0.09 (1 + 2 cos^2 0.2) / (1 + 2 cos 0.2)^2 = 0.0300087..., above 0.09 / 3.
  PeriodAverage a(true);
  for (double v : {kPi - 0.2, kPi, -kPi + 0.2}) a.add(v, 0.09);
  expectSameAngle(a.mean(), kPi);
  const double c = std::cos(0.2);
  EXPECT_NEAR(a.meanVariance(), 0.09 * (1 + 2 * c * c) / ((1 + 2 * c) * (1 + 2 * c)), 1e-15);
  EXPECT_GT(a.meanVariance(), 0.03);
}

TEST(AngleAverage, ClearKeepsTheAngleForm) {
  PeriodAverage a(true);
  a.add(1.0, std::nullopt);
  a.clear();
  EXPECT_TRUE(a.empty());
  a.add(3.1, std::nullopt);
  a.add(-3.1, std::nullopt);
  EXPECT_DOUBLE_EQ(a.mean(), kPi);
}

TEST(AngleAverage, OppositeReadingsHaveNoMeanAndTheAlignerTakesTheNewest) {
  InputPeriod period(0, true);
  period.add(0.0, std::nullopt, 0.01);
  period.add(kPi, std::nullopt, 0.02);
  EXPECT_FALSE(period.average().hasMean());
  const InputAligner aligner(AlignmentPolicy::average(), true);
  const auto v = aligner.measured(period);
  ASSERT_TRUE(v.has_value());
  EXPECT_DOUBLE_EQ(v->value, kPi);
}

TEST(AngleAverage, TheAlignerAveragesAnAngleInputOnTheCircle) {
  InputPeriod period(0, true);
  period.add(3.1, 0.01, 0.01);
  period.add(-3.1, 0.03, 0.02);
  const auto v = InputAligner(AlignmentPolicy::average(), true).measured(period);
  ASSERT_TRUE(v.has_value() && v->variance.has_value());
  EXPECT_DOUBLE_EQ(v->value, kPi);
  EXPECT_NEAR(*v->variance, 0.01, 1e-15);
}

TEST(AngleHold, FirstOrderHoldsContinueTheTurnAcrossTheSeam) {
  // pi - 0.1 at 0.1 s, -pi + 0.1 at 0.2 s: the heading turned by +0.2 rad in 0.1 s; at 0.25 s
  // the line gives -pi + 0.2 for every primitive of order 1. The wrapped numbers' line would
  // give -pi + 0.1 + 0.5 (-2 pi + 0.2) = -2 pi + 0.2, i.e. 0.2: pi away.
  for (HoldPrimitive primitive :
       {HoldPrimitive::Lagrange, HoldPrimitive::Bezier, HoldPrimitive::Taylor}) {
    MultiRateHold hold(primitive, 1, true);
    hold.sampled(0.1, kPi - 0.1);
    hold.sampled(0.2, -kPi + 0.1);
    const double value = hold.value(0.25);
    expectSameAngle(value, -kPi + 0.2);
    EXPECT_GT(value, -kPi);
    EXPECT_LE(value, kPi);
    EXPECT_DOUBLE_EQ(hold.history()[0].value, -kPi + 0.1);  // stored as read
    MultiRateHold linear(primitive, 1);
    linear.sampled(0.1, kPi - 0.1);
    linear.sampled(0.2, -kPi + 0.1);
    expectSameAngle(linear.value(0.25), 0.2);
  }
}

TEST(AngleHold, SecondOrderLagrangeReproducesAQuadraticTurnThroughTheSeam) {
  // theta(t) = pi - 0.3 + t + t^2 read at 0, 0.2, 0.4 s: pi - 0.3, pi - 0.06, pi + 0.26 (read
  // as -pi + 0.26); at 0.5 s theta = pi + 0.45 = -pi + 0.45.
  MultiRateHold hold(HoldPrimitive::Lagrange, 2, true);
  hold.sampled(0.0, kPi - 0.3);
  hold.sampled(0.2, kPi - 0.06);
  hold.sampled(0.4, -kPi + 0.26);
  expectSameAngle(hold.value(0.5), -kPi + 0.45);
}

TEST(AngleHold, ReadingsSeveralTurnsApartAreTheSameAngle) {
  // A sensor that does not wrap (7 rad = 7 - 2 pi): zero-order hold gives the wrapped value.
  MultiRateHold hold(HoldPrimitive::Lagrange, 0, true);
  hold.sampled(0.1, 7.0);
  EXPECT_NEAR(hold.value(0.3), 7.0 - 2 * kPi, 1e-15);
}

TEST(AngleFill, TheFilterPredictionIsTakenOnTheSeamSideOfTheSample) {
  // omega = 0.05 s, N = 1, sample pi - 0.1 at 0.05 s, z^ = -pi + 0.1 at t = 0.2 s:
  //   T_N = 0.2, w1 = 0.75, w2 = 0.25; z^ unwrapped to pi + 0.1:
  //   0.75 (pi + 0.1) + 0.25 (pi - 0.1) = pi + 0.05 = -pi + 0.05.
  // Linearly: 0.75 (-pi + 0.1) + 0.25 (pi - 0.1) = -pi / 2 + 0.05.
  GapFilling fill(0.05, 1, true);
  fill.sampled(0.05, kPi - 0.1);
  expectSameAngle(fill.value(0.2, -kPi + 0.1), -kPi + 0.05);
  GapFilling linear(0.05, 1);
  linear.sampled(0.05, kPi - 0.1);
  EXPECT_NEAR(linear.value(0.2, -kPi + 0.1), -kPi / 2 + 0.05, 1e-14);
}

TEST(AngleFill, TwoSamplesAcrossTheSeam) {
  // Samples pi - 0.2 at 0 s and -pi + 0.1 (= pi + 0.1) at 0.1 s, N = 2, omega = 0.05 s, z^ =
  // -pi + 0.3 (= pi + 0.3) at 0.15 s: weights 0.5625, 0.375, 0.0625 (test_gap_filling.cpp):
  //   0.5625 (pi + 0.3) + 0.375 (pi + 0.1) + 0.0625 (pi - 0.2) = pi + 0.19375.
  GapFilling fill(0.05, 2, true);
  fill.sampled(0.0, kPi - 0.2);
  fill.sampled(0.1, -kPi + 0.1);
  expectSameAngle(fill.value(0.15, -kPi + 0.3), -kPi + 0.19375);
}

// The fusion core with a heading filter (x = heading, z = compass, both declared angles): the
// compass's aligned value is what the filter is stepped with.
using Heading = estimation::KalmanFilter<1, 1, 0>;
using HeadingCore = sf_filter::FusionCore<Heading>;
constexpr double kPeriod = 0.1;

Heading makeHeading() {
  const estimation::Matrix<1, 1> one = estimation::Matrix<1, 1>::Identity();
  return Heading(one, estimation::Matrix<1, 0>(), one, one * 0.01, one * 0.5,
                 estimation::Vector<1>(kPi - 0.05), one, estimation::AngularComponents{{0}, {0}});
}

HeadingCore makeCore(const AlignmentPolicy& policy) {
  HeadingCore::Options options;
  options.period = kPeriod;
  sf_filter::InputOptions compass;
  compass.alignment = policy;
  compass.angle = true;
  options.inputs = {compass};
  return HeadingCore(makeHeading(), options);
}

struct Collector {
  std::vector<HeadingCore::Estimate> estimates;
  void operator()(const HeadingCore::Estimate& e) { estimates.push_back(e); }
};

estimation::Measurement<1> compass(double value, double variance = NAN) {
  estimation::Measurement<1> z;
  z.value << value;
  z.varianceGiven << !std::isnan(variance);
  z.variance << (std::isnan(variance) ? 0.0 : variance);
  return z;
}

void expectSameBelief(const HeadingCore::Estimate& e, const Heading& reference) {
  expectSameAngle(e.state(0), reference.state()(0), 1e-13);
  EXPECT_NEAR(e.covariance(0, 0), reference.covariance()(0, 0), 1e-13);
}

TEST(AngleFusionCore, AverageStepsTheFilterWithTheCircularMean) {
  HeadingCore core = makeCore(AlignmentPolicy::average());
  Collector out;
  core.advanceTo(0.0, out);
  core.addMeasurement(0, 0.02, 3.1, 0.01);
  core.addMeasurement(0, 0.04, -3.1, 0.03);
  core.advanceTo(0.1, out);
  ASSERT_EQ(out.estimates.size(), 1u);
  Heading reference = makeHeading();
  reference.estimate(compass(kPi, 0.01));
  expectSameBelief(out.estimates[0], reference);
  EXPECT_GT(std::abs(out.estimates[0].state(0)), 3.0);  // not pulled towards 0
}

TEST(AngleFusionCore, HoldSubstitutesTheUnwrappedExtrapolation) {
  // First-order hold: pi - 0.1 at 0.05 s, -pi + 0.1 at 0.15 s; the third period (end 0.3 s)
  // has none: -pi + 0.1 + 0.2 * 1.5 = -pi + 0.4, with the hold's variance 0.2.
  HeadingCore core = makeCore(AlignmentPolicy::hold(HoldPrimitive::Lagrange, 1, 0.2));
  Collector out;
  core.advanceTo(0.0, out);
  core.advanceTo(0.05, out);
  core.addMeasurement(0, 0.05, kPi - 0.1);
  core.advanceTo(0.15, out);
  core.addMeasurement(0, 0.15, -kPi + 0.1);
  core.advanceTo(0.3, out);
  ASSERT_EQ(out.estimates.size(), 3u);
  Heading reference = makeHeading();
  reference.estimate(compass(kPi - 0.1));
  reference.estimate(compass(-kPi + 0.1));
  reference.estimate(compass(-kPi + 0.4, 0.2));
  expectSameBelief(out.estimates[2], reference);
  EXPECT_EQ(out.estimates[2].substitutedInputs, 1);
}

}  // namespace
