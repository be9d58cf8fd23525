// The batch maximum-a-posteriori track of a recorded run (issue 39): all states x_s..x_e of a
// segment at once, minimising
//
//   J = 1/2 |x_s - m_s|^2_(P_s^-1) + 1/2 sum_k |x_k - f(x_k-1, u_k)|^2_(Q^-1)
//       + 1/2 sum_k |z_k - h(x_k)|^2_(R_k^-1)          (the present rows of z_k only)
//
// with the filter's own f, h, Q and the R the filter used in each period (the configured R with
// the period's variances and covariances, measurement_noise.hpp). The prior (m_s, P_s) is the
// segment's first recorded belief, which already holds that period's measurement: it is not
// weighed again. Angle states and angle measurements enter every residual wrapped.
//
// Method: Gauss-Newton, each step the iterated extended Kalman smoother: a Kalman filter on the
// model linearised about the current track, x' = f(t) + F (x - t), z = h(t) + H (x - t), and the
// RTS backward pass of rts_step.hpp over it. For this block-tridiagonal least-squares problem
// that is exactly the Gauss-Newton step, in O(T) per iteration (Bell, "The iterated Kalman
// smoother as a Gauss-Newton method", SIAM J. Optim. 4(3), 1994). Safeguard: the step is halved
// until the cost does not increase (the cost never increases). Stop when every entry of the
// step is below `tolerance` times its smoothed standard deviation, or after `maxIterations`.
// For a linear model the first iteration is the RTS smoother's result and the second, whose
// step vanishes, confirms it. The covariance given with the track is the last iteration's
// smoothed covariance (of the model linearised about the track before the last step: at
// convergence the Laplace approximation of the posterior's marginals).
//
// A state that no process noise reaches (a zero row and column of Q) follows its transition
// exactly, a constraint the cost cannot weigh: every track the cost judges (the filtered one,
// each step's candidate) has such states rolled forward from the segment's first period, else
// a step judged without its violation can stall (the Pioneer's dead reckoning did). Otherwise a
// residual is weighed in the directions its covariance spans only (LDLT's solve skips zero
// pivots, as rtsGain does): a segment prior with an exactly known direction, or a singular Q
// whose null space does not lie along states.
//
// Memory per period: the record (the belief, control and the measurement applied) and, while
// smoothing, the track, a candidate track, the linearised filter's belief and the result.
// Nothing is allocated per period or per iteration (fixed sizes) once smooth() sized its
// buffers.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <string>
#include <utility>
#include <vector>

#include "sf_estimation/angles.hpp"
#include "sf_estimation/batch_map_step.hpp"
#include "sf_estimation/errors.hpp"
#include "sf_estimation/extended_kalman_filter.hpp"
#include "sf_estimation/jacobian.hpp"
#include "sf_estimation/kalman_correction.hpp"
#include "sf_estimation/kalman_filter.hpp"
#include "sf_estimation/measurement.hpp"
#include "sf_estimation/measurement_noise.hpp"
#include "sf_estimation/rts_smoother.hpp"
#include "sf_estimation/rts_step.hpp"
#include "sf_estimation/small_products.hpp"
#include "sf_estimation/types.hpp"
#include "sf_estimation/unscented_kalman_filter.hpp"

