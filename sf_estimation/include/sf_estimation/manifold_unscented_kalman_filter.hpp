// Unscented Kalman filter on a state layout (UKF-M: Brossard, Barrau, Bonnabel 2020, "A Code
// for Unscented Kalman Filtering on Manifolds"). Sigma points are drawn in the tangent space
// and put on the manifold by the retraction, x [+] xi_j; nothing is averaged on the manifold:
//   propagation: the mean is f(x, u, 0) itself; the covariance is the unscented covariance of
//     the deviations f(x [+] xi_j, u, 0) [-] f(x, u, 0) (state sigma points) plus that of
//     f(x, u, w_j) [-] f(x, u, 0) (noise sigma points), each with its own alpha;
//   update: measurement sigma points h(x [+] xi_j), compared with h(x) by the measurement
//     layout's [-]; x+ = x [+] K nu with nu = z [-] (h(x) [+] mean deviation).
// A flat layout with a linear model gives the Kalman filter's result exactly (the transform
// is exact for linear maps; test_manifold_filters.cpp). The covariance reset Jacobian after
// x [+] K nu is not applied, as in UKF-M: it differs from the identity only to first order in
// K nu, i.e. by the size of the correction, and the benchmarks (doc/manifolds.md) show the
// filter consistent without it.
//
// Unlike UnscentedKalmanFilter, the step is split into predict(u) and update(z), so that
// sensors of different rates need no missing-entry handling; every size is fixed and a step
// allocates nothing.
#pragma once

#include <cmath>

#include "sf_estimation/kalman_correction.hpp"
#include "sf_estimation/manifold/manifold_filter_base.hpp"
#include "sf_estimation/probability/gaussian.hpp"

namespace estimation {

/// UKF-M's three sigma-point spreads (their benchmarks use 1e-3 for all three).
struct ManifoldUnscentedParameters {
  double alphaState = 1e-3;   ///< sigma points of the state, propagation
  double alphaNoise = 1e-3;   ///< sigma points of the process noise
  double alphaUpdate = 1e-3;  ///< sigma points of the state, update
};

namespace manifold {

/// Weights of 2n + 1 sigma points of spread alpha (beta = 2, kappa = 0): lambda = (alpha^2 -
/// 1) n, points at +-sqrt(n + lambda) times the root's columns, weight 1 / (2 (n + lambda))
/// each; the central point's mean weight lambda / (n + lambda) and covariance weight that + 3
/// - alpha^2.
struct SigmaWeights {
  SigmaWeights(int n, double alpha, const std::string& method) {
    if (!(alpha > 0.0 && alpha <= 1.0)) {
      throw ParameterError(method + ": sigma-point alpha must be in (0, 1]");
    }
    const double lambda = (alpha * alpha - 1.0) * n;
    spread = std::sqrt(n + lambda);
    point = 0.5 / (n + lambda);
    centralMean = lambda / (n + lambda);
    centralCovariance = centralMean + 3.0 - alpha * alpha;
  }
  double spread, point, centralMean, centralCovariance;
};

/// Mean and covariance of deviations from the central point (which deviates by 0): the 2n
/// columns of `deviations` are the other points'. mean = w sum_j d_j, covariance =
/// w sum_j (d_j - mean)(d_j - mean)^T + w_0c mean mean^T.
template <int Rows, int Points>
void unscentedMoments(const Matrix<Rows, Points>& deviations, const SigmaWeights& w,
                      Vector<Rows>& mean, Matrix<Rows, Rows>& covariance) {
  mean = w.point * deviations.rowwise().sum();
  const Matrix<Rows, Points> centred = deviations.colwise() - mean;
  covariance.noalias() = w.point * centred * centred.transpose();
  covariance.noalias() += w.centralCovariance * mean * mean.transpose();
}

}  // namespace manifold

template <class Model>
class ManifoldUnscentedKalmanFilter : public manifold::ManifoldFilterBase<Model> {
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

  ManifoldUnscentedKalmanFilter(Model model, const ProcessNoise& Q, const MeasurementNoise& R,
                                const State& x0, const Covariance& P0,
                                const ManifoldUnscentedParameters& params = {})
      : Base("ManifoldUnscentedKalmanFilter", std::move(model), Q, R, x0, P0),
        stateWeights_(D, params.alphaState, this->method_),
        noiseWeights_(W, params.alphaNoise, this->method_),
        updateWeights_(D, params.alphaUpdate, this->method_),
        noiseRoot_(W) {
    noiseRoot_.compute(this->Q_);
  }

  /// x <- f(x, u, 0), P <- covariance of the propagated state and noise sigma points. Defined
  /// below, out of the class (not inline): a node of a 3D header compiles it in its second unit
  /// (SF_ESTIMATION_MANIFOLD_UKF_PREDICT).
  void predict(const Control& u);

