// The particle filter's linearised optimal proposal (Doucet, Godsill, Andrieu 2000, "On
// sequential Monte Carlo sampling methods for Bayesian filtering", section II.D.2): instead of
// drawing x_i from the transition N(f(x_i), Q) and weighing it by the likelihood alone, each
// particle is drawn from the Kalman posterior of its own prediction,
//   x_i ~ N(mu_i, Sigma),  mu_i = f(x_i) + K (z - h(f(x_i))),  K = Q H^T S^-1,  S = H Q H^T + R,
//   Sigma = (I - K H) Q (I - K H)^T + K R K^T,
// with H the Jacobian of h at the particles' mean prediction (central differences, shared by the
// particles), and weighed by the exact ratio
//   w_i *= N(z; h(x_i), R) N(x_i; f(x_i), Q) / N(x_i; mu_i, Sigma).
// For a linear h this is the optimal proposal, whose weights do not depend on the draw: an
// accurate sensor no longer leaves a few particles with all the weight, so the filter resamples
// rarely and a state the measurements cannot tell apart from another (a gyro bias in motion)
// keeps its spread instead of following the lineage that survives (doc/estimation.md).
// Dead-reckoned states (dead_reckoned_states.hpp) are left to the caller: their rows are taken
// out of Q here (an identity placeholder), so they get no gain and no noise.
#pragma once

#include <cmath>
#include <string>

#include <Eigen/Cholesky>
#include <Eigen/Core>

#include "sf_estimation/angles.hpp"
#include "sf_estimation/errors.hpp"
#include "sf_estimation/measurement.hpp"
#include "sf_estimation/measurement_noise.hpp"
#include "sf_estimation/probability/gaussian.hpp"
#include "sf_estimation/types.hpp"

namespace estimation {

template <class Model>
class LinearisedProposal {
  static constexpr int N = Model::StateSize;
  static constexpr int M = Model::MeasurementSize;

 public:
  LinearisedProposal() = default;

  /// Throws ParameterError when Q is not positive definite over the states outside `fixed`.
  LinearisedProposal(const Matrix<N, N>& Q, const Mask<N>& fixed, Index measurements)
      : fixed_(fixed),
        Q_(Q),
        H_(measurements, Q.rows()),
        S_(measurements, measurements),
        gainT_(measurements, Q.rows()),
        sigma_(Q.rows(), Q.rows()),
        sigmaWhitening_(Q.rows(), Q.rows()),
        Reff_(measurements, measurements) {
    const Index n = Q.rows();
    for (Index r = 0; r < n; ++r) {
      if (!fixed_(r)) continue;
      Q_.row(r).setZero();
      Q_.col(r).setZero();
      Q_(r, r) = 1.0;
    }
    Eigen::LLT<Matrix<N, N>> llt(Q_);
    if (llt.info() != Eigen::Success) {
      throw ParameterError(
          "ParticleFilterSIR: the linearised proposal needs Q positive definite over the "
          "weighed states (it weighs each draw by N(x; f(x), Q))");
    }
    transitionWhitening_ = llt.matrixL().solve(Matrix<N, N>::Identity(n, n));
  }

  /// Gain and proposal covariance for this step, about the particles' mean prediction `mean`.
  /// Throws NumericalError when S or Sigma is not positive definite or not finite.
  void prepare(const Model& model, const Vector<N>& mean, const Measurement<M>& z,
               const Matrix<M, M>& R, const AngleMask<M>& angles) {
    constexpr double kRelativeStep = 1e-6;
    const Index n = mean.size(), m = z.size();
    effectiveMeasurementNoise(R, z, Reff_);
    Vector<N> moved = mean;
    Vector<M> ahead(m), behind(m), column(m);
    H_.setZero();
    for (Index c = 0; c < n; ++c) {
      if (fixed_(c)) continue;
      const double step = kRelativeStep * std::max(1.0, std::abs(mean(c)));
      moved(c) = mean(c) + step;
      model.observation(moved, ahead);
      moved(c) = mean(c) - step;
      model.observation(moved, behind);
      moved(c) = mean(c);
      column = ahead - behind;
      angles.wrap(column);
      for (Index r = 0; r < m; ++r) H_(r, c) = z.available(r) ? column(r) / (2.0 * step) : 0.0;
    }
    S_.noalias() = H_ * Q_ * H_.transpose();
    S_ += Reff_;
    Eigen::LLT<Matrix<M, M>> llt(S_);
    if (llt.info() != Eigen::Success || !S_.allFinite()) {
      throw NumericalError(
          "ParticleFilterSIR: the proposal's innovation covariance is not "
          "positive definite; step rejected");
    }
    gainT_.noalias() = H_ * Q_;  // K^T = S^-1 H Q
    llt.solveInPlace(gainT_);
    // Joseph form: positive semi-definite by construction.
    Matrix<N, N> IKH = Matrix<N, N>::Identity(n, n);
    IKH.noalias() -= gainT_.transpose() * H_;
    sigma_.noalias() = IKH * Q_ * IKH.transpose();
    sigma_.noalias() += gainT_.transpose() * Reff_ * gainT_;
    sigma_ = 0.5 * (sigma_ + sigma_.transpose()).eval();
    Eigen::LLT<Matrix<N, N>> root(sigma_);
    if (root.info() != Eigen::Success || !sigma_.allFinite()) {
      throw NumericalError(
          "ParticleFilterSIR: the proposal's covariance is not positive "
          "definite; step rejected");
    }
    sigmaRoot_ = root.matrixL();
    sigmaWhitening_ = root.matrixL().solve(Matrix<N, N>::Identity(n, n));
  }

  /// Draws `sample` for a particle whose prediction is `predicted` (its fixed rows are kept) and
  /// returns log N(sample; predicted, Q) - log N(sample; mu, Sigma) up to a constant shared by
  /// the particles; `noise` holds the standard normal draws.
  double draw(const Model& model, const Vector<N>& predicted, const Measurement<M>& z,
              const AngleMask<N>& stateAngles, const AngleMask<M>& measurementAngles,
              const Vector<N>& noise, Vector<N>& sample) const {
    const Index n = predicted.size(), m = z.size();
    Vector<M> residual(m);
    model.observation(predicted, residual);
    residual = z.value - residual;
    measurementAngles.wrap(residual);
    for (Index r = 0; r < m; ++r) {
      if (!z.available(r)) residual(r) = 0.0;
    }
    Vector<N> mean = predicted;
    mean.noalias() += gainT_.transpose() * residual;
    sample = mean;
    sample.noalias() += sigmaRoot_ * noise;
    for (Index r = 0; r < n; ++r) {
      if (fixed_(r)) sample(r) = predicted(r);
    }
    Vector<N> fromPrediction = sample - predicted, fromMean = sample - mean;
    stateAngles.wrap(fromPrediction);
    stateAngles.wrap(fromMean);
    stateAngles.wrap(sample);
    const double transition = (transitionWhitening_ * fromPrediction).squaredNorm();
    const double proposal = (sigmaWhitening_ * fromMean).squaredNorm();
    return -0.5 * transition + 0.5 * proposal;
  }

 private:
  Mask<N> fixed_;
  Matrix<N, N> Q_;  // fixed rows replaced by the identity
  Matrix<N, N> transitionWhitening_;
  Matrix<M, N> H_;
  Matrix<M, M> S_;
  Matrix<M, N> gainT_;
  Matrix<N, N> sigma_, sigmaRoot_, sigmaWhitening_;
  Matrix<M, M> Reff_;
};

}  // namespace estimation