namespace estimation {

/// One recorded period: the filter's committed belief and control (rts_smoother.hpp) and the
/// measurement the filter applied in it (present rows after gating, given variances and
/// covariances). The measurement of a segment's first period is in its belief already.
template <int N, int M, int L>
struct MeasuredPeriod {
  FilteredPeriod<N, L> belief;
  Measurement<M> z;
};

struct BatchMapOptions {
  int maxIterations = 50;
  /// Converged when every entry of a step is below this fraction of its smoothed standard
  /// deviation (or at the rounding level of the entry).
  double tolerance = 1e-9;
  /// Step halvings tried before an iteration gives up (the cost would increase).
  int maxHalvings = 40;
};

struct BatchMapReport {
  std::size_t segments = 0;
  int iterations = 0;        ///< the most any segment took
  int halvings = 0;          ///< step halvings, all segments
  double initialCost = 0.0;  ///< J of the filtered track, summed over the segments
  double cost = 0.0;         ///< J of the result, summed over the segments
  bool converged = true;     ///< every segment
};

/// x' = A x + B u, z = H x with its Jacobians: the Kalman filter's model for the batch smoother.
template <int N, int M, int L>
struct LinearStateSpace {
  static constexpr int StateSize = N, MeasurementSize = M, ControlSize = L;
  Matrix<N, N> A;
  Matrix<N, L> B;
  Matrix<M, N> H;
  void transition(const Vector<N>& x, const Vector<L>& u, Vector<N>& next) const {
    next.resize(x.size());
    multiply<Store::Assign>(A, x, next);
    multiply<Store::Add>(B, u, next);
  }
  void observation(const Vector<N>& x, Vector<M>& z) const {
    z.resize(H.rows());
    multiply<Store::Assign>(H, x, z);
  }
  Index controlSize() const { return B.cols(); }
  void transitionJacobian(const Vector<N>&, const Vector<L>&, Matrix<N, N>& J) const { J = A; }
  void observationJacobian(const Vector<N>&, Matrix<M, N>& J) const { J = H; }
};

template <class Model>
class BatchMapSmoother {
 public:
  static constexpr int N = Model::StateSize;
  static constexpr int M = Model::MeasurementSize;
  static constexpr int L = Model::ControlSize;
  using Period = MeasuredPeriod<N, M, L>;
  using Smoothed = SmoothedPeriod<N>;

  BatchMapSmoother(Model model, const Matrix<N, N>& Q, const Matrix<M, M>& R,
                   const AngleMask<N>& angleStates, const AngleMask<M>& angleMeasurements,
                   BatchMapOptions options = {})
      : model_(std::move(model)),
        Q_(Q),
        R_(R),
        angleStates_(angleStates),
        angleMeasurements_(angleMeasurements),
        options_(options),
        deterministic_(Mask<N>::Constant(Q.rows(), false)) {
    for (Index i = 0; i < Q.rows(); ++i) {
      deterministic_(i) = (Q.row(i).array() == 0.0).all() && (Q.col(i).array() == 0.0).all();
    }
    if (options_.maxIterations < 1 || !(options_.tolerance > 0.0) || options_.maxHalvings < 0) {
      throw ParameterError(
          "BatchMapSmoother: expected maxIterations >= 1, tolerance > 0, maxHalvings >= 0");
    }
  }

  /// The MAP track of `record` (periods in time order; a period with belief.predicted false
  /// starts a new, independent segment) into `smoothed`, starting from the filtered means.
  /// Throws InvalidInputError for a record of the wrong sizes or with a non-finite entry, and
  /// NumericalError when a linearised step fails (an indefinite covariance).
  BatchMapReport smooth(const std::vector<Period>& record, std::vector<Smoothed>& smoothed) {
    BatchMapReport report;
    validate(record);
    smoothed.resize(record.size());
    if (record.empty()) return report;
    const Index n = record.front().belief.x.size();
    track_.assign(record.size(), Vector<N>::Zero(n));
    candidate_.assign(record.size(), Vector<N>::Zero(n));
    forward_.assign(record.size(), Smoothed{Vector<N>::Zero(n), Matrix<N, N>::Zero(n, n)});
    for (std::size_t begin = 0; begin < record.size();) {
      std::size_t end = begin + 1;
      while (end < record.size() && record[end].belief.predicted) ++end;
      const BatchMapReport segment = solveSegment(record, begin, end, smoothed);
      ++report.segments;
      report.iterations = std::max(report.iterations, segment.iterations);
      report.halvings += segment.halvings;
      report.initialCost += segment.initialCost;
      report.cost += segment.cost;
      report.converged = report.converged && segment.converged;
      begin = end;
    }
    return report;
  }

