// The unscented Kalman filter of a flat model (x' = f(x, u), z = h(x), the configuration
// header's) over a state layout with rotations (QUATERNION_STATES): UKF-M's time update
// (manifold_unscented_kalman_filter.hpp: the mean propagated by f itself, the covariance from
// tangent sigma points) behind the flat filters' interface (FlatInterface). The noise is added
// on the tangent, f(x, u) [+] w (AdditiveNoiseModel). The correction takes sigma points
// x [+] xi_j of the predicted belief, the deviations h(x [+] xi_j) - h(x) (angles wrapped)
// give z^ = h(x) + their mean, Pzz and Pxz, and the flat filters' cross-covariance
// correction of the tangent error uses the present entries of z only; then x <- x [+] K nu.
// The measurement layout's rotations (measurement_rows.hpp) are compared as z [-] h: their
// deviations are h(x [+] xi_j) [-] h(x) and the innovation (z [-] h(x)) - their mean.
#pragma once

#include "sf_estimation/kalman_correction.hpp"
#include "sf_estimation/manifold/additive_noise_model.hpp"
#include "sf_estimation/manifold/flat_interface.hpp"
#include "sf_estimation/manifold/measurement_rows.hpp"
#include "sf_estimation/manifold_unscented_kalman_filter.hpp"
#include "sf_estimation/measurement_prediction.hpp"

namespace estimation {

template <class FlatModel, class Layout,
          class MeasurementLayout = manifold::FlatLayout<FlatModel::MeasurementSize>>
class LayoutUnscentedKalmanFilter
    : public manifold::FlatInterface<ManifoldUnscentedKalmanFilter<
          manifold::AdditiveNoiseModel<FlatModel, Layout, MeasurementLayout>>> {
  using LayoutModel = manifold::AdditiveNoiseModel<FlatModel, Layout, MeasurementLayout>;
  using Rows = manifold::MeasurementRows<MeasurementLayout>;
  using Manifold = ManifoldUnscentedKalmanFilter<LayoutModel>;
  using Interface = manifold::FlatInterface<Manifold>;
  static constexpr int N = Interface::StateSize, M = Interface::MeasurementSize;
  static constexpr int D = Interface::TangentSize;
  using State = typename Interface::State;
  using Covariance = typename Interface::Covariance;

 public:
  LayoutUnscentedKalmanFilter(FlatModel model, const Matrix<N, N>& Q, const Matrix<M, M>& R,
                              const Vector<N>& x0, const Matrix<N, N>& P0,
                              const ManifoldUnscentedParameters& params = {},
                              const AngularComponents& angles = {})
      : Interface(angles, LayoutModel{std::move(model)}, Q, R, x0, P0, params) {}

  /// Time update with the last control, then the correction by the present entries of z.
  /// Throws InvalidInputError or NumericalError and keeps the belief on failure.
  void estimate(const Measurement<M>& z);

  /// z^ and the covariance of h over the sigma points of the next step's predicted belief, for
  /// the gates and the NIS; the filter is unchanged (a copy predicts).
  void predictMeasurement(MeasurementPrediction<M>& out) const;

  const FlatModel& model() const { return this->model_.flat; }

 private:
  /// h(x), the mean deviation, Pzz (R not included) and Pxz of the current belief.
  void measurementMoments(Vector<M>& central, Vector<M>& deviationMean, Matrix<M, M>& Pzz,
                          Matrix<D, M>& Pxz) {
    Matrix<D, 2 * D> xis;
    this->sigmaPoints(this->P_, this->updateWeights_, xis);
    Vector<M> zj;
    this->model_.observation(this->x_, central);
    Matrix<M, 2 * D> deviations;
    for (Index j = 0; j < 2 * D; ++j) {
      this->model_.observation(Layout::template plus<double>(this->x_, xis.col(j)), zj);
      if constexpr (MeasurementLayout::IsFlat) {
        deviations.col(j) = zj - central;
      } else {
        deviations.col(j) = Rows::innovation(zj, central);
      }
    }
    this->angleMeasurements_.wrap(deviations);
    manifold::unscentedMoments<M, 2 * D>(deviations, this->updateWeights_, deviationMean, Pzz);
    const Matrix<M, 2 * D> centred = deviations.colwise() - deviationMean;
    Pxz.noalias() = this->updateWeights_.point * xis * centred.transpose();
  }

  void correct(const Measurement<M>& z) {
    Vector<M> mean, deviationMean;
    Matrix<M, M> Pzz;
    Matrix<D, M> Pxz;
    measurementMoments(mean, deviationMean, Pzz, Pxz);
    Vector<D> correction = Vector<D>::Zero();
    Covariance P = this->P_;
    if constexpr (MeasurementLayout::IsFlat) {
      mean += deviationMean;
      this->angleMeasurements_.wrap(mean);
      crossCovarianceCorrection<D, M>(z, mean, this->angleMeasurements_, this->R_, Pxz, Pzz,
                                      correction, P);
    } else {
      // The innovation (z [-] h(x)) - deviation mean, as the flat one is z - (h(x) + mean).
      Measurement<M> about = z;
      about.value = Rows::innovation(z.value, mean);
      Rows::withoutTangentFreeRows(about);
      crossCovarianceCorrection<D, M>(about, deviationMean, this->angleMeasurements_, this->R_, Pxz,
                                      Pzz, correction, P);
    }
    State x = Layout::template plus<double>(this->x_, correction);
    this->commit(x, P);
  }
};

// The step, defined out of the class (not inline), so that a node compiles it, most of the
// filter's compile cost, in its third unit (SF_ESTIMATION_LAYOUT_UKF_STEP).
template <class FlatModel, class Layout, class MeasurementLayout>
void LayoutUnscentedKalmanFilter<FlatModel, Layout, MeasurementLayout>::estimate(
    const Measurement<M>& z) {
  z.validate(M);
  const State x = this->x_;
  const Covariance P = this->P_;
  try {
    Manifold::predict(this->u_);
    if (z.anyAvailable()) correct(z);
  } catch (const EstimationError&) {
    this->x_ = x;
    this->P_ = P;
    throw;
  }
}

template <class FlatModel, class Layout, class MeasurementLayout>
void LayoutUnscentedKalmanFilter<FlatModel, Layout, MeasurementLayout>::predictMeasurement(
    MeasurementPrediction<M>& out) const {
  LayoutUnscentedKalmanFilter predicted = *this;
  predicted.Manifold::predict(this->u_);
  Matrix<D, M> Pxz;
  Vector<M> deviationMean;
  predicted.measurementMoments(out.mean, deviationMean, out.covariance, Pxz);
  out.mean += deviationMean;
  this->angleMeasurements_.wrap(out.mean);
  out.noise = this->R_;
  out.angular = this->angleMeasurements_.mask();
}

}  // namespace estimation

// The step of FILTER (a LayoutUnscentedKalmanFilter), declared extern (PREFIX extern) in a
// node's units and instantiated (PREFIX empty) in its third (fusion_node_step.cpp,
// doc/build_cost.md "The 3D headers' step").
#define SF_ESTIMATION_LAYOUT_UKF_STEP(PREFIX, FILTER)                                            \
  PREFIX template void FILTER::estimate(const estimation::Measurement<FILTER::M>&);              \
  PREFIX template void FILTER::predictMeasurement(estimation::MeasurementPrediction<FILTER::M>&) \
      const;
