// Problems shared by the smoother tests (test_rts_smoother.cpp, and the Ceres reference of
// ceres/test_rts_smoother_ceres.cpp): a recorded and smoothed filter run, a linear model and
// a simulated unicycle with position fixes, as batch problems (batch_map.hpp).
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

#include "batch_map.hpp"
#include "filter_test_utils.hpp"
#include "sf_estimation/angles.hpp"
#include "sf_estimation/batch_map_smoother.hpp"
#include "sf_estimation/rts_smoother.hpp"

namespace sftest {

using estimation::FilteredPeriod;
using estimation::wrapAngle;

/// Runs `filter` over controls u[1..T] and measurements z[1..T], recording period 0 (the
/// initial belief) and every filtered period, and smooths the record.
template <class Filter, int N = Filter::StateSize, int M = Filter::MeasurementSize,
          int L = Filter::ControlSize>
struct SmoothedRun {
  static constexpr int StateSize = N, MeasurementSize = M, ControlSize = L;
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

/// The batch smoother's record of a run: each filtered period with the measurement of its
/// step (z[0], of the initial belief, is not used).
template <class Run, int N = Run::StateSize, int M = Run::MeasurementSize, int L = Run::ControlSize>
std::vector<estimation::MeasuredPeriod<N, M, L>> measuredRecord(
    const Run& run, const std::vector<Measurement<M>>& z) {
  std::vector<estimation::MeasuredPeriod<N, M, L>> record;
  for (std::size_t k = 0; k < run.filtered.size(); ++k) record.push_back({run.filtered[k], z[k]});
  return record;
}

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

/// The linear reference problem: 2 states, correlated Q and R, 40 periods with random
/// controls, random missing measurement entries and every 9th period without any.
inline BatchProblem<LinearModel> linearProblem() {
  LinearModel model;
  model.A << 1.0, 0.1, -0.05, 0.98;
  model.B << 0.005, 0.1;
  model.H << 1.0, 0.0, 0.3, 1.0;
  BatchProblem<LinearModel> problem{model, {}, {}, Vector<2>(0.5, -0.2), {}, {}, {}, {}};
  problem.Q << 0.02, 0.004, 0.004, 0.03;
  problem.R << 0.4, 0.1, 0.1, 0.25;
  problem.P0 << 0.5, 0.1, 0.1, 0.3;
  const auto run = simulateLinear<2, 2, 1>(model.A, model.B, model.H, problem.Q, problem.R,
                                           problem.x0, 40, 7, 0.3, 9, 1.0);
  problem.u.push_back(Vector<1>::Zero());
  problem.z.push_back(Measurement<2>::missing());
  for (const auto& step : run) {
    problem.u.push_back(step.u);
    problem.z.push_back(step.z);
  }
  return problem;
}

/// State (x, y, heading), control (speed, turn rate), period T; a position fix z = (x, y).
struct Unicycle {
  static constexpr int StateSize = 3, MeasurementSize = 2, ControlSize = 2;
  double T = 0.1;
  Index stateSize() const { return 3; }
  Index measurementSize() const { return 2; }
  Index controlSize() const { return 2; }
  template <class S>
  void transition(const Eigen::Matrix<S, 3, 1>& x, const Vector<2>& u,
                  Eigen::Matrix<S, 3, 1>& next) const {
    using std::cos;
    using std::sin;
    next(0) = x(0) + u(0) * T * cos(x(2));
    next(1) = x(1) + u(0) * T * sin(x(2));
    next(2) = x(2) + u(1) * T;
  }
  template <class S>
  void observation(const Eigen::Matrix<S, 3, 1>& x, Eigen::Matrix<S, 2, 1>& z) const {
    z(0) = x(0);
    z(1) = x(1);
  }
};

/// A drive of `steps` periods along a loop (the heading wraps several times), the truth
/// perturbed by Q, a position fix every third period with noise R.
struct UnicycleDrive {
  BatchProblem<Unicycle> problem;
  std::vector<Vector<3>> truth;

  UnicycleDrive(int steps, std::uint64_t seed, double sigma) {
    const double variance = sigma * sigma;
    problem.Q = variance * Vector<3>(0.02 * 0.02, 0.02 * 0.02, 0.03 * 0.03).asDiagonal();
    problem.R = variance * Vector<2>(0.5 * 0.5, 0.5 * 0.5).asDiagonal();
    problem.x0 = Vector<3>(0.0, 0.0, 3.0);
    problem.P0 = variance * Vector<3>(0.1, 0.1, 0.05).asDiagonal();
    problem.angles.states = {2};
    std::mt19937_64 rng(seed);
    std::normal_distribution<double> normal(0.0, 1.0);
    const Eigen::Vector3d rootQ = problem.Q.diagonal().cwiseSqrt();
    Vector<3> x = problem.x0;
    truth.push_back(x);
    problem.u.push_back(Vector<2>::Zero());
    problem.z.push_back(Measurement<2>::missing());
    for (int k = 1; k <= steps; ++k) {
      const Vector<2> u(1.0 + 0.5 * std::sin(0.01 * k), 0.8 * std::cos(0.013 * k));
      Vector<3> next;
      problem.model.transition(x, u, next);
      for (Index i = 0; i < 3; ++i) next(i) += rootQ(i) * normal(rng);
      next(2) = wrapAngle(next(2));
      x = next;
      truth.push_back(x);
      problem.u.push_back(u);
      Measurement<2> z = Measurement<2>::missing();
      z.value = x.head<2>() + 0.5 * sigma * Vector<2>(normal(rng), normal(rng));
      z.available.setConstant(k % 3 == 0);
      problem.z.push_back(z);
    }
  }

  /// Root mean square position error of a track against the truth.
  template <class Track>
  double positionRmse(const Track& track) const {
    double sum = 0.0;
    for (std::size_t k = 0; k < truth.size(); ++k) {
      sum += (track[k].x.template head<2>() - truth[k].head<2>()).squaredNorm();
    }
    return std::sqrt(sum / static_cast<double>(truth.size()));
  }
};

/// Largest gap of the smoothed track to the MAP track, in MAP standard deviations.
template <class Run>
double largestGapInSigmas(const Run& run, const sftest::BatchSolution& map) {
  double gap = 0.0;
  for (std::size_t k = 0; k < map.x.size(); ++k) {
    Vector<3> difference = run.smoothed[k].x - map.x[k];
    difference(2) = wrapAngle(difference(2));
    for (Index i = 0; i < 3; ++i) {
      gap = std::max(gap, std::abs(difference(i)) / std::sqrt(map.P[k](i, i)));
    }
  }
  return gap;
}

}  // namespace sftest