  /// The memory of one period while smoothing: the track, the candidate and the linearised
  /// filter's belief (the record and the result are the caller's).
  static constexpr std::size_t bytesPerPeriodWorking() {
    return 2 * sizeof(Vector<N>) + sizeof(Smoothed);
  }

  const Model& model() const { return model_; }

 private:
  /// The record's sizes and finiteness, and its measurements (Measurement::validate).
  void validate(const std::vector<Period>& record) const {
    const Index n = Q_.rows(), m = R_.rows();
    for (std::size_t k = 0; k < record.size(); ++k) {
      const Period& p = record[k];
      const auto where = [k] { return "BatchMapSmoother: period " + std::to_string(k) + ": "; };
      if (p.belief.x.size() != n || p.belief.P.rows() != n || p.belief.P.cols() != n) {
        throw InvalidInputError(where() + "the belief does not have the model's " +
                                std::to_string(n) + " states");
      }
      if (!p.belief.x.allFinite() || !p.belief.P.allFinite() || !p.belief.u.allFinite()) {
        throw InvalidInputError(where() + "the belief or the control is not finite");
      }
      try {
        validateControl(p.belief.u, model_.controlSize());
        p.z.validate(m);
      } catch (const InvalidInputError& e) {
        throw InvalidInputError(where() + e.what());
      }
    }
  }

  /// Gauss-Newton on the segment [begin, end) from its filtered means.
  BatchMapReport solveSegment(const std::vector<Period>& record, std::size_t begin, std::size_t end,
                              std::vector<Smoothed>& smoothed) {
    for (std::size_t k = begin; k < end; ++k) track_[k] = record[k].belief.x;
    holdConstraints(record, begin, end, track_);
    BatchMapReport out;
    out.converged = false;
    out.initialCost = out.cost = cost(record, begin, end, track_);
    while (out.iterations < options_.maxIterations) {
      ++out.iterations;
      linearisedPass(record, begin, end, smoothed);
      const bool small = stepIsSmall(begin, end, smoothed);
      const bool moved =
          takeStep(record, begin, end, smoothed, small ? 0 : options_.maxHalvings, out);
      if (small) out.converged = true;
      if (small || !moved) break;
    }
    for (std::size_t k = begin; k < end; ++k) smoothed[k].x = track_[k];
    return out;
  }

  /// The Gauss-Newton step's target: the Kalman filter and RTS pass of the model linearised
  /// about the track, into `smoothed` (the linearised filter's beliefs into forward_).
  void linearisedPass(const std::vector<Period>& record, std::size_t begin, std::size_t end,
                      std::vector<Smoothed>& smoothed) {
    const Index n = track_[begin].size();
    OneStepPrediction<N> prediction(n);
    forward_[begin].x = record[begin].belief.x;
    forward_[begin].P = record[begin].belief.P;
    for (std::size_t k = begin + 1; k < end; ++k) {
      predictAbout(track_[k - 1], record[k].belief.u, forward_[k - 1], prediction);
      forward_[k].x = prediction.x;
      forward_[k].P = prediction.P;
      correctAbout(track_[k], record[k].z, forward_[k]);
    }
    smoothed[end - 1] = forward_[end - 1];
    Matrix<N, N> gain(n, n);
    for (std::size_t k = end - 1; k-- > begin;) {
      predictAbout(track_[k], record[k + 1].belief.u, forward_[k], prediction);
      rtsGain<N>(prediction, gain);
      rtsCorrect<N>(forward_[k].x, forward_[k].P, prediction, gain, smoothed[k + 1].x,
                    smoothed[k + 1].P, angleStates_, smoothed[k].x, smoothed[k].P);
    }
  }

