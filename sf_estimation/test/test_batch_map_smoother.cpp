// Tests of the batch MAP smoother (batch_map_smoother.hpp) against independent references: a
// two-step case solved by hand, the RTS smoother and the dense batch least-squares solution
// (batch_map.hpp) for a linear model, where both are the exact MAP track, and the dense
// Gauss-Newton MAP track of a simulated unicycle for the EKF's and UKF's models. The Ceres
// reference is in ceres/test_rts_smoother_ceres.cpp.
#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "batch_map.hpp"
#include "filter_test_utils.hpp"
#include "scalar_models.hpp"
#include "sf_estimation/batch_map_smoother.hpp"
#include "sf_estimation/extended_kalman_filter.hpp"
#include "sf_estimation/kalman_filter.hpp"
#include "sf_estimation/unscented_kalman_filter.hpp"
#include "sf_estimation/unscented_rts_smoother.hpp"
#include "smoother_test_problems.hpp"

// Named, not anonymous: compiled in a unity group (sf_estimation/CMakeLists.txt).
namespace batch_map_smoother_test {

using estimation::BatchMapOptions;
using estimation::BatchMapReport;
using estimation::ExtendedKalmanFilter;
using estimation::Index;
using estimation::KalmanFilter;
using estimation::Matrix;
using estimation::Measurement;
using estimation::SmoothedPeriod;
using estimation::UnscentedKalmanFilter;
using estimation::UnscentedParameters;
using estimation::Vector;
using estimation::wrapAngle;
using sftest::BatchProblem;
using sftest::measuredRecord;
using sftest::relDiff;
using sftest::SmoothedRun;

const Matrix<1, 1> kOne = Matrix<1, 1>::Identity();

// ---------------------------------------------------------------------------------------------
// The two steps of test_rts_smoother.cpp by hand: x' = x + w, z = x + v, Q = R = 1, x_0 ~
// N(0, 1), z_1 = 3, z_2 = 6. The MAP track solves [2 -1 0; -1 3 -1; 0 -1 2] x = (0, 3, 6):
// (1.5, 3, 4.5), variances the inverse's diagonal (5/8, 1/2, 5/8). Its cost: the residuals
// x_0 - 0, x_1 - x_0, x_2 - x_1, 3 - x_1, 6 - x_2 are 1.5, 1.5, 1.5, 0, 1.5: J = 9/2. The
// filtered track (0, 2, 4.5) has 0, 2, 2.5, 1, 1.5: J = 13.5/2.
// ---------------------------------------------------------------------------------------------
template <class Filter>
void expectHandCase(const Filter& filter) {
  std::vector<Vector<0>> u(3);
  const std::vector<Measurement<1>> z{Measurement<1>::missing(),
                                      Measurement<1>::complete(Vector<1>(3.0)),
                                      Measurement<1>::complete(Vector<1>(6.0))};
  const SmoothedRun<Filter> run(filter, u, z);
  auto smoother = estimation::batchSmootherFor(filter);
  std::vector<SmoothedPeriod<1>> smoothed;
  const BatchMapReport report = smoother.smooth(measuredRecord(run, z), smoothed);
  const double means[] = {1.5, 3.0, 4.5}, variances[] = {5.0 / 8.0, 0.5, 5.0 / 8.0};
  ASSERT_EQ(smoothed.size(), 3u);
  for (std::size_t k = 0; k < 3; ++k) {
    EXPECT_NEAR(smoothed[k].x(0), means[k], 1e-14) << "period " << k;
    EXPECT_NEAR(smoothed[k].P(0, 0), variances[k], 1e-14) << "period " << k;
  }
  EXPECT_NEAR(report.initialCost, 13.5 / 2.0, 1e-13);
  EXPECT_NEAR(report.cost, 9.0 / 2.0, 1e-13);
  // Linear: the first step is exact, the second confirms it.
  EXPECT_EQ(report.iterations, 2);
  EXPECT_TRUE(report.converged);
  EXPECT_EQ(report.segments, 1u);
}

TEST(BatchMapSmootherHandCase, KalmanFilter) {
  expectHandCase(
      KalmanFilter<1, 1, 0>(kOne, Matrix<1, 0>(), kOne, kOne, kOne, Vector<1>(0.0), kOne));
}

TEST(BatchMapSmootherHandCase, ExtendedKalmanFilter) {
  expectHandCase(ExtendedKalmanFilter<sftest::IdentityModel>({}, kOne, kOne, Vector<1>(0.0), kOne));
}

// ---------------------------------------------------------------------------------------------
// Linear model (2 states, correlated Q and R, missing entries): the RTS smoother and the dense
// batch solution are the MAP track and its marginal covariances; the batch smoother must equal
// both to 1e-9 relative.
// ---------------------------------------------------------------------------------------------

TEST(BatchMapSmootherLinear, EqualsRtsAndDenseBatch) {
  using Filter = KalmanFilter<2, 2, 1>;
  const BatchProblem<sftest::LinearModel> problem = sftest::linearProblem();
  const Filter kf(problem.model.A, problem.model.B, problem.model.H, problem.Q, problem.R,
                  problem.x0, problem.P0);
  const SmoothedRun<Filter> run(kf, problem.u, problem.z);
  const sftest::BatchSolution dense = sftest::solveBatch(
      problem, std::vector<Eigen::VectorXd>(problem.z.size(), Eigen::VectorXd::Zero(2)));
  auto smoother = estimation::batchSmootherFor(kf);
  std::vector<SmoothedPeriod<2>> smoothed;
  const BatchMapReport report = smoother.smooth(measuredRecord(run, problem.z), smoothed);
  ASSERT_EQ(smoothed.size(), dense.x.size());
  for (std::size_t k = 0; k < smoothed.size(); ++k) {
    EXPECT_LT(relDiff(smoothed[k].x, dense.x[k]), 1e-9) << "period " << k;
    EXPECT_LT(relDiff(smoothed[k].P, dense.P[k]), 1e-9) << "period " << k;
    EXPECT_LT(relDiff(smoothed[k].x, run.smoothed[k].x), 1e-9) << "period " << k;
    EXPECT_LT(relDiff(smoothed[k].P, run.smoothed[k].P), 1e-9) << "period " << k;
  }
  EXPECT_EQ(report.iterations, 2);
  EXPECT_TRUE(report.converged);
  EXPECT_LT(report.cost, report.initialCost);
  EXPECT_EQ(report.halvings, 0);
}

// A period whose belief was set starts an independent segment, with that belief (its
// measurement in it) as the prior: the batch track of the cut record equals the RTS smoother's,
// which does not link the two parts either.
TEST(BatchMapSmootherLinear, SetBeliefSeparatesTheSegments) {
  using Filter = KalmanFilter<2, 2, 1>;
  const BatchProblem<sftest::LinearModel> problem = sftest::linearProblem();
  Filter kf(problem.model.A, problem.model.B, problem.model.H, problem.Q, problem.R, problem.x0,
            problem.P0);
  SmoothedRun<Filter> run(kf, problem.u, problem.z);
  run.filtered[20].predicted = false;
  smootherFor(kf).smooth(run.filtered, run.smoothed);
  auto smoother = estimation::batchSmootherFor(kf);
  std::vector<SmoothedPeriod<2>> smoothed;
  const BatchMapReport report = smoother.smooth(measuredRecord(run, problem.z), smoothed);
  EXPECT_EQ(report.segments, 2u);
  for (std::size_t k = 0; k < smoothed.size(); ++k) {
    EXPECT_LT(relDiff(smoothed[k].x, run.smoothed[k].x), 1e-9) << "period " << k;
    EXPECT_LT(relDiff(smoothed[k].P, run.smoothed[k].P), 1e-9) << "period " << k;
  }
  // Period 19 ends its segment: it keeps its filtered belief (re-filtered: up to rounding),
  // which the next segment's data would have moved.
  EXPECT_LT(relDiff(smoothed[19].x, run.filtered[19].x), 1e-12);
  EXPECT_GT(relDiff(smoothed[18].x, run.filtered[18].x), 1e-3);
}

// ---------------------------------------------------------------------------------------------
// The unicycle of the smoother tests (300 periods, position fixes every third, the heading
// wrapping): the batch smoother's track equals the dense Gauss-Newton MAP track to 1e-6 of the
// MAP's standard deviation in every entry (converged at 1e-9 of it), its covariance the
// Laplace covariance of the MAP to 1e-6 relative, from the EKF's and the UKF's record alike.
// The RTS track lay up to 0.45 standard deviations from it.
// ---------------------------------------------------------------------------------------------

/// Largest gap of `track` to the MAP track in MAP standard deviations.
double gapInSigmas(const std::vector<SmoothedPeriod<3>>& track, const sftest::BatchSolution& map) {
  double gap = 0.0;
  for (std::size_t k = 0; k < map.x.size(); ++k) {
    Vector<3> difference = track[k].x - map.x[k];
    difference(2) = wrapAngle(difference(2));
    for (Index i = 0; i < 3; ++i) {
      gap = std::max(gap, std::abs(difference(i)) / std::sqrt(map.P[k](i, i)));
    }
  }
  return gap;
}

template <class Filter>
void expectMapTrack(const Filter& filter, const sftest::UnicycleDrive& drive) {
  const auto& p = drive.problem;
  const SmoothedRun<Filter> run(filter, p.u, p.z);
  std::vector<Eigen::VectorXd> start;
  for (const auto& period : run.filtered) start.emplace_back(period.x);
  const sftest::BatchSolution map = sftest::solveBatch(p, start);
  auto smoother = estimation::batchSmootherFor(filter);
  std::vector<SmoothedPeriod<3>> smoothed;
  const BatchMapReport report = smoother.smooth(measuredRecord(run, p.z), smoothed);
  EXPECT_TRUE(report.converged);
  EXPECT_GT(report.iterations, 2);  // measured: 10
  EXPECT_LT(gapInSigmas(smoothed, map), 1e-6);
  EXPECT_GT(gapInSigmas(run.smoothed, map), 0.1);  // the RTS track is not the MAP track
  for (std::size_t k = 0; k < map.x.size(); ++k) {
    EXPECT_LT(relDiff(smoothed[k].P, map.P[k]), 1e-6) << "period " << k;
  }
}

TEST(BatchMapSmootherNonlinear, ExtendedKalmanFilterRecordReachesMapTrack) {
  const sftest::UnicycleDrive drive(300, 11, 1.0);
  const auto& p = drive.problem;
  expectMapTrack(ExtendedKalmanFilter<sftest::Unicycle>(p.model, p.Q, p.R, p.x0, p.P0, p.angles),
                 drive);
}

TEST(BatchMapSmootherNonlinear, UnscentedKalmanFilterRecordReachesMapTrack) {
  const sftest::UnicycleDrive drive(300, 11, 1.0);
  const auto& p = drive.problem;
  expectMapTrack(UnscentedKalmanFilter<sftest::Unicycle>(p.model, p.Q, p.R, p.x0, p.P0,
                                                         UnscentedParameters{}, p.angles),
                 drive);
}

// States that no process noise reaches (here the unicycle's position, Q(0, 0) = Q(1, 1) = 0:
// the position only integrates the speed along the heading) follow their transition exactly: a
// constraint the cost cannot weigh, which the smoother keeps by rolling such states forward.
// The track must converge, meet the constraint to rounding, and equal the MAP track of the same
// problem with a position noise 1e-8 of the original (the dense reference needs Q^-1) to 1e-4
// of its standard deviation (measured 2e-9). (Here the steps also converge without the
// constraint kept; on the Pioneer's dead reckoning they do not: test_batch_smoothing_replay.py.)
TEST(BatchMapSmootherNonlinear, StatesWithoutProcessNoiseFollowTheirTransition) {
  sftest::UnicycleDrive drive(100, 5, 1.0);
  BatchProblem<sftest::Unicycle> p = drive.problem;
  p.Q(0, 0) = p.Q(1, 1) = 0.0;
  const ExtendedKalmanFilter<sftest::Unicycle> ekf(p.model, p.Q, p.R, p.x0, p.P0, p.angles);
  const SmoothedRun<ExtendedKalmanFilter<sftest::Unicycle>> run(ekf, p.u, p.z);
  auto smoother = estimation::batchSmootherFor(ekf);
  std::vector<SmoothedPeriod<3>> smoothed;
  const BatchMapReport report = smoother.smooth(measuredRecord(run, p.z), smoothed);
  EXPECT_TRUE(report.converged);
  for (std::size_t k = 1; k < smoothed.size(); ++k) {
    Vector<3> predicted;
    p.model.transition(smoothed[k - 1].x, p.u[k], predicted);
    EXPECT_LT((smoothed[k].x.head<2>() - predicted.head<2>()).cwiseAbs().maxCoeff(), 1e-12)
        << "period " << k;
  }
  BatchProblem<sftest::Unicycle> nearly = p;
  nearly.Q(0, 0) = 1e-8 * drive.problem.Q(0, 0);
  nearly.Q(1, 1) = 1e-8 * drive.problem.Q(1, 1);
  std::vector<Eigen::VectorXd> start;
  for (const auto& period : smoothed) start.emplace_back(period.x);
  const sftest::BatchSolution map = sftest::solveBatch(nearly, start, 1e-10);
  EXPECT_LT(gapInSigmas(smoothed, map), 1e-4);
}

// ---------------------------------------------------------------------------------------------
// The safeguard: x' = x, z = x / sqrt(1 + x^2) (a reading that saturates), a weak prior at 3
// and a precise reading z = 0. The undamped Gauss-Newton step from the track (3, 3) is about
// Newton's on h, which overshoots to about -27 (h'(3) = 10^-1.5) and diverges from there;
// halving the step keeps the cost decreasing and reaches the MAP track (the dense Gauss-Newton
// solution from the start (0, 0), where Newton converges; the MAP is 3e-6).
// ---------------------------------------------------------------------------------------------

struct SaturatingReading {
  static constexpr int StateSize = 1, MeasurementSize = 1, ControlSize = 0;
  Index stateSize() const { return 1; }
  Index measurementSize() const { return 1; }
  Index controlSize() const { return 0; }
  template <class S>
  void transition(const Eigen::Matrix<S, 1, 1>& x, const Vector<0>&,
                  Eigen::Matrix<S, 1, 1>& next) const {
    next = x;
  }
  template <class S>
  void observation(const Eigen::Matrix<S, 1, 1>& x, Eigen::Matrix<S, 1, 1>& z) const {
    using std::sqrt;
    z(0) = x(0) / sqrt(1.0 + x(0) * x(0));
  }
};

struct SaturatingCase {
  BatchProblem<SaturatingReading> problem;
  std::vector<estimation::MeasuredPeriod<1, 1, 0>> record;
  SaturatingCase() {
    problem.Q = Matrix<1, 1>::Constant(1e-4);
    problem.R = Matrix<1, 1>::Constant(1e-4);
    problem.x0 = Vector<1>(3.0);
    problem.P0 = Matrix<1, 1>::Constant(100.0);
    problem.u.assign(2, Vector<0>());
    problem.z = {Measurement<1>::missing(), Measurement<1>::complete(Vector<1>(0.0))};
    // A filter that kept the prior (as one whose updates were gated): the track starts at 3.
    record.push_back({{problem.x0, problem.P0, Vector<0>(), false}, problem.z[0]});
    record.push_back({{problem.x0, problem.P0, Vector<0>(), true}, problem.z[1]});
  }
  estimation::BatchMapSmoother<SaturatingReading> smoother(int maxIterations) const {
    BatchMapOptions options;
    options.maxIterations = maxIterations;
    return {SaturatingReading{},         problem.Q, problem.R, estimation::AngleMask<1>(1),
            estimation::AngleMask<1>(1), options};
  }
};

TEST(BatchMapSmootherSafeguard, HalvedStepsReachTheMapTrack) {
  const SaturatingCase c;
  const sftest::BatchSolution map =
      sftest::solveBatch(c.problem, std::vector<Eigen::VectorXd>(2, Eigen::VectorXd::Zero(1)));
  std::vector<SmoothedPeriod<1>> smoothed;
  const BatchMapReport report = c.smoother(50).smooth(c.record, smoothed);
  EXPECT_TRUE(report.converged);
  EXPECT_GT(report.halvings, 0);
  for (std::size_t k = 0; k < 2; ++k) {
    EXPECT_NEAR(smoothed[k].x(0), map.x[k](0), 1e-9 * std::sqrt(map.P[k](0, 0))) << "period " << k;
  }
  // The MAP is near 0, far from the start.
  EXPECT_LT(std::abs(smoothed[1].x(0)), 1e-3);
  // Every iteration, the first included, lowers the cost.
  std::vector<SmoothedPeriod<1>> once;
  const BatchMapReport first = c.smoother(1).smooth(c.record, once);
  EXPECT_LT(first.cost, first.initialCost);
  EXPECT_FALSE(first.converged);
  EXPECT_LE(report.cost, first.cost);
}

// ---------------------------------------------------------------------------------------------
// Refusals: a record that does not fit the model, with the period and the problem named; the
// result is left untouched.
// ---------------------------------------------------------------------------------------------

template <class Call>
std::string errorOf(Call call) {
  try {
    call();
  } catch (const estimation::InvalidInputError& e) {
    return e.what();
  }
  return "no error";
}

TEST(BatchMapSmootherRecord, InvalidRecordIsRefused) {
  const SaturatingCase c;
  auto smoother = c.smoother(50);
  std::vector<SmoothedPeriod<1>> smoothed(5, {Vector<1>(7.0), kOne});
  auto badVariance = c.record;
  badVariance[1].z.varianceGiven(0) = true;
  badVariance[1].z.variance(0) = -1.0;
  EXPECT_NE(errorOf([&] {
              smoother.smooth(badVariance, smoothed);
            }).find("period 1: variance of measurement 0"),
            std::string::npos)
      << errorOf([&] { smoother.smooth(badVariance, smoothed); });
  auto notFinite = c.record;
  notFinite[1].z.value(0) = std::numeric_limits<double>::quiet_NaN();
  EXPECT_NE(errorOf([&] {
              smoother.smooth(notFinite, smoothed);
            }).find("period 1: measurement 0 is not finite"),
            std::string::npos)
      << errorOf([&] { smoother.smooth(notFinite, smoothed); });
  auto badBelief = c.record;
  badBelief[0].belief.P(0, 0) = std::numeric_limits<double>::infinity();
  EXPECT_NE(errorOf([&] {
              smoother.smooth(badBelief, smoothed);
            }).find("period 0: the belief or the control is not finite"),
            std::string::npos);
  ASSERT_EQ(smoothed.size(), 5u);
  EXPECT_EQ(smoothed[0].x(0), 7.0);
  BatchMapOptions bad;
  bad.maxIterations = 0;
  EXPECT_THROW(estimation::BatchMapSmoother<SaturatingReading>(
                   SaturatingReading{}, c.problem.Q, c.problem.R, estimation::AngleMask<1>(1),
                   estimation::AngleMask<1>(1), bad),
               estimation::ParameterError);
}

}  // namespace batch_map_smoother_test
