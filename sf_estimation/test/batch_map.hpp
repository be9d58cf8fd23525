// The reference of the smoother tests: the maximum-a-posteriori track of a whole recording as
// one least-squares problem over all states x_0..x_T, every residual weighted by its
// information (P0^-1 for the prior on x_0, Q^-1 for each transition, the present rows' R^-1
// for each measurement), solved densely by Gauss-Newton on the normal equations. For a linear
// model one iteration is exact and the inverse of the normal matrix is the joint posterior
// covariance, whose diagonal blocks the RTS smoother must reproduce; for a nonlinear model the
// iterations converge to the MAP track (its Laplace covariance beside it). The normal matrix is
// block tridiagonal, factored by Eigen's sparse Cholesky: O(n^3 T) per iteration, so that the
// sanitizer build (-O0) runs the tests in seconds (dense, the two nonlinear tests took 98 s each
// there).
#pragma once

#include <algorithm>
#include <cstddef>
#include <stdexcept>
#include <vector>

#include <Eigen/Dense>
#include <Eigen/SparseCholesky>

#include "filter_test_utils.hpp"
#include "sf_estimation/angles.hpp"
#include "sf_estimation/jacobian.hpp"
#include "sf_estimation/measurement.hpp"

namespace sftest {

/// x_0 ~ N(x0, P0); x_k = f(x_k-1, u[k]) + w, z[k] = h(x_k) + v for k = 1..T (u[0], z[0]
/// unused).
template <class Model>
struct BatchProblem {
  static constexpr int N = Model::StateSize, M = Model::MeasurementSize, L = Model::ControlSize;
  Model model;
  Matrix<N, N> Q;
  Matrix<M, M> R;
  Vector<N> x0;
  Matrix<N, N> P0;
  std::vector<Vector<L>> u;
  std::vector<Measurement<M>> z;
  estimation::AngularComponents angles;
};

struct BatchSolution {
  std::vector<Eigen::VectorXd> x;
  std::vector<Eigen::MatrixXd> P;  ///< diagonal blocks of the inverse normal matrix
  int iterations = 0;
};

namespace detail {

/// Normal equations of the linearised problem: information matrix (as triplets of its blocks)
/// and gradient J^T W r.
struct NormalEquations {
  std::vector<Eigen::Triplet<double>> information;
  Eigen::VectorXd gradient;

  /// Adds one residual r (rows of a state block pair) with Jacobians Ja (block a) and Jb
  /// (block b; b < 0: none) and weight W.
  void add(Index n, Index a, const Eigen::MatrixXd& Ja, Index b, const Eigen::MatrixXd& Jb,
           const Eigen::VectorXd& r, const Eigen::MatrixXd& W) {
    addBlock(n, a, a, Ja.transpose() * W * Ja);
    gradient.segment(a * n, n) += Ja.transpose() * W * r;
    if (b < 0) return;
    addBlock(n, b, b, Jb.transpose() * W * Jb);
    addBlock(n, a, b, Ja.transpose() * W * Jb);
    addBlock(n, b, a, Jb.transpose() * W * Ja);
    gradient.segment(b * n, n) += Jb.transpose() * W * r;
  }

  /// The sparse normal matrix of a track of `states` states of size n (duplicates summed).
  Eigen::SparseMatrix<double> matrix(Index n, Index states) const {
    Eigen::SparseMatrix<double> m(states * n, states * n);
    m.setFromTriplets(information.begin(), information.end());
    return m;
  }