  /// The prediction of `belief` by f linearised about `about`: f(t) + F (x - t), F P F^T + Q,
  /// and the cross covariance P F^T.
  void predictAbout(const Vector<N>& about, const Vector<L>& u, const Smoothed& belief,
                    OneStepPrediction<N>& out) const {
    const Index n = about.size();
    Matrix<N, N> F(n, n);
    transitionJacobian(model_, about, u, F);
    model_.transition(about, u, out.x);
    Vector<N> offset = belief.x - about;
    angleStates_.wrap(offset);
    multiply<Store::Add>(F, offset, out.x);
    angleStates_.wrap(out.x);
    propagateCovariance<N>(F, belief.P, Q_, out.P);
    multiply<Store::Assign, true>(belief.P, F, out.cross);
  }

  /// The correction of `belief` by the present rows of z with h linearised about `about`:
  /// innovation wrap(z - h(t)) - H (x - t), the period's R (missing rows neutralised).
  void correctAbout(const Vector<N>& about, const Measurement<M>& z, Smoothed& belief) const {
    if (!z.anyAvailable()) return;
    const Index n = about.size(), m = z.size();
    Matrix<M, N> H(m, n);
    observationJacobian(model_, about, H);
    Vector<M> y(m);
    model_.observation(about, y);
    y = z.value - y;
    angleMeasurements_.wrap(y);
    Vector<N> offset = belief.x - about;
    angleStates_.wrap(offset);
    multiply<Store::Subtract>(H, offset, y);
    neutraliseMissing(z, y, H);
    Matrix<M, M> R(m, m);
    effectiveMeasurementNoise(R_, z, R);
    linearCorrection<N, M>(belief.x, belief.P, H, y, R);
    symmetrize(belief.P);
    angleStates_.wrap(belief.x);
  }

  /// The states that no process noise reaches (a zero row and column of Q) follow their
  /// transition exactly, x_k(i) = f(x_k-1, u_k)(i): a constraint, which the cost cannot weigh.
  /// A track is made to meet it by rolling those states forward from the segment's first
  /// period. The filtered track does not meet it (the filter's corrections move such states),
  /// a linearised step only to first order.
  void holdConstraints(const std::vector<Period>& record, std::size_t begin, std::size_t end,
                       std::vector<Vector<N>>& track) const {
    if (!deterministic_.any()) return;
    Vector<N> predicted(track[begin].size());
    for (std::size_t k = begin + 1; k < end; ++k) {
      model_.transition(track[k - 1], record[k].belief.u, predicted);
      for (Index i = 0; i < predicted.size(); ++i) {
        if (deterministic_(i)) track[k](i) = predicted(i);
      }
      angleStates_.wrap(track[k]);
    }
  }

  /// J of the segment [begin, end) at `track`.
  double cost(const std::vector<Period>& record, std::size_t begin, std::size_t end,
              const std::vector<Vector<N>>& track) const {
    const Index n = track[begin].size(), m = R_.rows();
    Vector<N> r = track[begin] - record[begin].belief.x;
    angleStates_.wrap(r);
    double sum = weightedSquare<N>(record[begin].belief.P, r);
    Vector<N> predicted(n);
    Vector<M> y(m);
    Matrix<M, M> R(m, m);
    for (std::size_t k = begin + 1; k < end; ++k) {
      model_.transition(track[k - 1], record[k].belief.u, predicted);
      r = track[k] - predicted;
      angleStates_.wrap(r);
      sum += weightedSquare<N>(Q_, r);
      const Measurement<M>& z = record[k].z;
      if (!z.anyAvailable()) continue;
      model_.observation(track[k], y);
      y = z.value - y;
      angleMeasurements_.wrap(y);
      for (Index i = 0; i < m; ++i) y(i) = z.available(i) ? y(i) : 0.0;
      effectiveMeasurementNoise(R_, z, R);
      sum += weightedSquare<M>(R, y);
    }
    return 0.5 * sum;
  }

