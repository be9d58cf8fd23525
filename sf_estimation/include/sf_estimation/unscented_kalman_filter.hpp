// Unscented Kalman filter (thesis Algorithm 3.3) with additive noise. The correction draws
// fresh sigma points from the predicted mean and covariance (which includes Q), as line 3 of
// the algorithm says: reusing the propagated points would never correct a state whose
// transition ignores the previous state (in nav3ctrl, omega = u1 makes every propagated point
// carry the same omega, so gyro and wheels would be ignored).
#pragma once

#include <optional>
#include <utility>

#include "sf_estimation/abstract_kalman_filter.hpp"
#include "sf_estimation/kalman_correction.hpp"
#include "sf_estimation/measurement_prediction.hpp"
#include "sf_estimation/model.hpp"
#include "sf_estimation/unscented_transform.hpp"

namespace estimation {

template <class Model>
class UnscentedKalmanFilter
    : public AbstractKalmanFilter<Model::StateSize, Model::MeasurementSize, Model::ControlSize> {
  static constexpr int N = Model::StateSize;
  static constexpr int M = Model::MeasurementSize;
  static constexpr int L = Model::ControlSize;
  static constexpr int S = sigmaPointCount(N);
  using Base = AbstractKalmanFilter<N, M, L>;

 public:
  UnscentedKalmanFilter(Model model, const Matrix<N, N>& Q, const Matrix<M, M>& R,
                        const Vector<N>& x0, const Matrix<N, N>& P0,
                        const UnscentedParameters& params = {},
                        const AngularComponents& angles = {})
      : Base("UnscentedKalmanFilter", Q, R, x0, P0, model.controlSize(), angles),
        model_(std::move(model)),
        transform_(Q.rows(), params),
        params_(params) {
    checkModelSizes(this->method_, model_, this->stateSize(), this->measurementSize());
  }

  void estimate(const Measurement<M>& z) {
    z.validate(this->measurementSize());
    const Index n = this->stateSize();
    const Index count = transform_.pointCount();
    Vector<N> x(n);
    Matrix<N, N> P(n, n);
    bool widened = false;
    predict(x, P, widened);
    bool repairedPrediction = false;

    if (z.anyAvailable()) {
      const Index m = this->measurementSize();
      Matrix<N, S> points(n, count);
      Matrix<M, S> expected(m, count);
      Vector<M> zMean(m);
      Matrix<M, M> Pzz(m, m);
      std::optional<UnscentedTransform<N>> wide;
      const UnscentedTransform<N>& transform =
          predictMeasurementPoints(x, P, wide, repairedPrediction, points, expected, zMean, Pzz);
      widened = widened || wide.has_value();
      Matrix<N, M> Pxz(n, m);
      // The state deviations of fresh sigma points are the columns of the root, exactly: not
      // wrapped, even when an angle's spread exceeds pi.
      transform.crossCovariance(points, x, expected, zMean, Pxz, AngleMask<N>(n),
                                this->angleMeasurements_);

      crossCovarianceCorrection<N, M>(z, zMean, this->angleMeasurements_, this->R_, Pxz, Pzz, x, P);
    }
    this->commit(x, P, repairedPrediction);
    if (widened) ++this->repairs_.sigmaSpread;
  }

  /// z^ and Pzz of the unscented transform of the predicted belief for the next step with
  /// the current control; the filter is unchanged.
  void predictMeasurement(MeasurementPrediction<M>& out) const {
    const Index n = this->stateSize(), m = this->measurementSize();
    const Index count = transform_.pointCount();
    Vector<N> x(n);
    Matrix<N, N> P(n, n);
    bool widened = false, repaired = false;
    predict(x, P, widened);
    Matrix<N, S> points(n, count);
    Matrix<M, S> expected(m, count);
    std::optional<UnscentedTransform<N>> wide;
    predictMeasurementPoints(x, P, wide, repaired, points, expected, out.mean, out.covariance);
    out.noise = this->R_;
    out.angular = this->angleMeasurements_.mask();
  }

  const Model& model() const { return model_; }
  Model& model() { return model_; }
  const UnscentedParameters& parameters() const { return params_; }

 private:
  /// Time update: sigma points of the current belief propagated through f; P includes Q; the
  /// mean as params_.predictedMean says.
  /// P may have lost positive semi-definiteness (a negative central covariance weight, beta
  /// < 0 or a small alpha with a strongly nonlinear f, can make the unscented covariance
  /// indefinite): the correction (predictMeasurementPoints) or commit() repairs it.
  /// `widened` is set when the sigma points needed a larger alpha (transformFor).
  void predict(Vector<N>& x, Matrix<N, N>& P, bool& widened) const {
    const Index n = this->stateSize();
    const Index count = transform_.pointCount();
    Matrix<N, S> points(n, count), propagated(n, count);
    std::optional<UnscentedTransform<N>> wide;
    const UnscentedTransform<N>& transform = transformFor(this->x_, this->P_, wide);
    widened = wide.has_value();
    transform.sigmaPoints(this->x_, this->P_, points);
    Vector<N> in(n), out(n);
    for (Index i = 0; i < count; ++i) {
      in = points.col(i);
      model_.transition(in, this->u_, out);
      propagated.col(i) = out;
    }
    // The covariance is always the one around the points' weighted mean: with the propagated
    // mean it is UKF-M's covariance of the deviations from f(x) about their own mean.
    transform.mean(propagated, x, this->angleStates_);
    transform.crossCovariance(propagated, x, propagated, x, P, this->angleStates_,
                              this->angleStates_);
    if (params_.predictedMean == PredictedMean::Propagated) {
      x = propagated.col(0);  // the central sigma point is the mean itself
      this->angleStates_.wrap(x);
    }
    P += this->Q_;
    symmetrize(P);
    if (!x.allFinite() || !P.allFinite()) {
      rejectStep(this->method_, "the time update became non-finite");
    }
  }

  /// Fresh sigma points of the predicted belief (x, P), their images under h, and the
  /// images' mean and covariance (without R); returns the transform used (the configured
  /// one or, widened for a badly scaled state, `wide`). A P that has no Cholesky factor
  /// and lost positive semi-definiteness is repaired first (`repaired` set); the factor
  /// that makes the points is the check, so a healthy P costs no extra factorisation.
  const UnscentedTransform<N>& predictMeasurementPoints(const Vector<N>& x, Matrix<N, N>& P,
                                                        std::optional<UnscentedTransform<N>>& wide,
                                                        bool& repaired, Matrix<N, S>& points,
                                                        Matrix<M, S>& expected, Vector<M>& zMean,
                                                        Matrix<M, M>& Pzz) const {
    const Index n = this->stateSize(), m = this->measurementSize();
    const UnscentedTransform<N>* transform = &transformFor(x, P, wide);
    if (!transform->choleskySigmaPoints(x, P, points)) {
      repaired = repairCovariance(P);
      if (repaired) {
        wide.reset();
        transform = &transformFor(x, P, wide);  // the spread depends on the variances
      }
      transform->sigmaPoints(x, P, points);
    }
    Vector<N> in(n);
    Vector<M> zi(m);
    for (Index i = 0; i < transform->pointCount(); ++i) {
      in = points.col(i);
      model_.observation(in, zi);
      expected.col(i) = zi;
    }
    transform->mean(expected, zMean, this->angleMeasurements_);
    transform->crossCovariance(expected, zMean, expected, zMean, Pzz, this->angleMeasurements_,
                               this->angleMeasurements_);
    return *transform;
  }

  /// The configured transform, or, when its sigma points of (x, P) would be too close to x to
  /// be resolved in floating point (UnscentedTransform::alphaFor), one with the alpha that
  /// resolves them, built in `wide` for this step.
  const UnscentedTransform<N>& transformFor(const Vector<N>& x, const Matrix<N, N>& P,
                                            std::optional<UnscentedTransform<N>>& wide) const {
    const double alpha = transform_.alphaFor(x, P);
    if (alpha <= params_.alpha) return transform_;
    UnscentedParameters widened = params_;
    widened.alpha = alpha;
    wide.emplace(this->stateSize(), widened);
    return *wide;
  }

  Model model_;
  UnscentedTransform<N> transform_;
  UnscentedParameters params_;
};

}  // namespace estimation
