// Extended Kalman filter (thesis Algorithm 3.2) for x' = f(x, u), z = h(x). Jacobians come
// from the model when it has them, otherwise from automatic differentiation (jacobian.hpp).
#pragma once

#include <utility>

#include "sf_estimation/abstract_kalman_filter.hpp"
#include "sf_estimation/jacobian.hpp"
#include "sf_estimation/kalman_correction.hpp"
#include "sf_estimation/measurement_prediction.hpp"

namespace estimation {

template <class Model>
class ExtendedKalmanFilter
    : public AbstractKalmanFilter<Model::StateSize, Model::MeasurementSize, Model::ControlSize> {
  static constexpr int N = Model::StateSize;
  static constexpr int M = Model::MeasurementSize;
  static constexpr int L = Model::ControlSize;
  using Base = AbstractKalmanFilter<N, M, L>;

 public:
  ExtendedKalmanFilter(Model model, const Matrix<N, N>& Q, const Matrix<M, M>& R,
                       const Vector<N>& x0, const Matrix<N, N>& P0,
                       const AngularComponents& angles = {})
      : Base("ExtendedKalmanFilter", Q, R, x0, P0, model.controlSize(), angles),
        model_(std::move(model)) {
    checkModelSizes(this->method_, model_, this->stateSize(), this->measurementSize());
  }

  ExtendedKalmanFilter(Model model, const Matrix<N, N>& Q, const Matrix<M, M>& R)
      : ExtendedKalmanFilter(std::move(model), Q, R, Vector<N>::Zero(Q.rows()),
                             Matrix<N, N>::Identity(Q.rows(), Q.rows())) {}

  void estimate(const Measurement<M>& z) {
    z.validate(this->measurementSize());
    const Index n = this->stateSize();
    Vector<N> x(n);
    Matrix<N, N> P(n, n);
    predict(x, P);
    if (z.anyAvailable()) {
      const Index m = this->measurementSize();
      Matrix<M, N> H(m, n);
      Vector<M> expected(m);
      observationJacobian(model_, x, H, &expected);
      Vector<M> y = z.value - expected;
      this->angleMeasurements_.wrap(y);
      neutraliseMissing(z, y, H);
      Matrix<M, M> R(m, m);
      effectiveMeasurementNoise(this->R_, z, R);
      linearCorrection<N, M>(x, P, H, y, R);
    }
    this->commit(x, P);
  }

  /// z^ = h(x(k|k-1)) and H P(k|k-1) H^T (H the observation Jacobian at x(k|k-1)) for the
  /// next step with the current control; the filter is unchanged.
  void predictMeasurement(MeasurementPrediction<M>& out) const {
    const Index n = this->stateSize(), m = this->measurementSize();
    Vector<N> x(n);
    Matrix<N, N> P(n, n);
    predict(x, P);
    Matrix<M, N> H(m, n);
    observationJacobian(model_, x, H, &out.mean);
    this->angleMeasurements_.wrap(out.mean);
    projectCovariance<N, M>(H, P, out.covariance);
    out.noise = this->R_;
    out.angular = this->angleMeasurements_.mask();
  }

  const Model& model() const { return model_; }
  Model& model() { return model_; }

 private:
  /// Time update of the current belief: x(k|k-1) = f(x, u), P(k|k-1) = A P A^T + Q with A
  /// the transition Jacobian at the current state.
  void predict(Vector<N>& x, Matrix<N, N>& P) const {
    const Index n = this->stateSize();
    Matrix<N, N> A(n, n);
    transitionJacobian(model_, this->x_, this->u_, A, &x);
    propagateCovariance<N>(A, this->P_, this->Q_, P);
  }

  Model model_;
};

}  // namespace estimation
