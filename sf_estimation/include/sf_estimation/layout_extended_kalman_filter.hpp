// The extended Kalman filter of a flat model (x' = f(x, u), z = h(x), the configuration
// header's) over a state layout with rotations (QUATERNION_STATES): the error-state EKF of
// manifold_extended_kalman_filter.hpp behind the flat filters' interface (FlatInterface), with
// missing measurement entries handled as ExtendedKalmanFilter handles them. The noise is added
// on the tangent, f(x, u) [+] w (AdditiveNoiseModel), so its Jacobian G is the identity and
// only F = d/de [f(x [+] e, u) [-] f(x, u)] at e = 0 is differentiated (AutoDiff of the
// model's code): P <- F P F^T + Q; the Joseph-form correction of the tangent error by the
// present entries of z - h(x) (angles wrapped; the measurement layout's rotations as z [-] h(x),
// measurement_rows.hpp), then x <- x [+] K nu.
#pragma once

#include <Eigen/Core>
#include <unsupported/Eigen/AutoDiff>

#include "sf_estimation/kalman_correction.hpp"
#include "sf_estimation/manifold/additive_noise_model.hpp"
#include "sf_estimation/manifold/flat_interface.hpp"
#include "sf_estimation/manifold/measurement_rows.hpp"
#include "sf_estimation/manifold_extended_kalman_filter.hpp"
#include "sf_estimation/measurement_noise.hpp"
#include "sf_estimation/measurement_prediction.hpp"

namespace estimation {

template <class FlatModel, class Layout,
          class MeasurementLayout = manifold::FlatLayout<FlatModel::MeasurementSize>>
class LayoutExtendedKalmanFilter
    : public manifold::FlatInterface<ManifoldExtendedKalmanFilter<
          manifold::AdditiveNoiseModel<FlatModel, Layout, MeasurementLayout>>> {
  using LayoutModel = manifold::AdditiveNoiseModel<FlatModel, Layout, MeasurementLayout>;
  using Rows = manifold::MeasurementRows<MeasurementLayout>;
  using Manifold = ManifoldExtendedKalmanFilter<LayoutModel>;
  using Interface = manifold::FlatInterface<Manifold>;
  static constexpr int N = Interface::StateSize, M = Interface::MeasurementSize;
  static constexpr int D = Interface::TangentSize;
  using State = typename Interface::State;
  using Covariance = typename Interface::Covariance;

 public:
  LayoutExtendedKalmanFilter(FlatModel model, const Matrix<N, N>& Q, const Matrix<M, M>& R,
                             const Vector<N>& x0, const Matrix<N, N>& P0,
                             const AngularComponents& angles = {})
      : Interface(angles, LayoutModel{std::move(model)}, Q, R, x0, P0) {}

  /// Time update with the last control, then the correction by the present entries of z.
  /// Throws InvalidInputError or NumericalError and keeps the belief on failure.
  void estimate(const Measurement<M>& z);

  /// z^ = h(x(k|k-1)) and H P(k|k-1) H^T for the next step; the filter is unchanged. The
  /// covariance is over the flat measurement, as the gates and the NIS expect.
  void predictMeasurement(MeasurementPrediction<M>& out) const;

  const FlatModel& model() const { return this->model_.flat; }

 private:
  /// The Joseph-form correction of (x, P) by the present entries of the innovation y.
  void correct(const Measurement<M>& z, Vector<M> y, Matrix<M, D>& H, State& x,
               Covariance& P) const {
    this->angleMeasurements_.wrap(y);
    neutraliseMissing(z, y, H);
    Matrix<M, M> R;
    effectiveMeasurementNoise(this->R_, z, R);
    Vector<D> correction = Vector<D>::Zero();
    linearCorrection<D, M>(correction, P, H, y, R);
    x = Layout::template plus<double>(x, correction);
  }

  /// x(k|k-1) = f(x, u) (normalised), P(k|k-1) = F P F^T + Q.
  void predict(State& x, Covariance& P) const {
    Matrix<D, D> F;
    transitionJacobian(x, F);
    propagateCovariance<D>(F, this->P_, this->Q_, P);
  }

  // The model's Jacobians by AutoDiff, most of the filter's compile cost: defined below, out
  // of the class (not inline), so that a node compiles them in its second unit
  // (SF_ESTIMATION_LAYOUT_EKF_JACOBIANS), and the step above in its third
  // (SF_ESTIMATION_LAYOUT_EKF_STEP).

  /// F at the current state (see the top of the file) and f(x, u).
  void transitionJacobian(State& next, Matrix<D, D>& F) const;

  /// H at the state x and h(x).
  void observationJacobian(const State& x, Vector<M>& expected, Matrix<M, D>& H) const;
};

template <class FlatModel, class Layout, class MeasurementLayout>
void LayoutExtendedKalmanFilter<FlatModel, Layout, MeasurementLayout>::estimate(
    const Measurement<M>& z) {
  z.validate(M);
  State x;
  Covariance P;
  predict(x, P);
  if (z.anyAvailable()) {
    Matrix<M, D> H;
    Vector<M> expected;
    observationJacobian(x, expected, H);
    if constexpr (MeasurementLayout::IsFlat) {
      correct(z, z.value - expected, H, x, P);
    } else {
      Measurement<M> present = z;
      Rows::withoutTangentFreeRows(present);
      Rows::tangentRows(expected, H);
      correct(present, Rows::innovation(z.value, expected), H, x, P);
    }
  }
  this->commit(x, P);
}

template <class FlatModel, class Layout, class MeasurementLayout>
void LayoutExtendedKalmanFilter<FlatModel, Layout, MeasurementLayout>::predictMeasurement(
    MeasurementPrediction<M>& out) const {
  State x;
  Covariance P;
  predict(x, P);
  Matrix<M, D> H;
  observationJacobian(x, out.mean, H);
  this->angleMeasurements_.wrap(out.mean);
  projectCovariance<D, M>(H, P, out.covariance);
  out.noise = this->R_;
  out.angular = this->angleMeasurements_.mask();
}

template <class FlatModel, class Layout, class MeasurementLayout>
void LayoutExtendedKalmanFilter<FlatModel, Layout, MeasurementLayout>::transitionJacobian(
    State& next, Matrix<D, D>& F) const {
  using Ad = Eigen::AutoDiffScalar<Vector<D>>;
  typename Layout::template Tangent<Ad> e;
  for (Index i = 0; i < D; ++i) e(i) = Ad(0.0, D, i);
  const typename Layout::template Stored<Ad> x =
      Layout::template plus<Ad>(this->x_.template cast<Ad>(), e);
  typename Layout::template Stored<Ad> f;
  this->model_.flat.transition(x, this->u_, f);
  for (Index i = 0; i < N; ++i) next(i) = f(i).value();
  Layout::normalise(next);
  const typename Layout::template Tangent<Ad> deviation =
      Layout::template minus<Ad>(f, next.template cast<Ad>());
  for (Index i = 0; i < D; ++i) F.row(i) = deviation(i).derivatives().transpose();
}

template <class FlatModel, class Layout, class MeasurementLayout>
void LayoutExtendedKalmanFilter<FlatModel, Layout, MeasurementLayout>::observationJacobian(
    const State& x, Vector<M>& expected, Matrix<M, D>& H) const {
  Manifold::observationJacobianAt(this->model_, x, expected, H);
}

}  // namespace estimation

