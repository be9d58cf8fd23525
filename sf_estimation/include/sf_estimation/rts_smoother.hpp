// Rauch-Tung-Striebel smoother: a backward pass over what a Kalman-type filter produced per
// period (filtered mean, covariance and the control of the time update), which gives each
// period the estimate that uses the whole recording. The pass re-derives every one-step
// prediction exactly as the forward filter made it, from the filter's own model and Q, so the
// filters need no change and store nothing extra:
//
//   x(k+1|k), P(k+1|k), C(k) = Cov(x_k, x_k+1 | k)        (KF/EKF: f, F P F^T + Q, P F^T)
//   G = C P(k+1|k)^-1                                      (an LDLT solve, no inverse)
//   x_k^s = x_k + G (x_k+1^s - x(k+1|k)),  P_k^s = P_k + G (P_k+1^s - P(k+1|k)) G^T
//
// The unscented variant (unscented_rts_smoother.hpp) only replaces the prediction. Angle
// states: the difference x_k+1^s - x(k+1|k) and the smoothed mean are wrapped.
//
// Memory: the recorded sequence, per period N + N^2 + L doubles (FilteredPeriod) and N + N^2
// for the smoothed result (SmoothedPeriod); the backward pass itself holds one prediction and
// one gain at fixed sizes (no allocation per period; a Dynamic size allocates its temporaries).
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "sf_estimation/angles.hpp"
#include "sf_estimation/extended_kalman_filter.hpp"
#include "sf_estimation/jacobian.hpp"
#include "sf_estimation/kalman_correction.hpp"
#include "sf_estimation/kalman_filter.hpp"
#include "sf_estimation/rts_step.hpp"
#include "sf_estimation/types.hpp"

namespace estimation {

/// What the forward filter produced in one period: the committed belief and the control of
/// the time update that led to it (the control set before that period's estimate()).
template <int N, int L>
struct FilteredPeriod {
  Vector<N> x;
  Matrix<N, N> P;
  Vector<L> u;
  /// false: the belief was set (the initial belief, setBelief(), reset()), not predicted from
  /// the previous period, so the backward pass does not link the two.
  bool predicted = true;

  /// The belief a filter holds now and the control it last used (call right after estimate()).
  template <class Filter>
  static FilteredPeriod of(const Filter& filter, bool predicted = true) {
    return FilteredPeriod{filter.state(), filter.covariance(), filter.control(), predicted};
  }
};

template <int N>
struct SmoothedPeriod {
  Vector<N> x;
  Matrix<N, N> P;
};

/// The backward pass over a recorded forward run, for any one-step prediction:
///   Prediction::StateSize, ControlSize, and
///   void predict(const Vector<N>& x, const Matrix<N, N>& P, const Vector<L>& u,
///                OneStepPrediction<N>& out) const;   // exactly the forward filter's
template <class Prediction>
class RtsSmoother {
 public:
  static constexpr int N = Prediction::StateSize;
  static constexpr int L = Prediction::ControlSize;
  using Period = FilteredPeriod<N, L>;
  using Smoothed = SmoothedPeriod<N>;

  RtsSmoother(Prediction prediction, const AngleMask<N>& angleStates)
      : prediction_(std::move(prediction)), angleStates_(angleStates) {}

  /// Smooths `filtered` (periods in time order) into `smoothed` (resized to match; the last
  /// period and every period followed by a set belief keep their filtered estimate).
  void smooth(const std::vector<Period>& filtered, std::vector<Smoothed>& smoothed) const {
    smoothed.resize(filtered.size());
    if (filtered.empty()) return;
    const Index n = filtered.back().x.size();
    OneStepPrediction<N> prediction(n);
    smoothed.back() = Smoothed{filtered.back().x, filtered.back().P};
    for (std::size_t k = filtered.size() - 1; k-- > 0;) {
      const Period& now = filtered[k];
      const Period& next = filtered[k + 1];
      if (!next.predicted) {
        smoothed[k] = Smoothed{now.x, now.P};
        continue;
      }
      prediction_.predict(now.x, now.P, next.u, prediction);
      rtsBackwardStep<N>(now.x, now.P, prediction, smoothed[k + 1].x, smoothed[k + 1].P,
                         angleStates_, smoothed[k].x, smoothed[k].P);
    }
  }

  const Prediction& prediction() const { return prediction_; }
  const AngleMask<N>& angleStates() const { return angleStates_; }

 private:
  Prediction prediction_;
  AngleMask<N> angleStates_;
};

/// The Kalman filter's time update: x' = A x + B u, P' = A P A^T + Q, C = P A^T.
template <int N, int L>
struct LinearPrediction {
  static constexpr int StateSize = N;
  static constexpr int ControlSize = L;
  Matrix<N, N> A;
  Matrix<N, L> B;
  Matrix<N, N> Q;

  void predict(const Vector<N>& x, const Matrix<N, N>& P, const Vector<L>& u,
               OneStepPrediction<N>& out) const {
    linearTransition<N, L>(A, x, B, u, out.x);
    propagateCovariance<N>(A, P, Q, out.P);
    out.cross = P * A.transpose();
  }
};

/// The extended Kalman filter's time update: x' = f(x, u), P' = F P F^T + Q, C = P F^T with F
/// the transition Jacobian at the filtered x (jacobian.hpp, as the EKF evaluates it).
template <class Model>
struct LinearisedPrediction {
  static constexpr int StateSize = Model::StateSize;
  static constexpr int ControlSize = Model::ControlSize;
  static constexpr int N = StateSize;
  Model model;
  Matrix<N, N> Q;

  void predict(const Vector<N>& x, const Matrix<N, N>& P, const Vector<ControlSize>& u,
               OneStepPrediction<N>& out) const {
    Matrix<N, N> F(x.size(), x.size());
    transitionJacobian(model, x, u, F);
    model.transition(x, u, out.x);
    propagateCovariance<N>(F, P, Q, out.P);
    out.cross = P * F.transpose();
  }
};

/// The smoother of a Kalman filter: its A, B, Q and angle states.
template <int N, int M, int L, class Layout>
RtsSmoother<LinearPrediction<N, L>> smootherFor(const KalmanFilter<N, M, L, Layout>& filter) {
  return {LinearPrediction<N, L>{filter.transitionMatrix(), filter.controlMatrix(),
                                 filter.processNoise()},
          filter.angleStates()};
}

/// The smoother of an extended Kalman filter: a copy of its model, its Q and angle states.
template <class Model>
RtsSmoother<LinearisedPrediction<Model>> smootherFor(const ExtendedKalmanFilter<Model>& filter) {
  return {LinearisedPrediction<Model>{filter.model(), filter.processNoise()}, filter.angleStates()};
}

}  // namespace estimation
