// Unit tests of the stamp-to-arrival delay estimator (sf_filter/core/stamp_delay.hpp) and of
// the advice about late values (input_counters.hpp, health.hpp): quantiles against the exact
// ones of a known set of delays, and the advised ~max_measurement_lag checked by running the
// same values through a fusion core with it.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "sf_filter/core/health.hpp"
#include "sf_filter/core/input_counters.hpp"
#include "sf_filter/core/stamp_delay.hpp"
#include "train_core.hpp"

namespace {

using namespace train_core;
using sf_filter::Rejection;
using sf_filter::StampDelays;

/// Delays spread evenly over [21, 36] ms, as the IMU (median 28.5 ms).
std::vector<double> imuLikeDelays(int n = 1000) {
  std::vector<double> d;
  for (int i = 0; i < n; ++i) d.push_back(0.021 + 0.015 * ((i * 389) % n) / (n - 1));
  return d;
}

/// The exact q-quantile (the ceil(q n)-th smallest) of `d`.
double exactQuantile(std::vector<double> d, double q) {
  std::sort(d.begin(), d.end());
  return d.at(static_cast<std::size_t>(std::ceil(q * static_cast<double>(d.size()))) - 1);
}

/// The number after "~max_measurement_lag " in `text` (NaN if absent).
double advisedLag(const std::string& text) {
  const std::string key = "~max_measurement_lag ";
  const std::size_t at = text.find(key);
  return at == std::string::npos ? std::nan("") : std::stod(text.substr(at + key.size()));
}

TEST(StampDelays, QuantilesAreWithinTheBinResolutionOfTheExactOnes) {
  StampDelays d;
  const std::vector<double> delays = imuLikeDelays();
  for (double x : delays) d.add(x);
  EXPECT_EQ(d.count(), delays.size());
  for (double q : {0.5, 0.95, 0.99}) {
    const double exact = exactQuantile(delays, q);
    EXPECT_NEAR(d.quantile(q), exact, 0.022 * exact) << "q = " << q;
    // The bound is never below the exact quantile and at most one bin (4.4 %) above it.
    EXPECT_GE(d.bound(q), exact) << "q = " << q;
    EXPECT_LE(d.bound(q), 1.045 * exact) << "q = " << q;
  }
}

TEST(StampDelays, NoStampIsNotCountedAndTinyOrNegativeDelaysReadAsZero) {
  StampDelays d;
  EXPECT_TRUE(std::isnan(d.quantile(0.5)));
  EXPECT_EQ(sf_filter::delayFigures(d), "no stamped values");
  d.add(std::nan(""));
  EXPECT_EQ(d.count(), 0u);
  d.add(-0.5);    // a sensor clock ahead of the ROS clock
  d.add(1e-5);    // below the lowest bin
  d.add(1000.0);  // beyond the highest: counted in it
  EXPECT_EQ(d.count(), 3u);
  EXPECT_EQ(d.quantile(0.5), 0.0);
  EXPECT_GE(d.quantile(1.0), 200.0);
}

TEST(LateAdvice, NamesTheShareTheDelaysAndALagThatKeeps99Percent) {
  sf_filter::InputCounters c;
  const std::vector<double> delays = imuLikeDelays();
  for (double x : delays) c.delays.add(x);
  c.received = 1000;
  c.late = 310;
  const std::string text = sf_filter::lateAdvice(2, "imu/data angular_velocity.z", c, 0.02);
  EXPECT_EQ(text.rfind("input 2 (imu/data angular_velocity.z): 31 % of values dropped as late "
                       "(310 of 1000): stamp-to-arrival delay median 28.0 ms, p95 34.8 ms; ",
                       0),
            0u)
      << text;
  EXPECT_NE(text.find("would keep 99 % (now 0.02)"), std::string::npos) << text;
  const double lag = advisedLag(text);
  const auto kept = std::count_if(delays.begin(), delays.end(), [&](double x) { return x <= lag; });
  EXPECT_GE(kept, 990) << text;
  EXPECT_LE(lag, 0.038) << text;  // not far beyond what is needed (p99 35.9 ms, one bin, 1 ms)
}

TEST(LateAdvice, AdvisesKeepingAllWhenTheLagAlreadyKeeps99Percent) {
  sf_filter::InputCounters c;
  for (int i = 0; i < 995; ++i) c.delays.add(0.010);
  for (int i = 0; i < 5; ++i) c.delays.add(0.150);
  c.received = 1000;
  c.late = 5;
  const std::string text = sf_filter::lateAdvice(0, "odom twist.twist.linear.x", c, 0.02);
  EXPECT_NE(text.find("would keep all (now 0.02)"), std::string::npos) << text;
  EXPECT_GE(advisedLag(text), 0.150);
  EXPECT_LE(advisedLag(text), 0.158);
}

/// Input 0 of the train by stamp, each value stamped `delay` s before it arrives, at 100 Hz for
/// 5 s from 1.033 s, the clock advanced to every arrival (as the replay and the node do). The
/// schedule starts at 1.0 s: its periods are [1.0 - lag + 0.1 k, 1.1 - lag + 0.1 k).
Core runDelayedSpeed(double lag, double delay) {
  Core::Options options;
  options.period = kPeriod;
  options.maxMeasurementLag = lag;
  options.inputs.resize(2);
  options.inputs[0].alignByStamp = true;
  Core core(makeTrain(), options);
  Collector out;
  core.advanceTo(1.0, out);
  for (int k = 0; k < 500; ++k) {
    const double arrival = 1.033 + 0.01 * k;
    core.advanceTo(arrival, out);
    core.addMeasurement(0, arrival, 1.0, std::nullopt, arrival - delay);
  }
  return core;
}

TEST(LateAdvice, TheAdvisedLagKeepsTheValuesTheCoreDroppedAsLate) {
  const Core late = runDelayedSpeed(0.02, 0.025);
  const sf_filter::InputCounters& c = late.counters(0);
  // Periods [0.98 + 0.1 k, 1.08 + 0.1 k) are estimated at their end + 20 ms: a value stamped
  // in the last 5 ms of one arrives 25 ms later, too late: the one stamped 2 ms before the end
  // of each of the 50 periods from 1.08 to 5.98 s.
  EXPECT_EQ(c.late, 50u);
  EXPECT_NEAR(c.delays.quantile(0.5), 0.025, 0.022 * 0.025);
  EXPECT_NEAR(c.delays.quantile(0.95), 0.025, 0.022 * 0.025);
  const double lag = advisedLag(sf_filter::lateAdvice(0, "speed", c, late.maxMeasurementLag()));
  ASSERT_GE(lag, 0.025);
  EXPECT_LE(lag, 0.027);
  EXPECT_EQ(runDelayedSpeed(lag, 0.025).counters(0).late, 0u);
}

TEST(LateAdvice, TheInputsDiagnosticWarningNamesTheDelaysAndTheParameter) {
  const Core core = runDelayedSpeed(0.02, 0.025);
  sf_filter::InputInterval in;
  in.now = core.counters(0);
  in.clock = core.clock();
  in.interval = 5.0;
  in.maxMeasurementLag = core.maxMeasurementLag();
  const sf_filter::HealthStatus h = sf_filter::inputHealth(core.inputOptions(0), in);
  EXPECT_EQ(h.level, sf_filter::HealthLevel::Warn);
  EXPECT_NE(h.message.find(std::to_string(core.counters(0).late) +
                           " late: stamp-to-arrival delay median 24.6 ms, p95 24.6 ms"),
            std::string::npos)
      << h.message;
  EXPECT_NE(h.message.find("~max_measurement_lag 0.026 would keep 99 % (now 0.02)"),
            std::string::npos)
      << h.message;
  // Every value late (150 ms behind a lag of 20 ms): ERROR, with the same advice.
  const Core allLate = runDelayedSpeed(0.02, 0.15);
  in.now = allLate.counters(0);
  in.before = sf_filter::InputCounters();
  const sf_filter::HealthStatus e = sf_filter::inputHealth(allLate.inputOptions(0), in);
  EXPECT_EQ(e.level, sf_filter::HealthLevel::Error);
  EXPECT_EQ(e.message.rfind("all 500 values dropped (500 late: stamp-to-arrival delay median ", 0),
            0u)
      << e.message;
  EXPECT_NE(e.message.find("would keep 99 % (now 0.02)"), std::string::npos) << e.message;
  // 25 ms lies in the bin [2^-5.375, 2^-5.3125) s, whose middle is 2^-5.34375 s = 24.625 ms.
  EXPECT_NEAR(std::stod(h.value("stamp-to-arrival delay median [ms]")), 24.625, 1e-3);
  EXPECT_NEAR(std::stod(h.value("stamp-to-arrival delay p95 [ms]")), 24.625, 1e-3);
}

}  // namespace
