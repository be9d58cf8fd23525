// The one snapshot of the fusion core's counters (core/fusion_statistics.hpp) that the
// diagnostics, the node's log lines, the replay's summary and --strict read: each counter and
// the inputs' totals against a hand-counted run of a Kalman filter's core.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include <sf_estimation/kalman_filter.hpp>

#include "sf_filter/core/fusion_engine_of.hpp"

namespace {

using estimation::Matrix;
using estimation::Vector;

/// A position (x, y) held still (Q = 0, P0 = I), measured by x and y (R = 4 I).
using Position = estimation::KalmanFilter<2, 2, 0>;

sf_filter::FusionEngineOf<Position> engine() {
  const Matrix<2, 2> I = Matrix<2, 2>::Identity();
  sf_filter::FusionCoreOptions options;
  options.period = 0.1;
  return sf_filter::FusionEngineOf<Position>(
      Position(I, Matrix<2, 0>(), I, Matrix<2, 2>::Zero(), 4.0 * I, Vector<2>::Zero(), I), options);
}

TEST(FusionStatistics, CountsOfAHandCountedRun) {
  auto core = engine();
  int estimates = 0;
  auto count = [&](const sf_filter::EstimateRef&) { ++estimates; };
  const double nan = std::numeric_limits<double>::quiet_NaN();
  core.advanceTo(0.0, count);  // starts the schedule
  // Input 0: one good value, one not finite, one with a negative variance; input 1: one good.
  EXPECT_EQ(core.addMeasurement(0, 0.02, 1.0, std::nullopt, nan), sf_filter::Rejection::None);
  EXPECT_EQ(core.addMeasurement(0, 0.03, nan, std::nullopt, nan), sf_filter::Rejection::NonFinite);
  EXPECT_EQ(core.addMeasurement(0, 0.04, 1.0, -1.0, nan), sf_filter::Rejection::BadVariance);
  EXPECT_EQ(core.addMeasurement(1, 0.05, 2.0, std::nullopt, nan), sf_filter::Rejection::None);
  core.advanceTo(0.15, count);  // the period [0, 0.1) ends
  const sf_filter::FusionStatistics s = core.statistics();
  ASSERT_EQ(s.inputs.size(), 2u);
  EXPECT_EQ(s.inputs[0].received, 3u);
  EXPECT_EQ(s.inputs[0].nonFinite, 1u);
  EXPECT_EQ(s.inputs[0].badVariance, 1u);
  EXPECT_EQ(s.inputs[0].used, 1u);
  EXPECT_EQ(s.inputs[1].used, 1u);
  EXPECT_EQ(s.totals.received, 4u);
  EXPECT_EQ(s.totals.used, 2u);
  EXPECT_EQ(s.totals.dropped, 2u);
  EXPECT_EQ(s.totals.gated + s.totals.late + s.totals.substituted, 0u);
  EXPECT_EQ(s.estimates, 1u);
  EXPECT_EQ(estimates, 1);
  EXPECT_EQ(s.estimationFailures + s.filterResets + s.clockResets + s.skippedGaps, 0u);
  EXPECT_EQ(s.clock, 0.15);
  EXPECT_EQ(s.startTime, 0.0);
  EXPECT_EQ(s.lastFailure, "");
}

TEST(FusionStatistics, GapsAndClockJumpsCountedOnce) {
  auto core = engine();
  auto ignore = [](const sf_filter::EstimateRef&) {};
  core.advanceTo(0.0, ignore);
  core.advanceTo(0.35, ignore);
  // A jump of 10000 s: more than maxCatchUpPeriods, crossed with one estimate.
  EXPECT_EQ(core.advanceTo(10000.35, ignore), sf_filter::ClockEvent::SkippedGap);
  EXPECT_EQ(core.advanceTo(5.0, ignore), sf_filter::ClockEvent::JumpedBackwards);
  sf_filter::FusionStatistics s;
  core.fillStatistics(s);
  EXPECT_EQ(s.skippedGaps, 1u);
  // 100000 periods ended in the jump: one estimated, the rest skipped.
  EXPECT_EQ(s.skippedPeriods, 99999u);
  EXPECT_EQ(s.clockResets, 1u);
  EXPECT_EQ(s.clock, 5.0);
  EXPECT_EQ(s.startTime, 5.0);
}

}  // namespace
