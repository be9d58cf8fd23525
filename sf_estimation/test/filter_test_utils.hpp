// Helpers shared by the filter tests: matrix comparison, simulated runs of linear models,
// the hand-derived Jacobians of nav3ctrl, and a model wrapper keeping only chosen
// measurement rows (the "reduced" reference for missing measurements).
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

#include "sf_estimation/measurement.hpp"
#include "sf_estimation/models/navigation.hpp"
#include "sf_estimation/types.hpp"
#include "sf_estimation/unscented_transform.hpp"

namespace sftest {

using estimation::Dynamic;
using estimation::Index;
using estimation::Matrix;
using estimation::Measurement;
using estimation::Vector;

/// Largest absolute entry of a - b.
template <class A, class B>
double maxAbsDiff(const Eigen::MatrixBase<A>& a, const Eigen::MatrixBase<B>& b) {
  if (a.size() == 0 && b.size() == 0) return 0.0;
  return (a - b).cwiseAbs().maxCoeff();
}

/// Largest absolute entry (the scale a relative tolerance refers to).
template <class A>
double scaleOf(const Eigen::MatrixBase<A>& a) {
  return a.size() == 0 ? 0.0 : a.cwiseAbs().maxCoeff();
}

/// max |a - ref| / max |ref| (absolute difference when ref is zero).
template <class A, class B>
double relDiff(const Eigen::MatrixBase<A>& a, const Eigen::MatrixBase<B>& ref) {
  const double scale = scaleOf(ref);
  const double diff = maxAbsDiff(a, ref);
  return scale > 0.0 ? diff / scale : diff;
}

/// The eigenvalues of a symmetric matrix, in increasing order.
Eigen::VectorXd symmetricEigenvalues(const Eigen::MatrixXd& P);

/// A square root of a symmetric positive semi-definite matrix (for simulating noise).
Eigen::MatrixXd psdRoot(const Eigen::MatrixXd& P);

/// One step of input: the control set before the step and the measurement of the step.
template <int M, int L>
struct Step {
  Vector<L> u;
  Measurement<M> z;
};

/// Simulates x' = A x + B u + w, z = H x + v with random controls (uniform in
/// [-controlScale, controlScale]), random missing entries (each with probability
/// `missingProbability`) and every `allMissingEvery`-th step without any measurement.
template <int N, int M, int L>
std::vector<Step<M, L>> simulateLinear(const Matrix<N, N>& A, const Matrix<N, L>& B,
                                       const Matrix<M, N>& H, const Matrix<N, N>& Q,
                                       const Matrix<M, M>& R, const Vector<N>& x0, int steps,
                                       std::uint64_t seed, double missingProbability,
                                       int allMissingEvery, double controlScale) {
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> normal(0.0, 1.0);
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  std::bernoulli_distribution missing(missingProbability);
  const Eigen::MatrixXd rootQ = psdRoot(Q), rootR = psdRoot(R);
  const Index n = A.rows(), m = H.rows(), l = B.cols();
  Eigen::VectorXd x = x0;
  std::vector<Step<M, L>> run;
  for (int k = 0; k < steps; ++k) {
    Step<M, L> step{Vector<L>(l), Measurement<M>(m)};
    for (Index i = 0; i < l; ++i) step.u(i) = controlScale * uniform(rng);
    Eigen::VectorXd w(n), v(m);
    for (Index i = 0; i < n; ++i) w(i) = normal(rng);
    for (Index i = 0; i < m; ++i) v(i) = normal(rng);
    x = A * x + B * step.u + rootQ * w;
    step.z.value = H * x + rootR * v;
    for (Index i = 0; i < m; ++i) step.z.available(i) = !missing(rng);
    if (allMissingEvery > 0 && k % allMissingEvery == allMissingEvery - 1) {
      step.z.available.setConstant(false);
    }
    run.push_back(step);
  }
  return run;
}

/// Inputs of a robot driving a smooth random path (the magnitudes of section 5: |v| < 1 m/s,
/// |omega| < 0.7 rad/s, |a| < 1 m/s^2) for the nav3 models: controls u = (v command, omega
/// command), measurements (gyro, accelerometer, left wheel, right wheel) with the noise of
/// nav3MeasurementNoise(), random missing entries and every `allMissingEvery`-th step empty.
std::vector<Step<4, 2>> simulateNav3Drive(int steps, std::uint64_t seed, double missingProbability,
                                          int allMissingEvery, double T = 0.1, double radius = 0.3);

/// Hand-derived Jacobian of the nav3ctrl transition (eqs. 5.8-5.14) at x:
///   x'     = x + ds cos(th)  -> d/dth = -ds sin(th), d/dds = cos(th)
///   y'     = y + ds sin(th)  -> d/dth =  ds cos(th), d/dds = sin(th)
///   th'    = th + om T       -> d/dom = T
///   om'    = u1              -> zero row
///   ds'    = v T             -> d/dv = T
///   v'     = v + a T         -> d/da = T
///   a'     = (u0 - v) / T    -> d/dv = -1/T
Matrix<7, 7> nav3CtrlTransitionJacobian(const estimation::models::Nav3Ctrl& model,
                                        const Vector<7>& x);

/// Hand-derived Jacobian of the nav3 observation (eqs. 5.15-5.18):
///   [0 0 0 1 0 0 0], [0 0 0 0 0 0 1], [0 0 0 -1000R 0 1000 0], [0 0 0 1000R 0 1000 0].
Matrix<4, 7> nav3CtrlObservationJacobian(const estimation::models::Nav3Ctrl& model);

/// The model `Model` observing only the measurement rows in `rows` (in that order).
template <class Model>
struct RowSubsetModel {
  static constexpr int StateSize = Model::StateSize;
  static constexpr int MeasurementSize = Dynamic;
  static constexpr int ControlSize = Model::ControlSize;

