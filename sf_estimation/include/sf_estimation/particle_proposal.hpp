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
#include "sf_estimation/kalman_correction.hpp"  // SF_ESTIMATION_FOR_MEASUREMENT_SIZES
#include "sf_estimation/measurement.hpp"
#include "sf_estimation/measurement_noise.hpp"
#include "sf_estimation/probability/cholesky.hpp"
#include "sf_estimation/probability/gaussian.hpp"
#include "sf_estimation/types.hpp"

namespace estimation {

/// What the linearised proposal holds between its steps: Q (its fixed rows replaced by the
/// identity), the factors of a step and the step's effective R.
template <int N, int M>
struct ProposalFactors {
  Mask<N> fixed;
  Matrix<N, N> Q;
  Matrix<N, N> transitionWhitening;
  Matrix<M, N> H;
  Matrix<M, M> S;
  Matrix<M, N> gainT;
  Matrix<N, N> sigma, sigmaRoot, sigmaWhitening;
  Matrix<M, M> Reff;
};

// What the proposal computes from the sizes alone is compiled once for the sigma-point grid's
// sizes (sigma_point_steps_N.cpp), as the rest of the particle filter's size-only parts:
// instantiated with the model, these Eigen products and factorisations took a third of a
// particle filter's unit (doc/build_cost.md, "The particle filter's proposal").
// LinearisedProposal adds what needs the model: h's Jacobian and the particles' residuals.

/// The factorisations are Eigen::LLT's, bit for bit, as plain loops (probability/cholesky.hpp):
/// Eigen::LLT cost about 4 s of compile time per pair of sizes.
constexpr probability::CholeskyOrder kLltOrder = probability::CholeskyOrder::sumFirst;

/// Sizes `f` and whitens Q over the states outside `fixed`. Throws ParameterError when Q is not
/// positive definite there.
template <int N, int M>
void setUpProposal(const Matrix<N, N>& Q, const Mask<N>& fixed, Index measurements,
                   ProposalFactors<N, M>& f) {
  const Index n = Q.rows();
  f.fixed = fixed;
  f.Q = Q;
  f.H.resize(measurements, n);
  f.S.resize(measurements, measurements);
  f.gainT.resize(measurements, n);
  f.sigma.resize(n, n);
  f.sigmaWhitening.resize(n, n);
  f.Reff.resize(measurements, measurements);
  for (Index r = 0; r < n; ++r) {
    if (!f.fixed(r)) continue;
    f.Q.row(r).setZero();
    f.Q.col(r).setZero();
    f.Q(r, r) = 1.0;
  }
  Matrix<N, N> root = f.Q;
  if (!probability::choleskyInPlace<N, kLltOrder>(root)) {
    throw ParameterError(
        "ParticleFilterSIR: the linearised proposal needs Q positive definite over the "
        "weighed states (it weighs each draw by N(x; f(x), Q))");
  }
  f.transitionWhitening =
      root.template triangularView<Eigen::Lower>().solve(Matrix<N, N>::Identity(n, n));
}

/// Gain and proposal covariance of a step from f.H (zero rows for the missing entries) and
/// f.Reff. Throws NumericalError when S or Sigma is not positive definite or not finite.
template <int N, int M>
void factoriseProposal(ProposalFactors<N, M>& f) {
  const Index n = f.H.cols();
  f.S.noalias() = f.H * f.Q * f.H.transpose();
  f.S += f.Reff;
  Matrix<M, M> factor = f.S;
  if (!probability::choleskyInPlace<M, kLltOrder>(factor) || !f.S.allFinite()) {
    throw NumericalError(
        "ParticleFilterSIR: the proposal's innovation covariance is not "
        "positive definite; step rejected");
  }
  f.gainT.noalias() = f.H * f.Q;  // K^T = S^-1 H Q, as Eigen::LLT::solveInPlace solves
  factor.template triangularView<Eigen::Lower>().solveInPlace(f.gainT);
  factor.adjoint().template triangularView<Eigen::Upper>().solveInPlace(f.gainT);
  // Joseph form: positive semi-definite by construction.
  Matrix<N, N> IKH = Matrix<N, N>::Identity(n, n);
  IKH.noalias() -= f.gainT.transpose() * f.H;
  f.sigma.noalias() = IKH * f.Q * IKH.transpose();
  f.sigma.noalias() += f.gainT.transpose() * f.Reff * f.gainT;
  f.sigma = 0.5 * (f.sigma + f.sigma.transpose()).eval();
  Matrix<N, N> root = f.sigma;
  if (!probability::choleskyInPlace<N, kLltOrder>(root) || !f.sigma.allFinite()) {
    throw NumericalError(
        "ParticleFilterSIR: the proposal's covariance is not positive "
        "definite; step rejected");
  }
  f.sigmaRoot = root.template triangularView<Eigen::Lower>();
  f.sigmaWhitening =
      root.template triangularView<Eigen::Lower>().solve(Matrix<N, N>::Identity(n, n));
}

/// The draw of a particle whose prediction is `predicted` and whose residual z - h(predicted)
/// is `residual` (wrapped, zero for missing entries): LinearisedProposal::draw's.
template <int N, int M>
double drawFromProposal(const ProposalFactors<N, M>& f, const Vector<N>& predicted,
                        const Vector<M>& residual, const AngleMask<N>& stateAngles,
                        const Vector<N>& noise, Vector<N>& sample) {
  const Index n = predicted.size();
  Vector<N> mean = predicted;
  mean.noalias() += f.gainT.transpose() * residual;
  sample = mean;
  sample.noalias() += f.sigmaRoot * noise;
  for (Index r = 0; r < n; ++r) {
    if (f.fixed(r)) sample(r) = predicted(r);
  }
  Vector<N> fromPrediction = sample - predicted, fromMean = sample - mean;
  stateAngles.wrap(fromPrediction);
  stateAngles.wrap(fromMean);
  stateAngles.wrap(sample);
  const double transition = (f.transitionWhitening * fromPrediction).squaredNorm();
  const double proposal = (f.sigmaWhitening * fromMean).squaredNorm();
  return -0.5 * transition + 0.5 * proposal;
}

template <class Model>
class LinearisedProposal {
  static constexpr int N = Model::StateSize;
  static constexpr int M = Model::MeasurementSize;

