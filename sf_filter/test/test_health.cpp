// Tests of the diagnostic rules (sf_filter/core/health.hpp): which level each situation gives,
// what the message says and the key values, on counters a fusion core really produced.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "sf_filter/core/health.hpp"
#include "train_core.hpp"

namespace {

using namespace train_core;
using sf_filter::HealthLevel;
using sf_filter::InputInterval;
using sf_filter::InputOptions;

/// One report interval of input 0 of `core`, from `before` to now.
InputInterval intervalOf(const Core& core, const sf_filter::InputCounters& before,
                         double interval) {
  InputInterval in;
  in.now = core.counters(0);
  in.before = before;
  in.clock = core.clock();
  in.interval = interval;
  in.sinceStart = core.clock() - core.startTime();
  in.timedOut = core.timedOut(0);
  return in;
}

Core timedCore() {
  Core::Options options;
  options.period = kPeriod;
  options.inputs.resize(2);
  options.inputs[0].timeout = 0.3;
  options.inputs[0].maximum = 10.0;
  options.inputs[0].gateThreshold = 9.0;
  return Core(makeTrain(), options);
}

TEST(InputHealth, OkWhileValuesArriveWithTheObservedRate) {
  Core core = timedCore();
  Collector out;
  core.advanceTo(0.0, out);
  for (int k = 0; k < 10; ++k) core.addMeasurement(0, 0.05 + 0.1 * k, 0.0);
  core.advanceTo(1.0, out);
  const auto h = sf_filter::inputHealth(core.inputOptions(0), intervalOf(core, {}, 1.0));
  EXPECT_EQ(h.level, HealthLevel::Ok);
  EXPECT_EQ(h.message, "ok");
  EXPECT_EQ(h.value("observed rate [Hz]"), "10");
  EXPECT_EQ(h.value("used"), "10");
  EXPECT_EQ(h.value("timed out"), "false");
  EXPECT_EQ(h.value("timeout [s]"), "0.3");
  EXPECT_NEAR(std::stod(h.value("last arrival age [s]")), 0.05, 1e-9);
}

TEST(InputHealth, WarnsWhenTimedOutAndRecovers) {
  Core core = timedCore();
  Collector out;
  core.advanceTo(0.0, out);
  core.addMeasurement(0, 0.05, 0.0);
  core.advanceTo(1.0, out);
  const auto silent = sf_filter::inputHealth(core.inputOptions(0), intervalOf(core, {}, 1.0));
  EXPECT_EQ(silent.level, HealthLevel::Warn);
  EXPECT_NE(silent.message.find("timed out: no value for 0.95 s (timeout 0.3 s)"),
            std::string::npos)
      << silent.message;
  const sf_filter::InputCounters before = core.counters(0);
  core.addMeasurement(0, 1.05, 0.0);
  core.advanceTo(1.1, out);
  EXPECT_EQ(sf_filter::inputHealth(core.inputOptions(0), intervalOf(core, before, 0.1)).level,
            HealthLevel::Ok);
}

TEST(InputHealth, NamesDropsAndGatedValuesAndErrsWhenNothingIsUsable) {
  Core core = timedCore();
  Collector out;
  core.advanceTo(0.0, out);
  core.addMeasurement(0, 0.01, 0.0);
  core.addMeasurement(0, 0.02, 11.0);          // out of range
  core.addMeasurement(0, 0.03, std::nan(""));  // not finite
  core.advanceTo(0.1, out);
  auto h = sf_filter::inputHealth(core.inputOptions(0), intervalOf(core, {}, 0.1));
  EXPECT_EQ(h.level, HealthLevel::Warn);
  EXPECT_EQ(h.message, "2 values dropped");
  EXPECT_EQ(h.value("dropped: out of range"), "1");
  EXPECT_EQ(h.value("dropped: not finite"), "1");
  // A wild value in the next period fails the gate (prediction about 0, S about 1.5).
  sf_filter::InputCounters before = core.counters(0);
  core.addMeasurement(0, 0.15, 9.5);
  core.advanceTo(0.2, out);
  h = sf_filter::inputHealth(core.inputOptions(0), intervalOf(core, before, 0.1));
  EXPECT_EQ(h.level, HealthLevel::Warn);
  EXPECT_EQ(h.message, "1 values gated");
  // Only garbage in an interval: ERROR.
  before = core.counters(0);
  core.addMeasurement(0, 0.21, std::nan(""));
  core.addMeasurement(0, 0.22, 1.0, -1.0);
  core.advanceTo(0.25, out);
  h = sf_filter::inputHealth(core.inputOptions(0), intervalOf(core, before, 0.05));
  EXPECT_EQ(h.level, HealthLevel::Error);
  EXPECT_EQ(h.message, "all 2 values dropped");
  EXPECT_EQ(h.value("dropped: bad variance"), "1");
}

sf_filter::EstimationInterval estimationOf(const Core& core,
                                           const sf_filter::EstimationTotals& before,
                                           double interval) {
  sf_filter::EstimationInterval e;
  e.now.estimates = core.estimateCount();
  e.now.estimationFailures = core.estimationFailures();
  e.now.filterResets = core.filterResets();
  e.now.clockResets = core.clockResets();
  e.now.estimatorSeconds = core.estimatorSeconds();
  e.before = before;
  e.interval = interval;
  e.period = core.period();
  e.covarianceTrace = core.lastEstimate().covariance.trace();
  e.lastFailure = core.lastFailure();
  return e;
}

TEST(EstimationHealth, WarnsOnAClockResetAndOnAStoppedClock) {
  Core core = timedCore();
  Collector out;
  core.advanceTo(0.0, out);
  core.advanceTo(1.0, out);
  auto h = sf_filter::estimationHealth(estimationOf(core, {}, 1.0), core.nis());
  EXPECT_EQ(h.level, HealthLevel::Ok);
  EXPECT_EQ(h.value("estimates"), "10");
  const double trace = core.lastEstimate().covariance.trace();
  EXPECT_NEAR(std::stod(h.value("covariance trace")), trace, 1e-5 * trace);
  sf_filter::EstimationTotals before;
  before.estimates = core.estimateCount();
  core.advanceTo(0.5, out);  // backwards
  h = sf_filter::estimationHealth(estimationOf(core, before, 0.0), core.nis());
  EXPECT_EQ(h.level, HealthLevel::Warn);
  EXPECT_EQ(h.message, "clock jumped backwards: filter reset");
  EXPECT_EQ(h.value("clock resets"), "1");
  // ROS time stood still between two reports (a paused bag): WARN.
  before.clockResets = 1;
  auto e = estimationOf(core, before, 0.0);
  EXPECT_EQ(sf_filter::estimationHealth(e, core.nis()).level, HealthLevel::Ok);
  e.clockStopped = true;
  e.clock = 0.5;
  h = sf_filter::estimationHealth(e, core.nis());
  EXPECT_EQ(h.level, HealthLevel::Warn);
  EXPECT_EQ(h.message, "clock stopped at 0.5 s: no estimates");
}

TEST(EstimationHealth, FlagsAnInconsistentNisAndErrsOnAFailure) {
  sf_filter::NisWindow nis(20);
  for (int k = 0; k < 20; ++k) nis.add(9.0, 1);  // expected 1 per period
  sf_filter::EstimationInterval e;
  e.covarianceTrace = 1.0;
  auto h = sf_filter::estimationHealth(e, nis);
  EXPECT_EQ(h.level, HealthLevel::Warn);
  EXPECT_EQ(h.message.rfind("filter inconsistent: NIS mean 9 outside [", 0), 0u) << h.message;
  // Above: what may cause it and where to see which input.
  EXPECT_NE(h.message.find("(innovations larger than S: Q or R too small, a sensor bias or a "
                           "wrong model; a replay's per-input NIS shows which input)"),
            std::string::npos)
      << h.message;
  // Below: no push to tune a track that may be right (issue 37).
  sf_filter::NisWindow small(20);
  for (int k = 0; k < 20; ++k) small.add(0.02, 1);
  const auto below = sf_filter::estimationHealth(e, small);
  EXPECT_EQ(below.level, HealthLevel::Warn);
  EXPECT_NE(below.message.find("(innovations smaller than S: the variances are pessimistic, the "
                               "track can still be right; check it against a reference before "
                               "tuning Q or R)"),
            std::string::npos)
      << below.message;
  EXPECT_EQ(below.message.find("too large?"), std::string::npos) << below.message;
  EXPECT_EQ(h.value("NIS consistent"), "false");
  EXPECT_EQ(h.value("NIS degrees of freedom"), "20");
  e.now.estimationFailures = 1;
  e.lastFailure = "innovation covariance is not positive definite";
  h = sf_filter::estimationHealth(e, nis);
  EXPECT_EQ(h.level, HealthLevel::Error);
  // A failed step keeps the last good estimate; the filter is reset only after repeated
  // failures (FusionCore::Options::maxConsecutiveFailures), and only then does the message
  // say so.
  EXPECT_EQ(h.message.rfind(
                "1 estimation steps failed, last good estimate kept: innovation covariance", 0),
            0u)
      << h.message;
  EXPECT_EQ(h.value("filter resets"), "0");
  e.now.estimationFailures = 10;
  e.now.filterResets = 1;
  h = sf_filter::estimationHealth(e, nis);
  EXPECT_EQ(h.level, HealthLevel::Error);
  EXPECT_EQ(h.message.rfind("10 estimation steps failed, filter reset 1 times after repeated "
                            "failures: innovation covariance",
                            0),
            0u)
      << h.message;
  EXPECT_EQ(h.value("filter resets"), "1");
  e.now.estimationFailures = 0;
  e.covarianceTrace = std::nan("");
  EXPECT_EQ(sf_filter::estimationHealth(e, sf_filter::NisWindow()).level, HealthLevel::Error);
}

}  // namespace