  Model model;
  std::vector<Index> rows;

  Index stateSize() const { return model.stateSize(); }
  Index measurementSize() const { return static_cast<Index>(rows.size()); }
  Index controlSize() const { return model.controlSize(); }

  template <class S>
  void transition(const Eigen::Matrix<S, StateSize, 1>& x, const Vector<ControlSize>& u,
                  Eigen::Matrix<S, StateSize, 1>& next) const {
    model.transition(x, u, next);
  }

  template <class S>
  void observation(const Eigen::Matrix<S, StateSize, 1>& x, Eigen::Matrix<S, Dynamic, 1>& z) const {
    Eigen::Matrix<S, Model::MeasurementSize, 1> full(model.measurementSize());
    model.observation(x, full);
    z.resize(measurementSize());
    for (Index i = 0; i < measurementSize(); ++i) z(i) = full(rows[static_cast<std::size_t>(i)]);
  }
};

/// Indices of the present entries of z.
template <int M>
std::vector<Index> presentRows(const Measurement<M>& z) {
  std::vector<Index> rows;
  for (Index i = 0; i < z.size(); ++i) {
    if (z.available(i)) rows.push_back(i);
  }
  return rows;
}

/// The rows `rows` of a vector or matrix.
template <class Derived>
Eigen::Matrix<typename Derived::Scalar, Dynamic, Derived::ColsAtCompileTime> selectRows(
    const Eigen::MatrixBase<Derived>& a, const std::vector<Index>& rows) {
  Eigen::Matrix<typename Derived::Scalar, Dynamic, Derived::ColsAtCompileTime> out(
      static_cast<Index>(rows.size()), a.cols());
  for (std::size_t i = 0; i < rows.size(); ++i) out.row(static_cast<Index>(i)) = a.row(rows[i]);
  return out;
}

/// The sub-matrix R(rows, rows).
template <class Derived>
Eigen::MatrixXd selectSquare(const Eigen::MatrixBase<Derived>& a, const std::vector<Index>& rows) {
  const Index k = static_cast<Index>(rows.size());
  Eigen::MatrixXd out(k, k);
  for (Index i = 0; i < k; ++i) {
    for (Index j = 0; j < k; ++j) {
      out(i, j) = a(rows[static_cast<std::size_t>(i)], rows[static_cast<std::size_t>(j)]);
    }
  }
  return out;
}

/// The measurement with only the rows `rows` (all present, per-entry variances kept).
template <int M>
Measurement<Dynamic> selectMeasurement(const Measurement<M>& z, const std::vector<Index>& rows) {
  Measurement<Dynamic> out(static_cast<Index>(rows.size()));
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const Index k = static_cast<Index>(i);
    out.value(k) = z.value(rows[i]);
    out.available(k) = true;
    out.varianceGiven(k) = z.varianceGiven(rows[i]);
    out.variance(k) = z.variance(rows[i]);
  }
  return out;
}

/// A symmetric positive definite 4x4 measurement noise with correlated entries, on the
/// scales of nav3's sensors (gyro rad/s, accelerometer m/s^2, wheels mm/s).
Matrix<4, 4> correlatedNav3MeasurementNoise();

/// x' = x (scalar random walk), z = x^2: the simplest nonlinear observation, with the
/// Jacobian 2x and closed-form unscented moments.
struct SquareModel {
  static constexpr int StateSize = 1;
  static constexpr int MeasurementSize = 1;
  static constexpr int ControlSize = 0;
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
    z(0) = x(0) * x(0);
  }
};

/// x' = x + 1, z = x^2 (scalar): the observation Jacobian 2x differs between the previous
/// and the predicted state, so the hand computation shows where H is evaluated.
struct ShiftSquareModel : SquareModel {
  template <class S>
  void transition(const Eigen::Matrix<S, 1, 1>& x, const Vector<0>&,
                  Eigen::Matrix<S, 1, 1>& next) const {
    next(0) = x(0) + 1.0;
  }
};

/// The unscented transform's parameters with alpha = 1 (the default is 1e-3).
inline estimation::UnscentedParameters alphaOne() {
  estimation::UnscentedParameters p;
  p.alpha = 1.0;
  return p;
}

}  // namespace sftest
