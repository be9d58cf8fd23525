// The smoothers against the batch maximum-a-posteriori track solved by Ceres (issue 39's
// reference; fuse builds on the same solver): the whole track as one nonlinear least-squares
// problem, each residual (prior, transition, present measurement rows) whitened by the square
// root of its information and differentiated by Ceres's own automatic differentiation, solved
// to convergence, the covariance from Ceres. Independent of the dense Gauss-Newton reference
// of test_rts_smoother.cpp (batch_map.hpp), with which it is also compared. An optional test
// program: built only where Ceres is installed (Debian: libceres-dev, doc/smoothing.md).
#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

#include <ceres/ceres.h>
#include <gtest/gtest.h>

#include "../batch_map.hpp"
#include "../smoother_test_problems.hpp"
#include "sf_estimation/batch_map_smoother.hpp"
#include "sf_estimation/extended_kalman_filter.hpp"
#include "sf_estimation/kalman_filter.hpp"
#include "sf_estimation/rts_smoother.hpp"
#include "sf_estimation/unscented_kalman_filter.hpp"
#include "sf_estimation/unscented_rts_smoother.hpp"

namespace {

using estimation::Index;
using estimation::Matrix;
using estimation::Vector;
using estimation::wrapAngle;
using sftest::BatchProblem;
using sftest::BatchSolution;
using sftest::relDiff;

inline double valueOf(double v) { return v; }
template <class T, int D>
double valueOf(const ceres::Jet<T, D>& j) {
  return j.a;
}

/// a shifted by the multiple of 2 pi that wraps its value (the derivative is unchanged).
template <class T>
T wrapped(const T& a) {
  const double v = valueOf(a);
  return a + (wrapAngle(v) - v);
}

/// S with S^T S = covariance^-1 (S = L^-1 for covariance = L L^T).
Eigen::MatrixXd squareRootInformation(const Eigen::MatrixXd& covariance) {
  const Eigen::LLT<Eigen::MatrixXd> llt(covariance);
  return llt.matrixL().solve(Eigen::MatrixXd::Identity(covariance.rows(), covariance.cols()));
}

/// r = S wrap(a - b) for the rows of `rows` (the others 0), angle rows per `angles`.
template <class T, int Size>
void whiten(const Eigen::Matrix<T, Size, 1>& difference, const std::vector<Index>& rows,
            const std::vector<bool>& angles, const Eigen::MatrixXd& S, T* r) {
  const Index k = static_cast<Index>(rows.size());
  Eigen::Matrix<T, Eigen::Dynamic, 1> e(k);
  for (Index i = 0; i < k; ++i) {
    const Index row = rows[static_cast<std::size_t>(i)];
    e(i) = angles[static_cast<std::size_t>(row)] ? wrapped(difference(row)) : difference(row);
  }
  for (Index i = 0; i < Size; ++i) r[i] = T(0.0);
  for (Index i = 0; i < k; ++i) {
    for (Index j = 0; j <= i; ++j) r[i] += S(i, j) * e(j);  // S is lower triangular
  }
}

template <class Model>
struct PriorResidual {
  static constexpr int N = Model::StateSize;
  Vector<N> mean;
  std::vector<Index> rows;
  std::vector<bool> angles;
  Eigen::MatrixXd S;
  template <class T>
  bool operator()(const T* x, T* r) const {
    const Eigen::Matrix<T, N, 1> difference =
        Eigen::Map<const Eigen::Matrix<T, N, 1>>(x) - mean.template cast<T>();
    whiten<T, N>(difference, rows, angles, S, r);
    return true;
  }
};

template <class Model>
struct TransitionResidual {
  static constexpr int N = Model::StateSize;
  Model model;
  Vector<Model::ControlSize> u;
  std::vector<Index> rows;
  std::vector<bool> angles;
  Eigen::MatrixXd S;
  template <class T>
  bool operator()(const T* previous, const T* current, T* r) const {
    const Eigen::Matrix<T, N, 1> before = Eigen::Map<const Eigen::Matrix<T, N, 1>>(previous);
    Eigen::Matrix<T, N, 1> predicted;
    model.transition(before, u, predicted);
    const Eigen::Matrix<T, N, 1> difference =
        Eigen::Map<const Eigen::Matrix<T, N, 1>>(current) - predicted;
    whiten<T, N>(difference, rows, angles, S, r);
    return true;
  }
};

template <class Model>
struct MeasurementResidual {
  static constexpr int N = Model::StateSize, M = Model::MeasurementSize;
  Model model;
  Vector<M> z;
  std::vector<Index> rows;  ///< the present entries
  std::vector<bool> angles;
  Eigen::MatrixXd S;  ///< of R's present rows and columns
  template <class T>
  bool operator()(const T* x, T* r) const {
    Eigen::Matrix<T, M, 1> expected;
    model.observation(Eigen::Matrix<T, N, 1>(Eigen::Map<const Eigen::Matrix<T, N, 1>>(x)),
                      expected);
    whiten<T, M>(Eigen::Matrix<T, M, 1>(expected - z.template cast<T>()), rows, angles, S, r);
    return true;
  }
};

std::vector<Index> allRows(Index n) {
  std::vector<Index> rows;
  for (Index i = 0; i < n; ++i) rows.push_back(i);
  return rows;
}

std::vector<bool> angleFlags(const std::vector<Index>& indices, Index n) {
  std::vector<bool> flags(static_cast<std::size_t>(n), false);
  for (const Index i : indices) flags[static_cast<std::size_t>(i)] = true;
  return flags;
}

/// The residual blocks of `problem` over the states `x` (T + 1 blocks of n doubles).
template <class Model>
void addResiduals(const BatchProblem<Model>& problem, std::vector<Eigen::VectorXd>& x,
                  ceres::Problem& solverProblem) {
  constexpr int N = Model::StateSize, M = Model::MeasurementSize;
  const Index n = problem.x0.size();
  const std::vector<bool> stateAngles = angleFlags(problem.angles.states, n);
  const std::vector<bool> measAngles = angleFlags(problem.angles.measurements, problem.R.rows());
  solverProblem.AddResidualBlock(
      new ceres::AutoDiffCostFunction<PriorResidual<Model>, N, N>(new PriorResidual<Model>{
          problem.x0, allRows(n), stateAngles, squareRootInformation(problem.P0)}),
      nullptr, x[0].data());
  const Eigen::MatrixXd SQ = squareRootInformation(problem.Q);
  for (std::size_t k = 1; k < x.size(); ++k) {
    solverProblem.AddResidualBlock(
        new ceres::AutoDiffCostFunction<TransitionResidual<Model>, N, N, N>(
            new TransitionResidual<Model>{problem.model, problem.u[k], allRows(n), stateAngles,
                                          SQ}),
        nullptr, x[k - 1].data(), x[k].data());
    const std::vector<Index> rows = sftest::presentRows(problem.z[k]);
    if (rows.empty()) continue;
    solverProblem.AddResidualBlock(
        new ceres::AutoDiffCostFunction<MeasurementResidual<Model>, M, N>(
            new MeasurementResidual<Model>{
                problem.model, problem.z[k].value, rows, measAngles,
                squareRootInformation(sftest::selectSquare(problem.R, rows))}),
        nullptr, x[k].data());
  }
}

/// The MAP track of `problem` from `start`, solved by Ceres to convergence (Levenberg-Marquardt
/// with a trust region so wide that each step is Gauss-Newton's), and each state's marginal
/// covariance from Ceres.
template <class Model>
BatchSolution solveWithCeres(const BatchProblem<Model>& problem,
                             std::vector<Eigen::VectorXd> start) {
  BatchSolution solution{std::move(start), {}, 0};
  ceres::Problem solverProblem;
  addResiduals(problem, solution.x, solverProblem);
  ceres::Solver::Options options;
  // Sparse: the normal matrix of a track is block tridiagonal.
  options.linear_solver_type = ceres::SPARSE_NORMAL_CHOLESKY;
  options.max_num_iterations = 100;
  options.function_tolerance = options.gradient_tolerance = options.parameter_tolerance = 1e-16;
  options.initial_trust_region_radius = options.max_trust_region_radius = 1e16;
  options.logging_type = ceres::SILENT;
  ceres::Solver::Summary summary;
  ceres::Solve(options, &solverProblem, &summary);
  EXPECT_TRUE(summary.IsSolutionUsable()) << summary.BriefReport();
  solution.iterations = static_cast<int>(summary.iterations.size());
  ceres::Covariance::Options covarianceOptions;
  covarianceOptions.algorithm_type = ceres::SPARSE_QR;
  ceres::Covariance covariance(covarianceOptions);
  std::vector<std::pair<const double*, const double*>> blocks;
  for (const auto& xk : solution.x) blocks.emplace_back(xk.data(), xk.data());
  EXPECT_TRUE(covariance.Compute(blocks, &solverProblem));
  const Index n = problem.x0.size();
  for (const auto& xk : solution.x) {
    Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor> block(n, n);
    covariance.GetCovarianceBlock(xk.data(), xk.data(), block.data());
    solution.P.emplace_back(block);
  }
  for (auto& xk : solution.x) {
    for (const Index i : problem.angles.states) xk(i) = wrapAngle(xk(i));
  }
  return solution;
}

// The linear case: RTS equals the Ceres batch solution to 1e-9 relative, means and
// covariances, on the linear problem of test_rts_smoother.cpp.
TEST(RtsSmootherCeres, LinearEqualsCeresBatch) {
  using Filter = estimation::KalmanFilter<2, 2, 1>;
  const BatchProblem<sftest::LinearModel> problem = sftest::linearProblem();
  const Filter kf(problem.model.A, problem.model.B, problem.model.H, problem.Q, problem.R,
                  problem.x0, problem.P0);
  const sftest::SmoothedRun<Filter> run(kf, problem.u, problem.z);
  const BatchSolution batch = solveWithCeres(
      problem, std::vector<Eigen::VectorXd>(problem.z.size(), Eigen::VectorXd::Zero(2)));
  ASSERT_EQ(run.smoothed.size(), batch.x.size());
  for (std::size_t k = 0; k < batch.x.size(); ++k) {
    EXPECT_LT(relDiff(run.smoothed[k].x, batch.x[k]), 1e-9) << "period " << k;
    EXPECT_LT(relDiff(run.smoothed[k].P, batch.P[k]), 1e-9) << "period " << k;
  }
}

// The unicycle of test_rts_smoother.cpp: Ceres's MAP track is the dense Gauss-Newton one
// (the two references agree: 1.4e-10 at most), and the EKF and UKF smoothers lie within the
// tolerance stated there (0.6 of the MAP's standard deviation; measured 0.45 and 0.29) of it.
TEST(RtsSmootherCeres, NonlinearNearCeresMapTrack) {
  using Unicycle = sftest::Unicycle;
  const sftest::UnicycleDrive drive(300, 11, 1.0);
  const auto& p = drive.problem;
  const estimation::ExtendedKalmanFilter<Unicycle> ekf(p.model, p.Q, p.R, p.x0, p.P0, p.angles);
  const estimation::UnscentedKalmanFilter<Unicycle> ukf(
      p.model, p.Q, p.R, p.x0, p.P0, estimation::UnscentedParameters{}, p.angles);
  const sftest::SmoothedRun<estimation::ExtendedKalmanFilter<Unicycle>> ekfRun(ekf, p.u, p.z);
  const sftest::SmoothedRun<estimation::UnscentedKalmanFilter<Unicycle>> ukfRun(ukf, p.u, p.z);
  std::vector<Eigen::VectorXd> start;
  for (const auto& period : ekfRun.filtered) start.emplace_back(period.x);
  const BatchSolution ceresMap = solveWithCeres(p, start);
  const BatchSolution denseMap = sftest::solveBatch(p, start);
  double gap = 0.0;
  for (std::size_t k = 0; k < ceresMap.x.size(); ++k) {
    Eigen::VectorXd difference = ceresMap.x[k] - denseMap.x[k];
    difference(2) = wrapAngle(difference(2));
    gap = std::max(gap, difference.cwiseAbs().maxCoeff());
    EXPECT_LT(relDiff(ceresMap.P[k], denseMap.P[k]), 1e-6) << "period " << k;
  }
  EXPECT_LT(gap, 1e-8);
  EXPECT_LT(sftest::largestGapInSigmas(ekfRun, ceresMap), 0.6);
  EXPECT_LT(sftest::largestGapInSigmas(ukfRun, ceresMap), 0.6);
}

// The batch MAP smoother (batch_map_smoother.hpp) against Ceres. Linear: the same track and
// covariances to 1e-9 relative. The unicycle: the same MAP track to 1e-6 of the MAP's standard
// deviation in every entry (the smoother stops at steps of 1e-9 of it), the covariance (the
// last iteration's smoothed one; Ceres's at its solution) to 1e-6 relative.
TEST(BatchMapSmootherCeres, LinearEqualsCeresBatch) {
  using Filter = estimation::KalmanFilter<2, 2, 1>;
  const BatchProblem<sftest::LinearModel> problem = sftest::linearProblem();
  const Filter kf(problem.model.A, problem.model.B, problem.model.H, problem.Q, problem.R,
                  problem.x0, problem.P0);
  const sftest::SmoothedRun<Filter> run(kf, problem.u, problem.z);
  const BatchSolution batch = solveWithCeres(
      problem, std::vector<Eigen::VectorXd>(problem.z.size(), Eigen::VectorXd::Zero(2)));
  auto smoother = estimation::batchSmootherFor(kf);
  std::vector<estimation::SmoothedPeriod<2>> smoothed;
  EXPECT_TRUE(smoother.smooth(sftest::measuredRecord(run, problem.z), smoothed).converged);
  ASSERT_EQ(smoothed.size(), batch.x.size());
  for (std::size_t k = 0; k < batch.x.size(); ++k) {
    EXPECT_LT(relDiff(smoothed[k].x, batch.x[k]), 1e-9) << "period " << k;
    EXPECT_LT(relDiff(smoothed[k].P, batch.P[k]), 1e-9) << "period " << k;
  }
}

TEST(BatchMapSmootherCeres, UnicycleEqualsCeresMapTrack) {
  using Unicycle = sftest::Unicycle;
  const sftest::UnicycleDrive drive(300, 11, 1.0);
  const auto& p = drive.problem;
  const estimation::ExtendedKalmanFilter<Unicycle> ekf(p.model, p.Q, p.R, p.x0, p.P0, p.angles);
  const sftest::SmoothedRun<estimation::ExtendedKalmanFilter<Unicycle>> run(ekf, p.u, p.z);
  std::vector<Eigen::VectorXd> start;
  for (const auto& period : run.filtered) start.emplace_back(period.x);
  const BatchSolution ceresMap = solveWithCeres(p, start);
  auto smoother = estimation::batchSmootherFor(ekf);
  std::vector<estimation::SmoothedPeriod<3>> smoothed;
  EXPECT_TRUE(smoother.smooth(sftest::measuredRecord(run, p.z), smoothed).converged);
  double gap = 0.0;
  for (std::size_t k = 0; k < ceresMap.x.size(); ++k) {
    Eigen::VectorXd difference = smoothed[k].x - ceresMap.x[k];
    difference(2) = wrapAngle(difference(2));
    for (Index i = 0; i < 3; ++i) {
      gap = std::max(gap, std::abs(difference(i)) / std::sqrt(ceresMap.P[k](i, i)));
    }
    EXPECT_LT(relDiff(smoothed[k].P, ceresMap.P[k]), 1e-6) << "period " << k;
  }
  EXPECT_LT(gap, 1e-6);
}

}  // namespace
