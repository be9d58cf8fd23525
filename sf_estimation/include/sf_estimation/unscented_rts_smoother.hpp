// The unscented Rauch-Tung-Striebel smoother (Sarkka 2008, "Unscented Rauch-Tung-Striebel
// smoother", IEEE TAC 53(3)): the backward pass of rts_smoother.hpp with the UKF's own time
// update in place of the linearised one. The sigma points of the filtered (x_k, P_k) are
// propagated through f as the UKF propagates them (same parameters, and the same widened alpha
// for a badly scaled state, UnscentedTransform::alphaFor), giving x(k+1|k), P(k+1|k) (with Q)
// and the cross covariance C = sum Wc_i (X_i - x_k)(f(X_i) - x(k+1|k))^T.
#pragma once

#include <optional>
#include <utility>

#include "sf_estimation/numerical_repairs.hpp"
#include "sf_estimation/rts_smoother.hpp"
#include "sf_estimation/unscented_kalman_filter.hpp"
#include "sf_estimation/unscented_transform.hpp"

namespace estimation {

template <class Model>
class UnscentedPrediction {
 public:
  static constexpr int StateSize = Model::StateSize;
  static constexpr int ControlSize = Model::ControlSize;
  static constexpr int N = StateSize;
  static constexpr int S = sigmaPointCount(N);

  UnscentedPrediction(Model model, const Matrix<N, N>& Q, const UnscentedParameters& params,
                      const AngleMask<N>& angleStates)
      : model_(std::move(model)),
        Q_(Q),
        params_(params),
        transform_(Q.rows(), params),
        angleStates_(angleStates) {}

  void predict(const Vector<N>& x, const Matrix<N, N>& P, const Vector<ControlSize>& u,
               OneStepPrediction<N>& out) const {
    const Index n = x.size();
    const Index count = transform_.pointCount();
    Matrix<N, S> points(n, count), propagated(n, count);
    std::optional<UnscentedTransform<N>> wide;
    const UnscentedTransform<N>& transform = transformFor(x, P, wide);
    transform.sigmaPoints(x, P, points);
    Vector<N> in(n), next(n);
    for (Index i = 0; i < count; ++i) {
      in = points.col(i);
      model_.transition(in, u, next);
      propagated.col(i) = next;
    }
    transform.mean(propagated, out.x, angleStates_);
    transform.crossCovariance(propagated, out.x, propagated, out.x, out.P, angleStates_,
                              angleStates_);
    out.P += Q_;
    symmetrize(out.P);
    // A negative central weight can make it indefinite; the UKF repairs it before using it (in
    // its correction, or commit()), and so does the smoother (one Cholesky when it is healthy).
    repairCovariance(out.P);
    // The sigma points' deviations from x are the columns of the root, exactly: not wrapped
    // (as in the UKF's correction), even when an angle's spread exceeds pi.
    transform.crossCovariance(points, x, propagated, out.x, out.cross, AngleMask<N>(n),
                              angleStates_);
    // The UKF's predicted mean (PredictedMean): P and C are around the points' weighted mean
    // either way, as in UnscentedKalmanFilter::predict.
    if (params_.predictedMean == PredictedMean::Propagated) {
      out.x = propagated.col(0);
      angleStates_.wrap(out.x);
    }
    if (!out.x.allFinite() || !out.P.allFinite() || !out.cross.allFinite()) {
      throw NumericalError("UnscentedRtsSmoother: the time update became non-finite");
    }
  }

 private:
  /// The UKF's choice (UnscentedKalmanFilter::transformFor): the configured transform, or one
  /// with the alpha that resolves the sigma points of (x, P).
  const UnscentedTransform<N>& transformFor(const Vector<N>& x, const Matrix<N, N>& P,
                                            std::optional<UnscentedTransform<N>>& wide) const {
    const double alpha = transform_.alphaFor(x, P);
    if (alpha <= params_.alpha) return transform_;
    UnscentedParameters widened = params_;
    widened.alpha = alpha;
    wide.emplace(x.size(), widened);
    return *wide;
  }

  Model model_;
  Matrix<N, N> Q_;
  UnscentedParameters params_;
  UnscentedTransform<N> transform_;
  AngleMask<N> angleStates_;
};

/// The unscented RTS smoother of a UKF: a copy of its model, its Q, sigma-point parameters and
/// angle states.
template <class Model>
RtsSmoother<UnscentedPrediction<Model>> smootherFor(const UnscentedKalmanFilter<Model>& filter) {
  return {UnscentedPrediction<Model>(filter.model(), filter.processNoise(), filter.parameters(),
                                     filter.angleStates()),
          filter.angleStates()};
}

}  // namespace estimation