  /// x <- x [+] K nu, P <- P - K Pzz K^T, nu = z [-] z^ (z^ the predicted measurement).
  void update(const MeasurementValue& z) {
    this->checkMeasurement(z);
    Matrix<D, 2 * D> xis;
    sigmaPoints(this->P_, updateWeights_, xis);
    MeasurementValue central, zj;
    this->model_.observation(this->x_, central);
    Matrix<M, 2 * D> deviations;
    State in;
    for (Index j = 0; j < 2 * D; ++j) {
      in = Space::template plus<double>(this->x_, xis.col(j));
      this->model_.observation(in, zj);
      deviations.col(j) = MSpace::template minus<double>(zj, central);
    }
    Vector<M> mean;
    Matrix<M, M> S;
    manifold::unscentedMoments<M, 2 * D>(deviations, updateWeights_, mean, S);
    S += this->R_;
    symmetrize(S);
    // Cross covariance: the central point deviates by 0 in the state.
    const Matrix<M, 2 * D> centred = deviations.colwise() - mean;
    Matrix<D, M> Pxz;
    Pxz.noalias() = updateWeights_.point * xis * centred.transpose();
    Matrix<D, M> K;
    kalmanGain<D, M>(Pxz, S, K);
    const MeasurementValue predicted = MSpace::template plus<double>(central, mean);
    const Vector<M> innovation = MSpace::template minus<double>(z, predicted);
    const Vector<D> correction = K * innovation;
    State x = Space::template plus<double>(this->x_, correction);
    Covariance P = this->P_;
    P.noalias() -= K * S * K.transpose();
    this->commit(x, P);
  }

 protected:
  /// The 2 D tangent sigma points +-spread * S_j, S S^T = P (P may be singular: a state known
  /// exactly). Throws NumericalError for an indefinite P.
  void sigmaPoints(const Covariance& P, const manifold::SigmaWeights& w, Matrix<D, 2 * D>& xis) {
    root_.compute(P);
    xis.template leftCols<D>() = w.spread * root_.matrix();
    xis.template rightCols<D>() = -w.spread * root_.matrix();
  }

  manifold::SigmaWeights stateWeights_, noiseWeights_, updateWeights_;
  probability::CovarianceSquareRoot<W> noiseRoot_;
  probability::CovarianceSquareRoot<D> root_{D};  // scratch of sigmaPoints()
};

template <class Model>
void ManifoldUnscentedKalmanFilter<Model>::predict(const Control& u) {
  this->checkControl(u);
  const Vector<W> noNoise = Vector<W>::Zero();
  State next;
  this->model_.transition(this->x_, u, noNoise, next);
  Matrix<D, 2 * D> xis;
  sigmaPoints(this->P_, stateWeights_, xis);
  Matrix<D, 2 * D> deviations;
  State in, out;
  for (Index j = 0; j < 2 * D; ++j) {
    in = Space::template plus<double>(this->x_, xis.col(j));
    this->model_.transition(in, u, noNoise, out);
    deviations.col(j) = Space::template minus<double>(out, next);
  }
  Vector<D> mean;
  Covariance P, PNoise;
  manifold::unscentedMoments<D, 2 * D>(deviations, stateWeights_, mean, P);
  Matrix<D, 2 * W> noiseDeviations;
  Vector<W> w;
  for (Index j = 0; j < W; ++j) {
    for (const int sign : {1, -1}) {
      w = sign * noiseWeights_.spread * noiseRoot_.matrix().col(j);
      this->model_.transition(this->x_, u, w, out);
      noiseDeviations.col(sign > 0 ? j : W + j) = Space::template minus<double>(out, next);
    }
  }
  manifold::unscentedMoments<D, 2 * W>(noiseDeviations, noiseWeights_, mean, PNoise);
  P += PNoise;
  this->commit(next, P);
}

// The size-only parts at the shipped 3D UKF's sizes (config/armesto_inertial_vision_ukf.h:
// 18 tangent, 13 measurement entries, 2 x 18 sigma points), compiled once in the library with
// its Kalman steps at 18 (layout_kalman_steps_18.cpp, kalman_correction.hpp).
#define SF_ESTIMATION_LAYOUT_UNSCENTED_STEPS_15(PREFIX)
#define SF_ESTIMATION_LAYOUT_UNSCENTED_STEPS_18(PREFIX)                                    \
  PREFIX template class probability::CovarianceSquareRoot<18>;                             \
  PREFIX template void manifold::unscentedMoments<18, 36>(                                 \
      const Matrix<18, 36>&, const manifold::SigmaWeights&, Vector<18>&, Matrix<18, 18>&); \
  PREFIX template void manifold::unscentedMoments<13, 36>(                                 \
      const Matrix<13, 36>&, const manifold::SigmaWeights&, Vector<13>&, Matrix<13, 13>&);
#if !defined(SF_ESTIMATION_INSTANTIATING_KALMAN_STEPS) && !defined(SF_ESTIMATION_IMPLICIT_INSTANCES)
SF_ESTIMATION_LAYOUT_UNSCENTED_STEPS_18(extern)
#endif

}  // namespace estimation

// UKF-M's propagation of FILTER (a ManifoldUnscentedKalmanFilter), declared extern (PREFIX
// extern) in a node's units and instantiated (PREFIX empty) in its second unit, beside the step
// in the third (doc/build_cost.md, "The 3D headers' step").
#define SF_ESTIMATION_MANIFOLD_UKF_PREDICT(PREFIX, FILTER) \
  PREFIX template void FILTER::predict(const FILTER::Control&);