 private:
  void addBlock(Index n, Index a, Index b, const Eigen::MatrixXd& block) {
    for (Index i = 0; i < n; ++i) {
      for (Index j = 0; j < n; ++j) information.emplace_back(a * n + i, b * n + j, block(i, j));
    }
  }
};

/// The normal equations of `problem` linearised at the track `x`.
template <class Model>
NormalEquations linearise(const BatchProblem<Model>& problem,
                          const std::vector<Eigen::VectorXd>& x) {
  constexpr int N = Model::StateSize, M = Model::MeasurementSize;
  const Index n = problem.x0.size(), m = problem.R.rows();
  const Index T = static_cast<Index>(x.size()) - 1;
  const estimation::AngleMask<N> stateAngles(problem.angles.states, n, "batch", "state");
  const estimation::AngleMask<M> measAngles(problem.angles.measurements, m, "batch", "meas");
  NormalEquations eq{{}, Eigen::VectorXd::Zero((T + 1) * n)};
  const Eigen::MatrixXd I = Eigen::MatrixXd::Identity(n, n);
  Vector<N> r = x[0] - problem.x0;
  stateAngles.wrap(r);
  eq.add(n, 0, I, -1, I, r, problem.P0.inverse());
  const Eigen::MatrixXd Qinv = problem.Q.inverse();
  for (Index k = 1; k <= T; ++k) {
    const auto kk = static_cast<std::size_t>(k);
    Vector<N> previous = x[kk - 1], predicted(n);
    Matrix<N, N> F(n, n);
    estimation::transitionJacobian(problem.model, previous, problem.u[kk], F);
    problem.model.transition(previous, problem.u[kk], predicted);
    r = x[kk] - predicted;
    stateAngles.wrap(r);
    eq.add(n, k - 1, -F, k, I, r, Qinv);
    const std::vector<Index> rows = presentRows(problem.z[kk]);
    if (rows.empty()) continue;
    Vector<N> state = x[kk];
    Vector<M> expected(m);
    Matrix<M, N> H(m, n);
    problem.model.observation(state, expected);
    estimation::observationJacobian(problem.model, state, H);
    Vector<M> innovation = expected - problem.z[kk].value;
    measAngles.wrap(innovation);
    eq.add(n, k, selectRows(H, rows), -1, I, selectRows(innovation, rows),
           selectSquare(problem.R, rows).inverse());
  }
  return eq;
}

}  // namespace detail

/// Gauss-Newton from the track `start` (T + 1 states) until the largest step is below
/// `tolerance` relative to the largest state entry (throws std::runtime_error after
/// `maxIterations`).
template <class Model>
BatchSolution solveBatch(const BatchProblem<Model>& problem, std::vector<Eigen::VectorXd> start,
                         double tolerance = 1e-12, int maxIterations = 50) {
  const Index n = problem.x0.size();
  const estimation::AngleMask<Model::StateSize> angles(problem.angles.states, n, "batch", "state");
  BatchSolution solution{std::move(start), {}, 0};
  const Index states = static_cast<Index>(solution.x.size());
  Eigen::SimplicialLLT<Eigen::SparseMatrix<double>> factor;
  for (;;) {
    const detail::NormalEquations eq = detail::linearise(problem, solution.x);
    factor.compute(eq.matrix(n, states));
    if (factor.info() != Eigen::Success) throw std::runtime_error("batch: singular information");
    const Eigen::VectorXd step = -factor.solve(eq.gradient);
    for (std::size_t k = 0; k < solution.x.size(); ++k) {
      Vector<Model::StateSize> xk = solution.x[k] + step.segment(static_cast<Index>(k) * n, n);
      angles.wrap(xk);
      solution.x[k] = xk;
    }
    ++solution.iterations;
    double scale = 1.0;
    for (const auto& xk : solution.x) scale = std::max(scale, xk.cwiseAbs().maxCoeff());
    if (step.cwiseAbs().maxCoeff() < tolerance * scale) break;
    if (solution.iterations >= maxIterations) throw std::runtime_error("batch: no convergence");
  }
  // The diagonal blocks of the inverse normal matrix, a block column at a time.
  for (Index k = 0; k < states; ++k) {
    Eigen::MatrixXd unit = Eigen::MatrixXd::Zero(states * n, n);
    unit.block(k * n, 0, n, n).setIdentity();
    const Eigen::MatrixXd column = factor.solve(unit);
    solution.P.push_back(column.block(k * n, 0, n, n));
  }
  return solution;
}

}  // namespace sftest
