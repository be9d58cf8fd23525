// The fusion core's online fixed-lag smoother (core/lagged_smoother_of.hpp) on the train's core
// (train_core.hpp): after each estimated period it must give the smoothed belief that the
// offline smoother (core/period_smoother_of.hpp, tested against the batch solution in
// sf_estimation) gives the period `lag` periods back when it smooths the run up to now, with
// that period's end time; the two share only the record of the core's estimates.
#include <gtest/gtest.h>

#include <cmath>
#include <cstddef>
#include <memory>
#include <vector>

#include "sf_filter/core/fusion_engine_of.hpp"
#include "train_core.hpp"

namespace {

using namespace train_core;

/// Runs the train's core over 60 periods of speed readings (a sine, so that later readings
/// tell something about earlier periods) with the lagged and the offline smoother fed after
/// every estimate, and compares them at every period.
void expectOfflinePassOnEveryPrefix(std::size_t lag) {
  sf_filter::FusionEngineOf<Train> engine(makeTrain(), [] {
    Core::Options options;
    options.period = kPeriod;
    return options;
  }());
  const std::unique_ptr<sf_filter::LaggedSmoother> lagged = engine.makeLaggedSmoother(lag);
  const std::unique_ptr<sf_filter::PeriodSmoother> offline = engine.makeSmoother();
  ASSERT_TRUE(lagged && offline);
  std::vector<double> times;
  std::size_t outputs = 0;
  auto onEstimate = [&](const sf_filter::EstimateRef& estimate) {
    times.push_back(estimate.time);
    offline->record();
    const auto belief = lagged->add();
    const std::size_t k = times.size() - 1;
    if (k < lag) {
      EXPECT_FALSE(belief) << "period " << k;
      return;
    }
    ASSERT_TRUE(belief) << "period " << k;
    offline->smooth();
    const sf_filter::PeriodBelief reference = offline->smoothed(k - lag);
    EXPECT_EQ(belief->time, times[k - lag]);
    EXPECT_LT((belief->belief.state - reference.state).norm(), 1e-12) << "period " << k;
    EXPECT_LT((belief->belief.covariance - reference.covariance).norm(), 1e-12) << "period " << k;
    ++outputs;
  };
  engine.advanceTo(0.0, onEstimate);
  for (int k = 1; k <= 60; ++k) {
    const double t = k * kPeriod;
    engine.addMeasurement(0, t - 0.05, std::sin(t), std::nullopt, t - 0.05);
    engine.advanceTo(t, onEstimate);
  }
  EXPECT_EQ(outputs, times.size() - lag);
  EXPECT_EQ(lagged->periodsHeld(), lag + 1);
  EXPECT_EQ(lagged->segments(), 1u);
  EXPECT_EQ(lagged->failures(), 0u);
}

TEST(LaggedSmoother, LagZeroIsTheFilteredBelief) { expectOfflinePassOnEveryPrefix(0); }
TEST(LaggedSmoother, OnePeriod) { expectOfflinePassOnEveryPrefix(1); }
TEST(LaggedSmoother, TenPeriods) { expectOfflinePassOnEveryPrefix(10); }

}  // namespace