// The Jacobians of FILTER (a LayoutExtendedKalmanFilter), declared extern (PREFIX extern) in
// a node's unit and instantiated (PREFIX empty) in its second unit, like the smoothers
// (doc/build_cost.md, "The 3D headers' Jacobians and the particle filter's step"), or each in
// a unit of its own (a measured rotation: "The Jacobians' unit").
#define SF_ESTIMATION_LAYOUT_EKF_TRANSITION_JACOBIAN(PREFIX, FILTER) \
  PREFIX template void FILTER::transitionJacobian(                   \
      FILTER::State&, estimation::Matrix<FILTER::D, FILTER::D>&) const;
#define SF_ESTIMATION_LAYOUT_EKF_OBSERVATION_JACOBIAN(PREFIX, FILTER) \
  PREFIX template void FILTER::observationJacobian(                   \
      const FILTER::State&, estimation::Vector<FILTER::M>&,           \
      estimation::Matrix<FILTER::M, FILTER::D>&) const;
#define SF_ESTIMATION_LAYOUT_EKF_JACOBIANS(PREFIX, FILTER)     \
  SF_ESTIMATION_LAYOUT_EKF_TRANSITION_JACOBIAN(PREFIX, FILTER) \
  SF_ESTIMATION_LAYOUT_EKF_OBSERVATION_JACOBIAN(PREFIX, FILTER)

// The step of FILTER (estimate and predictMeasurement: the corrections, a measured rotation's
// rows), likewise in a node's third unit (fusion_node_step.cpp, doc/build_cost.md "The 3D
// headers' step").
#define SF_ESTIMATION_LAYOUT_EKF_STEP(PREFIX, FILTER)                                            \
  PREFIX template void FILTER::estimate(const estimation::Measurement<FILTER::M>&);              \
  PREFIX template void FILTER::predictMeasurement(estimation::MeasurementPrediction<FILTER::M>&) \
      const;
