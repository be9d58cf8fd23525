// ALIGN_BY_STAMP without MAX_MEASUREMENT_LAG (test_config_stamp_default_lag.h): the lag
// defaults to one estimation period (sf_filter/config/detail/input_alignment.hpp), so a stamped
// value delayed in transport by less than a period still counts for the period it was
// measured in (with a lag of 0 it arrived after its period was estimated and was dropped).
#include "test_config_stamp_default_lag.h"
#include <sf_filter/config/configuration.hpp>

#include <optional>

#include <gtest/gtest.h>
#include <sf_estimation/kalman_filter.hpp>

#include "sf_filter/core/fusion_core.hpp"

namespace {

TEST(ConfigStampDefaultLag, TheLagDefaultsToOnePeriod) {
  static_assert(sf_config::kHasAlignByStamp, "the header aligns by stamp");
  EXPECT_DOUBLE_EQ(sf_config::kEstimationPeriodMs, 25.0);
  EXPECT_DOUBLE_EQ(sf_config::kMaxMeasurementLagMs, 25.0);
}

TEST(ConfigStampDefaultLag, AValueDelayedByLessThanAPeriodIsNotLate) {
  using Filter = estimation::KalmanFilter<1, 1, 0>;
  sf_filter::FusionCore<Filter>::Options options;
  options.period = sf_config::kEstimationPeriodMs / 1000.0;
  options.maxMeasurementLag = sf_config::kMaxMeasurementLagMs / 1000.0;
  options.inputs = sf_config::defaultInputOptions();
  ASSERT_TRUE(options.inputs[0].alignByStamp);
  sf_filter::FusionCore<Filter> core(
      Filter(estimation::Matrix<1, 1>::Identity(), estimation::Matrix<1, 0>(),
             estimation::Matrix<1, 1>::Identity(), estimation::Matrix<1, 1>::Constant(1e-4),
             estimation::Matrix<1, 1>::Constant(0.1), estimation::Vector<1>::Zero(),
             estimation::Matrix<1, 1>::Identity()),
      options);
  int estimates = 0;
  const auto count = [&](const auto&) { ++estimates; };
  core.advanceTo(0.0, count);  // the schedule starts one lag earlier: period 1 is [-0.025, 0)
  // Measured at 0.01 (period 2, [0, 0.025)), arriving 20 ms later, after that period's end.
  core.advanceTo(0.03, count);
  EXPECT_EQ(core.addMeasurement(0, 0.03, 1.0, std::nullopt, 0.01), sf_filter::Rejection::None);
  core.advanceTo(0.05, count);  // period 2 is estimated at 0.025 + 0.025
  EXPECT_EQ(core.counters(0).late, 0u);
  EXPECT_EQ(core.counters(0).used, 1u);
  // Reference: one KF step from (0, 1) with z = 1, R = 0.1 after period 1's prediction: P
  // = 1 + 1e-4 + 1e-4 (two predictions), K = P / (P + 0.1).
  const double P = 1.0 + 2e-4;
  EXPECT_NEAR(core.lastEstimate().state(0), P / (P + 0.1), 1e-12);
}

}  // namespace