 public:
  LinearisedProposal() = default;

  /// Throws ParameterError when Q is not positive definite over the states outside `fixed`.
  LinearisedProposal(const Matrix<N, N>& Q, const Mask<N>& fixed, Index measurements) {
    setUpProposal<N, M>(Q, fixed, measurements, f_);
  }

  /// Gain and proposal covariance for this step, about the particles' mean prediction `mean`.
  /// Throws NumericalError when S or Sigma is not positive definite or not finite.
  void prepare(const Model& model, const Vector<N>& mean, const Measurement<M>& z,
               const Matrix<M, M>& R, const AngleMask<M>& angles) {
    constexpr double kRelativeStep = 1e-6;
    const Index n = mean.size(), m = z.size();
    effectiveMeasurementNoise(R, z, f_.Reff);
    Vector<N> moved = mean;
    Vector<M> ahead(m), behind(m), column(m);
    f_.H.setZero();
    for (Index c = 0; c < n; ++c) {
      if (f_.fixed(c)) continue;
      const double step = kRelativeStep * std::max(1.0, std::abs(mean(c)));
      moved(c) = mean(c) + step;
      model.observation(moved, ahead);
      moved(c) = mean(c) - step;
      model.observation(moved, behind);
      moved(c) = mean(c);
      column = ahead - behind;
      angles.wrap(column);
      for (Index r = 0; r < m; ++r) f_.H(r, c) = z.available(r) ? column(r) / (2.0 * step) : 0.0;
    }
    factoriseProposal<N, M>(f_);
  }

  /// Draws `sample` for a particle whose prediction is `predicted` (its fixed rows are kept) and
  /// returns log N(sample; predicted, Q) - log N(sample; mu, Sigma) up to a constant shared by
  /// the particles; `noise` holds the standard normal draws.
  double draw(const Model& model, const Vector<N>& predicted, const Measurement<M>& z,
              const AngleMask<N>& stateAngles, const AngleMask<M>& measurementAngles,
              const Vector<N>& noise, Vector<N>& sample) const {
    Vector<M> expected(z.size());
    model.observation(predicted, expected);
    Vector<M> residual = z.value - expected;
    measurementAngles.wrap(residual);
    for (Index r = 0; r < z.size(); ++r) {
      if (!z.available(r)) residual(r) = 0.0;
    }
    return drawFromProposal<N, M>(f_, predicted, residual, stateAngles, noise, sample);
  }

 private:
  ProposalFactors<N, M> f_;
};

// The size-only steps above for the state sizes 1..7 and measurement sizes 1..6 of the
// sigma-point grid; other sizes are instantiated where they are used.
#define SF_ESTIMATION_PROPOSAL_STEP_INSTANCES(PREFIX, N, M)                                     \
  PREFIX template void setUpProposal<N, M>(const Matrix<N, N>&, const Mask<N>&, Index,          \
                                           ProposalFactors<N, M>&);                             \
  PREFIX template void factoriseProposal<N, M>(ProposalFactors<N, M>&);                         \
  PREFIX template double drawFromProposal<N, M>(const ProposalFactors<N, M>&, const Vector<N>&, \
                                                const Vector<M>&, const AngleMask<N>&,          \
                                                const Vector<N>&, Vector<N>&);
#define SF_ESTIMATION_PROPOSAL_STEP(N, M) SF_ESTIMATION_PROPOSAL_STEP_INSTANCES(, N, M)
#define SF_ESTIMATION_PROPOSAL_STEPS(N) \
  SF_ESTIMATION_FOR_MEASUREMENT_SIZES(SF_ESTIMATION_PROPOSAL_STEP, N)
#if !defined(SF_ESTIMATION_INSTANTIATING_SIGMA_POINT_STEPS) && \
    !defined(SF_ESTIMATION_IMPLICIT_INSTANCES)
#define SF_ESTIMATION_EXTERN_PROPOSAL_STEP(N, M) SF_ESTIMATION_PROPOSAL_STEP_INSTANCES(extern, N, M)
#define SF_ESTIMATION_EXTERN_PROPOSAL_STEPS(N) \
  SF_ESTIMATION_FOR_MEASUREMENT_SIZES(SF_ESTIMATION_EXTERN_PROPOSAL_STEP, N)
SF_ESTIMATION_EXTERN_PROPOSAL_STEPS(1)
SF_ESTIMATION_EXTERN_PROPOSAL_STEPS(2)
SF_ESTIMATION_EXTERN_PROPOSAL_STEPS(3)
SF_ESTIMATION_EXTERN_PROPOSAL_STEPS(4)
SF_ESTIMATION_EXTERN_PROPOSAL_STEPS(5)
SF_ESTIMATION_EXTERN_PROPOSAL_STEPS(6)
SF_ESTIMATION_EXTERN_PROPOSAL_STEPS(7)
#undef SF_ESTIMATION_EXTERN_PROPOSAL_STEPS
#undef SF_ESTIMATION_EXTERN_PROPOSAL_STEP
#endif

}  // namespace estimation
