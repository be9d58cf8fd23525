// The fusion core reports what its filter repaired (sf_estimation/numerical_repairs.hpp) and
// keeps the count across filter restarts, and the diagnostic rules turn a repair into a
// WARN. The fault: a UKF of x' = x^2 with alpha = 1, kappa = 0, beta = -10, whose predicted
// covariance from x ~ N(0, 1) is -10 + Q in closed form (sigma points 0, +1, -1, weights of
// the covariance -10, 1/2, 1/2; their squares 0, 1, 1 have mean 1): repaired to 0. And a
// failure no repair mends (an infinite time update) keeps the last good estimate, flagged,
// its covariance inflated by Q; only Options::maxConsecutiveFailures of them in a row restart
// the filter.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include <sf_estimation/unscented_kalman_filter.hpp>

#include "scalar_models.hpp"
#include "sf_filter/core/fusion_core.hpp"
#include "sf_filter/core/health.hpp"
#include "train_core.hpp"

namespace {

using estimation::Matrix;
using estimation::Vector;
using Ukf = estimation::UnscentedKalmanFilter<sftest::SquareTransition>;
using UkfCore = sf_filter::FusionCore<Ukf>;

constexpr double kT = 0.1;

UkfCore makeRepairingCore() {
  estimation::UnscentedParameters params;
  params.alpha = 1.0;
  params.beta = -10.0;
  params.kappa = 0.0;
  Ukf ukf(sftest::SquareTransition{}, Matrix<1, 1>::Constant(0.01), Matrix<1, 1>::Constant(0.1),
          Vector<1>::Zero(), Matrix<1, 1>::Identity(), params);
  UkfCore::Options options;
  options.period = kT;
  return UkfCore(std::move(ukf), options);
}

struct Ignore {
  template <class E>
  void operator()(const E&) const {}
};

TEST(FusionCoreRepairs, APeriodThatNeedsARepairIsEstimatedAndCounted) {
  UkfCore core = makeRepairingCore();
  EXPECT_EQ(core.numericalRepairs().total(), 0u);
  core.advanceTo(0.0, Ignore{});
  core.advanceTo(kT, Ignore{});  // one period, no measurement: the prediction alone
  EXPECT_EQ(core.estimateCount(), 1u);
  EXPECT_EQ(core.estimationFailures(), 0u);
  EXPECT_NEAR(core.lastEstimate().state(0), 1.0, 1e-15);
  EXPECT_EQ(core.lastEstimate().covariance(0, 0), 0.0);  // -9.99 floored to 0
  EXPECT_EQ(core.numericalRepairs().covariance, 1u);
  EXPECT_EQ(core.numericalRepairs().weights, 0u);
  EXPECT_EQ(core.numericalRepairs().sigmaSpread, 0u);
  // The repaired filter keeps estimating: from (1, 0) every sigma point is 1, so the
  // prediction is (1, Q) and z = 1.2 with R = 0.1 corrects it to 1 + 0.01 / 0.11 * 0.2.
  EXPECT_EQ(core.addMeasurement(0, 1.5 * kT, 1.2), sf_filter::Rejection::None);
  core.advanceTo(2 * kT, Ignore{});
  EXPECT_NEAR(core.lastEstimate().state(0), 1.0 + 0.01 / 0.11 * 0.2, 1e-12);
  EXPECT_EQ(core.numericalRepairs().covariance, 1u);
}

TEST(FusionCoreRepairs, TheCountSurvivesARestartOfTheFilter) {
  UkfCore core = makeRepairingCore();
  core.advanceTo(0.0, Ignore{});
  core.advanceTo(kT, Ignore{});
  ASSERT_EQ(core.numericalRepairs().covariance, 1u);
  core.reset();  // back to x ~ N(0, 1): the restarted filter counts from zero itself
  EXPECT_EQ(core.filter().numericalRepairs().covariance, 0u);
  EXPECT_EQ(core.numericalRepairs().covariance, 1u);
  core.advanceTo(2 * kT, Ignore{});  // the same fault again
  EXPECT_EQ(core.lastEstimate().covariance(0, 0), 0.0);
  EXPECT_EQ(core.numericalRepairs().covariance, 2u);
  // A clock jump backwards restarts the filter as well.
  core.advanceTo(0.5 * kT, Ignore{});
  EXPECT_EQ(core.clockResets(), 1u);
  EXPECT_EQ(core.numericalRepairs().covariance, 2u);
}

/// x' = x + 1 / u, z = x: a control of 0 makes the time update infinite, a failure no
/// repair can mend (the step is rejected with NumericalError).
struct ReciprocalControl {
  static constexpr int StateSize = 1, MeasurementSize = 1, ControlSize = 1;
  estimation::Index stateSize() const { return 1; }
  estimation::Index measurementSize() const { return 1; }
  estimation::Index controlSize() const { return 1; }
  template <class S>
  void transition(const Eigen::Matrix<S, 1, 1>& x, const Vector<1>& u,
                  Eigen::Matrix<S, 1, 1>& next) const {
    next(0) = x(0) + 1.0 / u(0);
  }
  template <class S>
  void observation(const Eigen::Matrix<S, 1, 1>& x, Eigen::Matrix<S, 1, 1>& z) const {
    z = x;
  }
};

using FailingUkf = estimation::UnscentedKalmanFilter<ReciprocalControl>;
using FailingCore = sf_filter::FusionCore<FailingUkf>;

FailingCore makeFailingCore(std::uint64_t maxConsecutiveFailures = 10) {
  FailingCore::Options options;
  options.period = kT;
  options.maxConsecutiveFailures = maxConsecutiveFailures;
  return FailingCore(
      FailingUkf(ReciprocalControl{}, Matrix<1, 1>::Constant(0.01), Matrix<1, 1>::Constant(0.1),
                 Vector<1>::Zero(), Matrix<1, 1>::Identity()),
      options);
}

TEST(FusionCoreRepairs, AFailedStepKeepsTheLastGoodEstimateAndTheEstimatesGoOn) {
  FailingCore core = makeFailingCore();
  std::vector<FailingCore::Estimate> out;
  const auto collect = [&](const auto& e) { out.push_back(e); };
  core.advanceTo(0.0, collect);
  // Periods 1 and 3 with u = 1, period 2 with u = 0 (rejected). The UKF of the linear
  // x' = x + 1 is exact: from (0, 1) period 1 predicts (1, 1 + Q). Period 2 keeps the state 1,
  // the filter unchanged by the rejected step, with the covariance inflated by Q for the period
  // that passed without a time update: (1, 1.02); period 3 predicts from it (2, 1.02 + Q).
  for (const double u : {1.0, 0.0, 1.0}) {
    ASSERT_EQ(core.addControl(0, u), sf_filter::Rejection::None);
    core.advanceTo(core.clock() + kT, collect);
  }
  ASSERT_EQ(out.size(), 3u);  // an estimate for every period, the failed one included
  EXPECT_NEAR(out[0].state(0), 1.0, 1e-12);
  EXPECT_NEAR(out[0].covariance(0, 0), 1.01, 1e-9);
  EXPECT_FALSE(out[0].stepFailed);
  EXPECT_EQ(out[1].state(0), out[0].state(0));
  EXPECT_NEAR(out[1].covariance(0, 0), 1.02, 1e-9);
  EXPECT_TRUE(out[1].stepFailed);
  EXPECT_FALSE(out[1].filterReset);
  EXPECT_NEAR(out[1].time, 2 * kT, 1e-12);
  // The UKF's default alpha = 1e-3 gives a mean weight of about -1e6: rounding of 1e6 * eps
  // * |x| = 4.4e-10 at x = 2.
  EXPECT_NEAR(out[2].state(0), 2.0, 1e-9);
  EXPECT_NEAR(out[2].covariance(0, 0), 1.03, 1e-9);
  EXPECT_FALSE(out[2].stepFailed);
  EXPECT_EQ(core.estimationFailures(), 1u);
  EXPECT_EQ(core.consecutiveFailures(), 0u);
  EXPECT_EQ(core.filterResets(), 0u);
  EXPECT_NE(core.lastFailure().find("non-finite"), std::string::npos) << core.lastFailure();
  EXPECT_EQ(core.numericalRepairs().total(), 0u);
}

TEST(FusionCoreRepairs, OnlyNConsecutiveFailuresRestartTheFilter) {
  FailingCore core = makeFailingCore(3);
  std::vector<FailingCore::Estimate> out;
  const auto collect = [&](const auto& e) { out.push_back(e); };
  core.advanceTo(0.0, collect);
  // u = 1, then 0 for four periods, then 1: failures 1 and 2 keep the state 1 and add Q to
  // the covariance each (1.02, 1.03); the third in a row restarts from (0, 1); the fourth is
  // the first of a new run: (0, 1 + Q); the last period predicts from it (1, 1 + 2 Q).
  for (const double u : {1.0, 0.0, 0.0, 0.0, 0.0, 1.0}) {
    ASSERT_EQ(core.addControl(0, u), sf_filter::Rejection::None);
    core.advanceTo(core.clock() + kT, collect);
  }
  ASSERT_EQ(out.size(), 6u);
  for (int k : {1, 2}) {
    EXPECT_NEAR(out[k].state(0), 1.0, 1e-12) << k;
    EXPECT_NEAR(out[k].covariance(0, 0), 1.01 + 0.01 * k, 1e-9) << k;
    EXPECT_TRUE(out[k].stepFailed && !out[k].filterReset) << k;
  }
  EXPECT_EQ(out[3].state(0), 0.0);
  EXPECT_EQ(out[3].covariance(0, 0), 1.0);
  EXPECT_TRUE(out[3].stepFailed && out[3].filterReset);
  EXPECT_EQ(out[4].state(0), 0.0);
  EXPECT_NEAR(out[4].covariance(0, 0), 1.01, 1e-12);
  EXPECT_TRUE(out[4].stepFailed && !out[4].filterReset);
  EXPECT_NEAR(out[5].state(0), 1.0, 1e-9);
  EXPECT_NEAR(out[5].covariance(0, 0), 1.02, 1e-9);
  EXPECT_FALSE(out[5].stepFailed);
  EXPECT_EQ(core.estimationFailures(), 4u);
  EXPECT_EQ(core.filterResets(), 1u);
  EXPECT_EQ(core.consecutiveFailures(), 0u);
}

TEST(FusionCoreRepairs, RefusesZeroConsecutiveFailures) {
  EXPECT_THROW(makeFailingCore(0), estimation::ParameterError);
}

TEST(FusionCoreRepairs, AHealthyFilterReportsNone) {
  train_core::Core core = train_core::makeCore();
  core.advanceTo(0.0, Ignore{});
  for (int k = 1; k <= 50; ++k) {
    core.addMeasurement(0, (k - 0.5) * kT, 1.0);
    core.advanceTo(k * kT, Ignore{});
  }
  EXPECT_EQ(core.estimateCount(), 50u);
  EXPECT_EQ(core.numericalRepairs().total(), 0u);
}

TEST(FusionCoreRepairs, ARepairInTheIntervalWarnsAndNamesTheCount) {
  UkfCore core = makeRepairingCore();
  core.advanceTo(0.0, Ignore{});
  core.advanceTo(kT, Ignore{});
  sf_filter::EstimationInterval e;
  e.now.estimates = core.estimateCount();
  e.now.repairs = core.numericalRepairs();
  e.period = kT;
  e.covarianceTrace = core.lastEstimate().covariance.trace();
  auto h = sf_filter::estimationHealth(e, core.nis());
  EXPECT_EQ(h.level, sf_filter::HealthLevel::Warn);
  EXPECT_EQ(h.message,
            "1 numerical repairs by the filter (covariance, particle weights or "
            "sigma spread)");
  EXPECT_EQ(h.value("numerical repairs"), "1");
  EXPECT_EQ(h.value("repairs: covariance"), "1");
  EXPECT_EQ(h.value("repairs: particle weights"), "0");
  // The next interval without a repair is OK again; the total stays in the key values.
  e.before = e.now;
  h = sf_filter::estimationHealth(e, core.nis());
  EXPECT_EQ(h.level, sf_filter::HealthLevel::Ok) << h.message;
  EXPECT_EQ(h.value("numerical repairs"), "1");
}

}  // namespace
