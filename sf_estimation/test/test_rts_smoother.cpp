// Tests of the RTS smoothers (rts_smoother.hpp, unscented_rts_smoother.hpp) against
// independent references: a two-step scalar case solved by hand, the dense batch
// least-squares solution of the whole track (batch_map.hpp) for a linear model, where RTS is
// exact, and the Gauss-Newton MAP track of a simulated unicycle for the EKF and UKF smoothers,
// with the ground truth that the smoothed track must approach better than the filtered one.
#include <cmath>
#include <cstdint>
#include <random>
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

namespace {

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
using sftest::relDiff;

/// Runs `filter` over controls u[1..T] and measurements z[1..T], recording period 0 (the
/// initial belief) and every filtered period, and smooths the record.
template <class Filter, int N = Filter::StateSize, int M = Filter::MeasurementSize,
          int L = Filter::ControlSize>
struct SmoothedRun {
  std::vector<FilteredPeriod<N, L>> filtered;
  std::vector<estimation::SmoothedPeriod<N>> smoothed;

  SmoothedRun(Filter filter, const std::vector<Vector<L>>& u,
              const std::vector<Measurement<M>>& z) {
    filtered.push_back(FilteredPeriod<N, L>::of(filter, false));
    for (std::size_t k = 1; k < z.size(); ++k) {
      filter.setControl(u[k]);
      filter.estimate(z[k]);
      filtered.push_back(FilteredPeriod<N, L>::of(filter));
    }
    smootherFor(filter).smooth(filtered, smoothed);
  }
};

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

// ---------------------------------------------------------------------------------------------
// (a) Linear model against the batch solution: means and covariances to 1e-9 relative.
// ---------------------------------------------------------------------------------------------

/// x' = A x + B u, z = H x as a model (for the batch reference).
struct LinearModel {
  static constexpr int StateSize = 2, MeasurementSize = 2, ControlSize = 1;
  Matrix<2, 2> A;
  Matrix<2, 1> B;
  Matrix<2, 2> H;
  Index stateSize() const { return 2; }
  Index measurementSize() const { return 2; }
  Index controlSize() const { return 1; }
  template <class S>
  void transition(const Eigen::Matrix<S, 2, 1>& x, const Vector<1>& u,
                  Eigen::Matrix<S, 2, 1>& next) const {
    next = A.cast<S>() * x + (B * u).cast<S>();
  }
  template <class S>
  void observation(const Eigen::Matrix<S, 2, 1>& x, Eigen::Matrix<S, 2, 1>& z) const {
    z = H.cast<S>() * x;
  }
};

TEST(RtsSmootherLinear, EqualsBatchLeastSquares) {
  LinearModel model;
  model.A << 1.0, 0.1, -0.05, 0.98;
  model.B << 0.005, 0.1;
  model.H << 1.0, 0.0, 0.3, 1.0;
  BatchProblem<LinearModel> problem{model, {}, {}, Vector<2>(0.5, -0.2), {}, {}, {}, {}};
  problem.Q << 0.02, 0.004, 0.004, 0.03;
  problem.R << 0.4, 0.1, 0.1, 0.25;
  problem.P0 << 0.5, 0.1, 0.1, 0.3;
  const auto run = sftest::simulateLinear<2, 2, 1>(model.A, model.B, model.H, problem.Q, problem.R,
                                                   problem.x0, 40, 7, 0.3, 9, 1.0);
  problem.u.push_back(Vector<1>::Zero());
  problem.z.push_back(Measurement<2>::missing());
  for (const auto& step : run) {
    problem.u.push_back(step.u);
    problem.z.push_back(step.z);
  }
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

}  // namespace
