// Tests of the RTS smoothers (rts_smoother.hpp, unscented_rts_smoother.hpp) against
// independent references: a two-step scalar case solved by hand, the dense batch
// least-squares solution of the whole track (batch_map.hpp) for a linear model, where RTS is
// exact, and the Gauss-Newton MAP track of a simulated unicycle for the EKF and UKF smoothers,
// with the ground truth that the smoothed track must approach better than the filtered one.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <random>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "batch_map.hpp"
#include "filter_test_utils.hpp"
#include "scalar_models.hpp"
#include "sf_estimation/extended_kalman_filter.hpp"
#include "sf_estimation/kalman_filter.hpp"
#include "sf_estimation/rts_smoother.hpp"
#include "sf_estimation/unscented_kalman_filter.hpp"
#include "sf_estimation/unscented_rts_smoother.hpp"
#include "smoother_test_problems.hpp"

// Named, not anonymous: compiled in a unity group (sf_estimation/CMakeLists.txt).
namespace rts_smoother_test {

using estimation::AngularComponents;
using estimation::ExtendedKalmanFilter;
using estimation::FilteredPeriod;
using estimation::Index;
using estimation::KalmanFilter;
using estimation::Matrix;
using estimation::Measurement;
using estimation::UnscentedKalmanFilter;
using estimation::UnscentedParameters;
using estimation::Vector;
using estimation::wrapAngle;
using sftest::BatchProblem;
using sftest::largestGapInSigmas;
using sftest::LinearModel;
using sftest::linearProblem;
using sftest::relDiff;
using sftest::SmoothedRun;
using sftest::Unicycle;
using sftest::UnicycleDrive;

// ---------------------------------------------------------------------------------------------
// (b) Two steps of a scalar random walk, by hand. x' = x + w, z = x + v, Q = R = 1, x_0 ~
// N(0, 1), z_1 = 3, z_2 = 6.
//   forward:  P(1|0) = 2, K = 2/3, x_1 = 2, P_1 = 2/3;
//             P(2|1) = 5/3, K = 5/8, x_2 = 2 + 5/8 (6 - 2) = 4.5, P_2 = 5/8.
//   backward: period 2 is its filtered (4.5, 5/8);
//             G_1 = (2/3) / (5/3) = 2/5, x_1^s = 2 + 2/5 (4.5 - 2) = 3,
//               P_1^s = 2/3 + 4/25 (5/8 - 5/3) = 2/3 - 1/6 = 1/2;
//             G_0 = 1 / 2, x_0^s = 0 + 1/2 (3 - 0) = 1.5, P_0^s = 1 + 1/4 (1/2 - 2) = 5/8.
//   check:    the information matrix of (x_0, x_1, x_2) is [2 -1 0; -1 3 -1; 0 -1 2] with
//             right-hand side (0, 3, 6): solved by (1.5, 3, 4.5); determinant 8, and the
//             diagonal of its inverse is (5/8, 4/8, 5/8).
// ---------------------------------------------------------------------------------------------
const std::vector<double> kHandMeans{1.5, 3.0, 4.5};
const std::vector<double> kHandVariances{5.0 / 8.0, 0.5, 5.0 / 8.0};

/// The hand case with the measurements scaled by `scale` (the means scale with them, the
/// variances do not) and shifted by `offset` (wrapped when the state is an angle).
template <class Filter>
void expectHandCase(const Filter& filter, double scale, double offset, bool angle,
                    double tolerance) {
  const auto place = [&](double value) {
    return angle ? wrapAngle(offset + scale * value) : offset + scale * value;
  };
  std::vector<Vector<0>> u(3);
  std::vector<Measurement<1>> z{Measurement<1>::missing(),
                                Measurement<1>::complete(Vector<1>(place(3.0))),
                                Measurement<1>::complete(Vector<1>(place(6.0)))};
  const SmoothedRun<Filter> run(filter, u, z);
  ASSERT_EQ(run.smoothed.size(), 3u);
  for (std::size_t k = 0; k < 3; ++k) {
    EXPECT_NEAR(run.smoothed[k].x(0), place(kHandMeans[k]), tolerance) << "period " << k;
    EXPECT_NEAR(run.smoothed[k].P(0, 0), kHandVariances[k], tolerance) << "period " << k;
  }
}

const Matrix<1, 1> kOne = Matrix<1, 1>::Identity();

TEST(RtsSmootherHandCase, KalmanFilter) {
  const KalmanFilter<1, 1, 0> kf(kOne, Matrix<1, 0>(), kOne, kOne, kOne, Vector<1>(0.0), kOne);
  expectHandCase(kf, 1.0, 0.0, false, 1e-14);
}

TEST(RtsSmootherHandCase, ExtendedKalmanFilter) {
  const ExtendedKalmanFilter<sftest::IdentityModel> ekf({}, kOne, kOne, Vector<1>(0.0), kOne);
  expectHandCase(ekf, 1.0, 0.0, false, 1e-14);
}

TEST(RtsSmootherHandCase, UnscentedKalmanFilter) {
  // alpha = 1e-3 weighs the central point by -1e6: the unscented moments of the identity are
  // exact up to that cancellation.
  const UnscentedKalmanFilter<sftest::IdentityModel> ukf({}, kOne, kOne, Vector<1>(0.0), kOne);
  expectHandCase(ukf, 1.0, 0.0, false, 1e-9);
}

// The same case on a heading near pi, halved so that every innovation stays within pi: the
// track crosses the wrap after period 0, which only the wrapped difference
// x_k+1^s - x(k+1|k) and the wrapped result follow.
TEST(RtsSmootherHandCase, AngleStateAcrossTheWrap) {
  const AngularComponents angles{{0}, {0}};
  const double offset = 3.14159265358979323846 - 1.0;
  const Vector<1> x0(offset);
  expectHandCase(ExtendedKalmanFilter<sftest::IdentityModel>({}, kOne, kOne, x0, kOne, angles), 0.5,
                 offset, true, 1e-12);
  expectHandCase(UnscentedKalmanFilter<sftest::IdentityModel>({}, kOne, kOne, x0, kOne,
                                                              UnscentedParameters{}, angles),
                 0.5, offset, true, 1e-9);
}

// A period whose belief was set (not predicted) cuts the record: the periods before it are
// smoothed as a record of their own.
TEST(RtsSmootherRecord, SetBeliefSeparatesTheSegments) {
  const KalmanFilter<1, 1, 0> kf(kOne, Matrix<1, 0>(), kOne, kOne, kOne, Vector<1>(0.0), kOne);
  const auto smoother = smootherFor(kf);
  using Period = FilteredPeriod<1, 0>;
  const auto period = [](double x, double P, bool predicted) {
    return Period{Vector<1>(x), Matrix<1, 1>(P), Vector<0>(), predicted};
  };
  // The hand case's filtered periods, then a belief set to (10, 1) and one predicted period.
  const std::vector<Period> head{period(0.0, 1.0, false), period(2.0, 2.0 / 3.0, true),
                                 period(4.5, 5.0 / 8.0, true)};
  std::vector<Period> record = head;
  record.push_back(period(10.0, 1.0, false));
  record.push_back(period(10.5, 0.5, true));
  std::vector<estimation::SmoothedPeriod<1>> smoothed;
  smoother.smooth(record, smoothed);
  ASSERT_EQ(smoothed.size(), 5u);
  for (std::size_t k = 0; k < 3; ++k) {
    EXPECT_NEAR(smoothed[k].x(0), kHandMeans[k], 1e-14) << "period " << k;
    EXPECT_NEAR(smoothed[k].P(0, 0), kHandVariances[k], 1e-14) << "period " << k;
  }
  // Period 3 is smoothed from period 4: G = 1 / 2, x = 10 + (10.5 - 10) / 2, P = 1 + (0.5 - 2) / 4.
  EXPECT_NEAR(smoothed[3].x(0), 10.25, 1e-14);
  EXPECT_NEAR(smoothed[3].P(0, 0), 0.625, 1e-14);
}

// A state known exactly (P = 0, Q = 0) has a semi-definite prediction: nothing flows back, and
// the smoothed period is the filtered one, finite.
TEST(RtsSmootherRecord, KnownStateIsItsOwnSmoothedState) {
  const Matrix<1, 1> zero = Matrix<1, 1>::Zero();
  const KalmanFilter<1, 1, 0> kf(kOne, Matrix<1, 0>(), kOne, zero, kOne, Vector<1>(0.0), kOne);
  using Period = FilteredPeriod<1, 0>;
  const std::vector<Period> record{Period{Vector<1>(2.0), zero, Vector<0>(), false},
                                   Period{Vector<1>(2.0), zero, Vector<0>(), true}};
  std::vector<estimation::SmoothedPeriod<1>> smoothed;
  smootherFor(kf).smooth(record, smoothed);
  EXPECT_EQ(smoothed[0].x(0), 2.0);
  EXPECT_EQ(smoothed[0].P(0, 0), 0.0);
}

// The UKF's prediction from x ~ N(0, 1) through x^2 with alpha = 1, kappa = 0, beta = -10 is
// -9.99 in closed form (test_numerical_repairs.cpp), which the UKF repairs to 0 and commits as
// (1, 0). The smoother repairs it as the UKF did: a zero prediction, nothing flows back, and
// period 0 keeps its (0, 1); the cross covariance is 0 too (-10 (0)(-1) + (1)(0) / 2 +
// (-1)(0) / 2).
TEST(RtsSmootherRecord, UnscentedPredictionRepairedAsTheFilterDid) {
  UnscentedParameters params;
  params.alpha = 1.0;
  params.beta = -10.0;
  params.kappa = 0.0;
  const UnscentedKalmanFilter<sftest::SquareTransition> ukf({}, Matrix<1, 1>::Constant(0.01),
                                                            Matrix<1, 1>::Constant(0.1),
                                                            Vector<1>::Zero(), kOne, params);
  const SmoothedRun<UnscentedKalmanFilter<sftest::SquareTransition>> run(
      ukf, std::vector<Vector<0>>(2), {Measurement<1>::missing(), Measurement<1>::missing()});
  ASSERT_EQ(run.smoothed.size(), 2u);
  EXPECT_NEAR(run.filtered[1].x(0), 1.0, 1e-15);
  EXPECT_EQ(run.filtered[1].P(0, 0), 0.0);
  EXPECT_EQ(run.smoothed[0].x(0), 0.0);
  EXPECT_EQ(run.smoothed[0].P(0, 0), 1.0);
}

// A record whose prediction is indefinite (a negative variance) is refused with an error that
// names it, not turned into a track.
TEST(RtsSmootherRecord, IndefinitePredictionIsRefused) {
  const KalmanFilter<1, 1, 0> kf(kOne, Matrix<1, 0>(), kOne, kOne, kOne, Vector<1>(0.0), kOne);
  using Period = FilteredPeriod<1, 0>;
  const std::vector<Period> record{Period{Vector<1>(0.0), Matrix<1, 1>(-3.0), Vector<0>(), false},
                                   Period{Vector<1>(0.0), kOne, Vector<0>(), true}};
  std::vector<estimation::SmoothedPeriod<1>> smoothed;
  try {
    smootherFor(kf).smooth(record, smoothed);
    FAIL() << "no error";
  } catch (const estimation::NumericalError& e) {
    EXPECT_NE(std::string(e.what()).find("predicted covariance is indefinite"), std::string::npos)
        << e.what();
  }
}

// ---------------------------------------------------------------------------------------------
// (a) Linear model against the batch solution: means and covariances to 1e-9 relative.
// ---------------------------------------------------------------------------------------------

TEST(RtsSmootherLinear, EqualsBatchLeastSquares) {
  const BatchProblem<LinearModel> problem = linearProblem();
  const LinearModel& model = problem.model;
  const KalmanFilter<2, 2, 1> kf(model.A, model.B, model.H, problem.Q, problem.R, problem.x0,
                                 problem.P0);
  const SmoothedRun<KalmanFilter<2, 2, 1>> smoothed(kf, problem.u, problem.z);
  const sftest::BatchSolution batch =
      sftest::solveBatch(problem, std::vector<Eigen::VectorXd>(41, Eigen::VectorXd::Zero(2)));
  ASSERT_EQ(smoothed.smoothed.size(), batch.x.size());
  for (std::size_t k = 0; k < batch.x.size(); ++k) {
    EXPECT_LT(relDiff(smoothed.smoothed[k].x, batch.x[k]), 1e-9) << "period " << k;
    EXPECT_LT(relDiff(smoothed.smoothed[k].P, batch.P[k]), 1e-9) << "period " << k;
  }
  // The last period is its filtered estimate; earlier ones moved (the test is not vacuous).
  EXPECT_GT(relDiff(smoothed.filtered[20].x, batch.x[20]), 1e-3);
}

// ---------------------------------------------------------------------------------------------
// (c) A unicycle with noisy position fixes: EKF and UKF smoothers against the Gauss-Newton MAP
// track of the same problem, and against the ground truth.
// ---------------------------------------------------------------------------------------------

/// The smoother of `filter` (its parameters taken from `drive`) on `drive`: the largest gap to
/// the MAP track in MAP standard deviations, and the filtered and smoothed position RMSE.
struct NonlinearResult {
  double gap, filteredRmse, smoothedRmse;
};

template <class Filter>
NonlinearResult smoothDrive(const Filter& filter, const UnicycleDrive& drive) {
  const SmoothedRun<Filter> run(filter, drive.problem.u, drive.problem.z);
  std::vector<Eigen::VectorXd> start;
  for (const auto& period : run.filtered) start.emplace_back(period.x);
  const sftest::BatchSolution map = sftest::solveBatch(drive.problem, start);
  return {largestGapInSigmas(run, map), drive.positionRmse(run.filtered),
          drive.positionRmse(run.smoothed)};
}

/// The RTS pass linearises (EKF) or sigma-point-approximates (UKF) each transition about the
/// filtered estimate instead of iterating to the MAP track: an error of first order in the
/// noise, measured as 0.45 (EKF) and 0.29 (UKF) MAP standard deviations at most over the 300
/// periods (tolerance 0.6), and ten times smaller with every noise ten times smaller (0.045,
/// 0.027; tolerance 0.06). A wrong model, control or gain would not shrink with the noise. The
/// smoothed position RMSE was 0.52 of the filtered one for both (tolerance 0.7).
template <class MakeFilter>
void expectCloseToMapAndTruth(const MakeFilter& makeFilter) {
  const UnicycleDrive drive(300, 11, 1.0);
  const NonlinearResult result = smoothDrive(makeFilter(drive.problem), drive);
  EXPECT_LT(result.gap, 0.6);
  EXPECT_LT(result.smoothedRmse, 0.7 * result.filteredRmse)
      << "filtered " << result.filteredRmse << ", smoothed " << result.smoothedRmse;
  const UnicycleDrive quiet(300, 11, 0.1);
  EXPECT_LT(smoothDrive(makeFilter(quiet.problem), quiet).gap, 0.06);
}

TEST(RtsSmootherNonlinear, ExtendedKalmanFilterNearMapTrack) {
  expectCloseToMapAndTruth([](const BatchProblem<Unicycle>& p) {
    return ExtendedKalmanFilter<Unicycle>(p.model, p.Q, p.R, p.x0, p.P0, p.angles);
  });
}

TEST(RtsSmootherNonlinear, UnscentedKalmanFilterNearMapTrack) {
  expectCloseToMapAndTruth([](const BatchProblem<Unicycle>& p) {
    return UnscentedKalmanFilter<Unicycle>(p.model, p.Q, p.R, p.x0, p.P0, UnscentedParameters{},
                                           p.angles);
  });
}

// Without any measurement every filtered estimate is the previous one's prediction, so the
// backward pass has nothing to move: x_s(k) = x_f(k) + G (x_s(k+1) - x(k+1|k)) with
// x_s(k+1) = x_f(k+1) = x(k+1|k). That holds only if the smoother re-derives the filter's own
// prediction, here the UKF's propagated mean (PredictedMean::Propagated) on a unicycle whose
// heading is uncertain enough that the sigma points' average would differ.
TEST(RtsSmootherRecord, UnscentedPropagatedMeanIsTheFiltersPrediction) {
  UnicycleDrive drive(100, 5, 1.0);
  for (auto& z : drive.problem.z) z = Measurement<2>::missing();
  drive.problem.P0 = Vector<3>(0.1, 0.1, 1.0).asDiagonal();
  for (const auto mean :
       {estimation::PredictedMean::Propagated, estimation::PredictedMean::SigmaPointAverage}) {
    UnscentedParameters params;
    params.predictedMean = mean;
    const BatchProblem<Unicycle>& p = drive.problem;
    const SmoothedRun<UnscentedKalmanFilter<Unicycle>> run(
        UnscentedKalmanFilter<Unicycle>(p.model, p.Q, p.R, p.x0, p.P0, params, p.angles), p.u, p.z);
    double largest = 0.0;
    for (std::size_t k = 0; k < run.filtered.size(); ++k) {
      largest = std::max(largest, (run.smoothed[k].x - run.filtered[k].x).cwiseAbs().maxCoeff());
    }
    EXPECT_LT(largest, 1e-9) << "predicted mean " << static_cast<int>(mean);
  }
}

}  // namespace rts_smoother_test