  /// Whether every entry of the step to `smoothed` is below the tolerance of its smoothed
  /// standard deviation, or at the rounding level of the entry.
  bool stepIsSmall(std::size_t begin, std::size_t end,
                   const std::vector<Smoothed>& smoothed) const {
    constexpr double kRounding = 64 * std::numeric_limits<double>::epsilon();
    for (std::size_t k = begin; k < end; ++k) {
      Vector<N> step = smoothed[k].x - track_[k];
      angleStates_.wrap(step);
      for (Index i = 0; i < step.size(); ++i) {
        const double sigma = std::sqrt(std::max(smoothed[k].P(i, i), 0.0));
        const double size = std::abs(step(i));
        if (size > options_.tolerance * sigma &&
            size > kRounding * std::max(1.0, std::abs(track_[k](i)))) {
          return false;
        }
      }
    }
    return true;
  }

  /// Moves the track towards `smoothed` by the largest of 1, 1/2, ... (up to `halvings`
  /// halvings) that does not increase the cost; false (the track kept) when none does.
  bool takeStep(const std::vector<Period>& record, std::size_t begin, std::size_t end,
                const std::vector<Smoothed>& smoothed, int halvings, BatchMapReport& out) {
    double fraction = 1.0;
    for (int h = 0; h <= halvings; ++h, fraction *= 0.5) {
      for (std::size_t k = begin; k < end; ++k) {
        Vector<N> step = smoothed[k].x - track_[k];
        angleStates_.wrap(step);
        candidate_[k] = track_[k] + fraction * step;
        angleStates_.wrap(candidate_[k]);
      }
      holdConstraints(record, begin, end, candidate_);
      const double candidateCost = cost(record, begin, end, candidate_);
      if (candidateCost <= out.cost) {
        std::swap(track_, candidate_);
        out.cost = candidateCost;
        return true;
      }
      if (h < halvings) ++out.halvings;
    }
    return false;
  }

  Model model_;
  Matrix<N, N> Q_;
  Matrix<M, M> R_;
  AngleMask<N> angleStates_;
  AngleMask<M> angleMeasurements_;
  BatchMapOptions options_;
  Mask<N> deterministic_;  ///< states without process noise (holdConstraints)
  std::vector<Vector<N>> track_, candidate_;
  std::vector<Smoothed> forward_;
};

/// The batch smoother of a Kalman filter: its A, B, H, Q, R and angles.
template <int N, int M, int L, class Layout>
BatchMapSmoother<LinearStateSpace<N, M, L>> batchSmootherFor(
    const KalmanFilter<N, M, L, Layout>& filter, BatchMapOptions options = {}) {
  return {LinearStateSpace<N, M, L>{filter.transitionMatrix(), filter.controlMatrix(),
                                    filter.observationMatrix()},
          filter.processNoise(),
          filter.measurementNoise(),
          filter.angleStates(),
          filter.angleMeasurements(),
          options};
}

/// The batch smoother of an extended Kalman filter: a copy of its model, Q, R and angles.
template <class Model>
BatchMapSmoother<Model> batchSmootherFor(const ExtendedKalmanFilter<Model>& filter,
                                         BatchMapOptions options = {}) {
  return {filter.model(),       filter.processNoise(),      filter.measurementNoise(),
          filter.angleStates(), filter.angleMeasurements(), options};
}

/// The batch smoother of an unscented Kalman filter: the MAP track is defined by the same f,
/// h, Q and R, linearised by the model's Jacobians (jacobian.hpp) as the EKF's are.
template <class Model>
BatchMapSmoother<Model> batchSmootherFor(const UnscentedKalmanFilter<Model>& filter,
                                         BatchMapOptions options = {}) {
  return {filter.model(),       filter.processNoise(),      filter.measurementNoise(),
          filter.angleStates(), filter.angleMeasurements(), options};
}

}  // namespace estimation
