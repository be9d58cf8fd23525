// Tests of the fixed-lag smoother (fixed_lag_smoother.hpp) against independent references: the
// two-step scalar case solved by hand (test_rts_smoother.cpp derives it), and the full RTS pass
// over the recording up to each period (rts_smoother.hpp, itself tested against the batch
// least-squares and MAP tracks), which the fixed-lag result must equal at the lagged period.
#include <algorithm>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "batch_map.hpp"
#include "filter_test_utils.hpp"
#include "scalar_models.hpp"
#include "sf_estimation/extended_kalman_filter.hpp"
#include "sf_estimation/fixed_lag_smoother.hpp"
#include "sf_estimation/kalman_filter.hpp"
#include "sf_estimation/unscented_kalman_filter.hpp"
#include "sf_estimation/unscented_rts_smoother.hpp"
#include "smoother_test_problems.hpp"

// Named, not anonymous: compiled in a unity group (sf_estimation/CMakeLists.txt).
namespace fixed_lag_smoother_test {

using estimation::ExtendedKalmanFilter;
using estimation::FilteredPeriod;
using estimation::KalmanFilter;
using estimation::Matrix;
using estimation::Measurement;
using estimation::UnscentedKalmanFilter;
using estimation::UnscentedParameters;
using estimation::Vector;
using sftest::BatchProblem;
using sftest::relDiff;
using sftest::SmoothedRun;
using sftest::Unicycle;
using sftest::UnicycleDrive;

const Matrix<1, 1> kOne = Matrix<1, 1>::Identity();
using ScalarPeriod = FilteredPeriod<1, 0>;

ScalarPeriod scalarPeriod(double x, double P, bool predicted) {
  return ScalarPeriod{Vector<1>(x), Matrix<1, 1>(P), Vector<0>(), predicted};
}

/// The hand case's filtered periods: x' = x + w, z = x + v, Q = R = 1, x_0 ~ N(0, 1),
/// z_1 = 3, z_2 = 6 give (0, 1), (2, 2/3), (4.5, 5/8).
std::vector<ScalarPeriod> handRecord() {
  return {scalarPeriod(0.0, 1.0, false), scalarPeriod(2.0, 2.0 / 3.0, true),
          scalarPeriod(4.5, 5.0 / 8.0, true)};
}

const KalmanFilter<1, 1, 0> kRandomWalk(kOne, Matrix<1, 0>(), kOne, kOne, kOne, Vector<1>(0.0),
                                        kOne);

// Lag 1 after period 1: G_0 = P_0 / P(1|0) = 1/2, x_0 = 0 + (2 - 0) / 2 = 1,
// P_0 = 1 + (2/3 - 2) / 4 = 2/3. Lag 1 after period 2 and lag 2 after period 2 are the full
// pass's periods 1 and 0: (3, 1/2) and (1.5, 5/8). Lag 0 is the filtered belief.
TEST(FixedLagSmootherHandCase, EachLagByHand) {
  const std::vector<ScalarPeriod> record = handRecord();
  auto lag0 = estimation::fixedLagSmootherFor(kRandomWalk, 0);
  auto lag1 = estimation::fixedLagSmootherFor(kRandomWalk, 1);
  auto lag2 = estimation::fixedLagSmootherFor(kRandomWalk, 2);
  EXPECT_NEAR(lag0.add(record[0])->x(0), 0.0, 1e-15);
  EXPECT_EQ(lag1.add(record[0]), nullptr);
  EXPECT_EQ(lag2.add(record[0]), nullptr);
  EXPECT_NEAR(lag0.add(record[1])->P(0, 0), 2.0 / 3.0, 1e-15);
  const auto* first = lag1.add(record[1]);
  ASSERT_NE(first, nullptr);
  EXPECT_NEAR(first->x(0), 1.0, 1e-14);
  EXPECT_NEAR(first->P(0, 0), 2.0 / 3.0, 1e-14);
  EXPECT_EQ(lag2.add(record[1]), nullptr);
  const auto* second = lag1.add(record[2]);
  EXPECT_NEAR(second->x(0), 3.0, 1e-14);
  EXPECT_NEAR(second->P(0, 0), 0.5, 1e-14);
  const auto* third = lag2.add(record[2]);
  ASSERT_NE(third, nullptr);
  EXPECT_NEAR(third->x(0), 1.5, 1e-14);
  EXPECT_NEAR(third->P(0, 0), 5.0 / 8.0, 1e-14);
  EXPECT_EQ(lag2.periodsHeld(), 3u);
}

/// Adds `record` to the fixed-lag smoothers of `filter` with each of `lags` and checks every
/// output against the full pass over the record up to that period, at the lagged period. The
/// full pass of each prefix is computed once for all lags (it dominates the test's time).
template <class Filter, class Record>
void expectFullPassOnEveryPrefix(const Filter& filter, const Record& record,
                                 const std::vector<std::size_t>& lags, double tolerance) {
  using Smoother = decltype(estimation::fixedLagSmootherFor(filter, 0));
  std::vector<Smoother> fixedLag;
  for (const std::size_t lag : lags)
    fixedLag.push_back(estimation::fixedLagSmootherFor(filter, lag));
  const auto full = smootherFor(filter);
  std::vector<estimation::SmoothedPeriod<Filter::StateSize>> smoothed;
  std::vector<std::size_t> outputs(lags.size(), 0);
  for (std::size_t k = 0; k < record.size(); ++k) {
    const Record prefix(record.begin(), record.begin() + static_cast<long>(k + 1));
    full.smooth(prefix, smoothed);
    for (std::size_t i = 0; i < lags.size(); ++i) {
      const std::size_t lag = lags[i];
      const auto* lagged = fixedLag[i].add(record[k]);
      if (k < lag) {
        EXPECT_EQ(lagged, nullptr) << "lag " << lag << ", period " << k;
        continue;
      }
      ASSERT_NE(lagged, nullptr) << "lag " << lag << ", period " << k;
      EXPECT_LT(relDiff(lagged->x, smoothed[k - lag].x), tolerance)
          << "lag " << lag << ", period " << k;
      EXPECT_LT(relDiff(lagged->P, smoothed[k - lag].P), tolerance)
          << "lag " << lag << ", period " << k;
      ++outputs[i];
    }
  }
  for (std::size_t i = 0; i < lags.size(); ++i) {
    EXPECT_EQ(outputs[i], record.size() - std::min(lags[i], record.size())) << "lag " << lags[i];
  }
}

/// A unicycle drive (the heading wraps) filtered by `filter`, with the belief of period 120
/// marked as set (not predicted): the chain is cut there as the full pass cuts it.
template <class Filter>
void expectUnicycleEqualsFullPass(const Filter& filter, double tolerance) {
  const UnicycleDrive drive(200, 3, 1.0);
  SmoothedRun<Filter> run(filter, drive.problem.u, drive.problem.z);
  run.filtered[120].predicted = false;
  expectFullPassOnEveryPrefix(filter, run.filtered, {0, 1, 7, 50, 250}, tolerance);
}

TEST(FixedLagSmootherEqualsFullPass, KalmanFilter) {
  const BatchProblem<sftest::LinearModel> problem = sftest::linearProblem();
  const auto& m = problem.model;
  const KalmanFilter<2, 2, 1> kf(m.A, m.B, m.H, problem.Q, problem.R, problem.x0, problem.P0);
  const SmoothedRun<KalmanFilter<2, 2, 1>> run(kf, problem.u, problem.z);
  expectFullPassOnEveryPrefix(kf, run.filtered, {0, 1, 5, 40}, 1e-12);
}

TEST(FixedLagSmootherEqualsFullPass, ExtendedKalmanFilter) {
  const UnicycleDrive drive(1, 3, 1.0);
  const BatchProblem<Unicycle>& p = drive.problem;
  expectUnicycleEqualsFullPass(
      ExtendedKalmanFilter<Unicycle>(p.model, p.Q, p.R, p.x0, p.P0, p.angles), 1e-12);
}

TEST(FixedLagSmootherEqualsFullPass, UnscentedKalmanFilterPropagatedMean) {
  const UnicycleDrive drive(1, 3, 1.0);
  const BatchProblem<Unicycle>& p = drive.problem;
  UnscentedParameters params;
  params.predictedMean = estimation::PredictedMean::Propagated;
  expectUnicycleEqualsFullPass(
      UnscentedKalmanFilter<Unicycle>(p.model, p.Q, p.R, p.x0, p.P0, params, p.angles), 1e-12);
}

// A period whose link to its predecessor has an indefinite prediction is refused with the
// smoother's error and not added: the smoother holds what it held and goes on from there.
TEST(FixedLagSmootherRecord, RefusedPeriodIsNotAdded) {
  const std::vector<ScalarPeriod> record = handRecord();
  auto smoother = estimation::fixedLagSmootherFor(kRandomWalk, 2);
  EXPECT_EQ(smoother.add(scalarPeriod(0.0, -3.0, false)), nullptr);
  try {
    smoother.add(record[1]);
    FAIL() << "no error";
  } catch (const estimation::NumericalError& e) {
    EXPECT_NE(std::string(e.what()).find("predicted covariance is indefinite"), std::string::npos)
        << e.what();
  }
  EXPECT_EQ(smoother.periodsHeld(), 1u);
  // A set belief cuts the chain; the hand case after it smooths as by hand.
  EXPECT_EQ(smoother.add(record[0]), nullptr);
  const auto* lagged = smoother.add(record[1]);
  ASSERT_NE(lagged, nullptr);  // the corrupt period, cut off: its own filtered belief
  EXPECT_EQ(lagged->P(0, 0), -3.0);
  const auto* hand = smoother.add(record[2]);
  EXPECT_NEAR(hand->x(0), 1.5, 1e-14);
  EXPECT_NEAR(hand->P(0, 0), 5.0 / 8.0, 1e-14);
}

}  // namespace fixed_lag_smoother_test
