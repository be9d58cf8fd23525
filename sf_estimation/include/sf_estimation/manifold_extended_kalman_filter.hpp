// Error-state (multiplicative) extended Kalman filter on a state layout: the state is stored
// on its manifold (angles, unit quaternions) and the covariance is over the tangent
// perturbation e, true state = x [+] e. The Jacobians are taken with respect to that
// perturbation by AutoDiff of the model's own code (jacobian.hpp does the same for the flat
// filters), at e = 0 and w = 0:
//   F = d/de [f(x [+] e, u, 0) [-] f(x, u, 0)],  G = d/dw [f(x, u, w) [-] f(x, u, 0)],
//   H = d/de [h(x [+] e) [-] h(x)]  (the measurement layout's [-]),
// P <- F P F^T + G Q G^T; the update is the Joseph-form linear correction of the flat filters
// (kalman_correction.hpp) on the tangent error, nu = z [-] h(x), then x <- x [+] K nu.
//
// The covariance reset Jacobian (the error redefined about the new mean after x [+] K nu,
// e.g. I - [K nu / 2]x for a quaternion) is not applied: it differs from the identity by the
// size of the correction, which is small wherever the linearisation itself holds, and UKF-M's
// EKF, whose benchmark doc/manifolds.md reproduces, leaves it out too.
#pragma once

#include <unsupported/Eigen/AutoDiff>

#include "sf_estimation/kalman_correction.hpp"
#include "sf_estimation/manifold/manifold_filter_base.hpp"

namespace estimation {

template <class Model>
class ManifoldExtendedKalmanFilter : public manifold::ManifoldFilterBase<Model> {
  using Base = manifold::ManifoldFilterBase<Model>;
  using Space = typename Base::StateSpace;
  using MSpace = typename Base::MeasurementSpace;
  static constexpr int X = Base::StoredSize, D = Base::TangentSize, W = Base::NoiseSize;
  static constexpr int Z = Base::MeasurementStoredSize, M = Base::MeasurementTangentSize;

 public:
  using typename Base::Control;
  using typename Base::Covariance;
  using typename Base::MeasurementNoise;
  using typename Base::MeasurementValue;
  using typename Base::ProcessNoise;
  using typename Base::State;

  ManifoldExtendedKalmanFilter(Model model, const ProcessNoise& Q, const MeasurementNoise& R,
                               const State& x0, const Covariance& P0)
      : Base("ManifoldExtendedKalmanFilter", std::move(model), Q, R, x0, P0) {}

  /// x <- f(x, u, 0), P <- F P F^T + G Q G^T.
  void predict(const Control& u) {
    this->checkControl(u);
    State next;
    Matrix<D, D> F;
    Matrix<D, W> G;
    transitionJacobians(u, next, F, G);
    Covariance GQGt;
    GQGt.noalias() = G * this->Q_ * G.transpose();
    Covariance P;
    propagateCovariance<D>(F, this->P_, GQGt, P);
    this->commit(next, P);
  }

  /// Joseph-form correction of the tangent error by nu = z [-] h(x), then x <- x [+] K nu.
  void update(const MeasurementValue& z) {
    this->checkMeasurement(z);
    MeasurementValue expected;
    Matrix<M, D> H;
    observationJacobian(expected, H);
    const Vector<M> innovation = MSpace::template minus<double>(z, expected);
    Vector<D> correction = Vector<D>::Zero();
    Covariance P = this->P_;
    linearCorrection<D, M>(correction, P, H, innovation, this->R_);
    State x = Space::template plus<double>(this->x_, correction);
    this->commit(x, P);
  }

  /// F and G at the current state (see the top of the file) and f(x, u, 0).
  void transitionJacobians(const Control& u, State& next, Matrix<D, D>& F, Matrix<D, W>& G) const {
    transitionJacobiansAt(this->model_, this->x_, u, next, F, G);
  }

  /// F and G of `model` at the state x and f(x, u, 0) (the smoother re-derives its
  /// predictions with it, manifold_rts_smoother.hpp).
  static void transitionJacobiansAt(const Model& model, const State& at, const Control& u,
                                    State& next, Matrix<D, D>& F, Matrix<D, W>& G) {
    using Ad = Eigen::AutoDiffScalar<Vector<D + W>>;
    typename Space::template Tangent<Ad> e;
    Eigen::Matrix<Ad, W, 1> w;
    for (Index i = 0; i < D; ++i) e(i) = Ad(0.0, D + W, i);
    for (Index i = 0; i < W; ++i) w(i) = Ad(0.0, D + W, D + i);
    const typename Space::template Stored<Ad> x =
        Space::template plus<Ad>(at.template cast<Ad>(), e);
    typename Space::template Stored<Ad> out;
    model.transition(x, u, w, out);
    for (Index i = 0; i < X; ++i) next(i) = out(i).value();
    const typename Space::template Tangent<Ad> deviation =
        Space::template minus<Ad>(out, next.template cast<Ad>());
    for (Index i = 0; i < D; ++i) {
      F.row(i) = deviation(i).derivatives().template head<D>().transpose();
      G.row(i) = deviation(i).derivatives().template tail<W>().transpose();
    }
  }

  /// H at the current state and h(x).
  void observationJacobian(MeasurementValue& expected, Matrix<M, D>& H) const {
    observationJacobianAt(this->model_, this->x_, expected, H);
  }

  /// H of `model` at the state x and h(x) (the node's filter on a layout takes it at the
  /// predicted state, layout_extended_kalman_filter.hpp).
  static void observationJacobianAt(const Model& model, const State& at, MeasurementValue& expected,
                                    Matrix<M, D>& H) {
    using Ad = Eigen::AutoDiffScalar<Vector<D>>;
    typename Space::template Tangent<Ad> e;
    for (Index i = 0; i < D; ++i) e(i) = Ad(0.0, D, i);
    const typename Space::template Stored<Ad> x =
        Space::template plus<Ad>(at.template cast<Ad>(), e);
    typename MSpace::template Stored<Ad> out;
    model.observation(x, out);
    for (Index i = 0; i < Z; ++i) expected(i) = out(i).value();
    const typename MSpace::template Tangent<Ad> deviation =
        MSpace::template minus<Ad>(out, expected.template cast<Ad>());
    for (Index i = 0; i < M; ++i) H.row(i) = deviation(i).derivatives().transpose();
  }
};

}  // namespace estimation
