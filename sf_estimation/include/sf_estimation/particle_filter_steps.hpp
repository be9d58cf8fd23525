// The parts of the SIR particle filter (particle_filter.hpp) that depend only on the sizes and
// run at construction, at reset or when a step's measurement noise differs from R: the
// Gaussian draw of the initial particles (a pivoted LDLT and a matrix product over all
// particles) and the whitening matrix of a measurement noise (a Cholesky factor and a triangular
// solve).
// They are compiled once in the library for the state sizes 1..7 and measurement sizes 1..6
// (cmake/sigma_point_steps.cpp.in), like the unscented transform. The per-particle loops of a
// step (sampling, weighing, normalisation, moments, resampling) stay in the filter's header,
// where they are compiled with the model and inlined into the step.
#pragma once

#include <Eigen/Core>

#include "sf_estimation/probability/cholesky.hpp"
#include "sf_estimation/probability/gaussian.hpp"
#include "sf_estimation/types.hpp"

namespace estimation {

template <int N>
using ParticleSet = Eigen::Matrix<double, N, Dynamic>;

/// particles <- p independent draws of N(mean, covariance), one per column, from `engine`
/// (the normals column by column); `noise` is scratch of the same size as `particles`.
template <int N>
void drawGaussianParticles(probability::RandomEngine& engine, const Vector<N>& mean,
                           const Matrix<N, N>& covariance, ParticleSet<N>& particles,
                           ParticleSet<N>& noise) {
  const Matrix<N, N> root = probability::covarianceSquareRoot(covariance);
  probability::fillStandardNormal(engine, noise);
  particles.noalias() = root * noise;
  particles.colwise() += mean;
}

/// Factors `noise` (L L^T) into `factor` (scratch) and sets `whitening` = L^-1: the
/// log-likelihood's |L^-1 r|^2 then costs multiplications only, where solving with L costs m
/// divisions per particle. Returns false, `whitening` unchanged, when `noise` is not positive
/// definite. The factor is Eigen::LLT's bit for bit (CholeskyOrder::sumFirst), so the weights
/// are what they were with Eigen::LLT, which cost 2 s of compile time per measurement size.
template <int M>
bool noiseWhitening(const Matrix<M, M>& noise, Matrix<M, M>& factor, Matrix<M, M>& whitening) {
  factor = noise;
  if (!probability::choleskyInPlace<M, probability::CholeskyOrder::sumFirst>(factor)) return false;
  const Index m = noise.rows();
  whitening = factor.template triangularView<Eigen::Lower>().solve(Matrix<M, M>::Identity(m, m));
  return true;
}

#define SF_ESTIMATION_PARTICLE_DRAW(N)                                                 \
  template void drawGaussianParticles<N>(probability::RandomEngine&, const Vector<N>&, \
                                         const Matrix<N, N>&, ParticleSet<N>&, ParticleSet<N>&);
#define SF_ESTIMATION_NOISE_WHITENING(M) \
  template bool noiseWhitening<M>(const Matrix<M, M>&, Matrix<M, M>&, Matrix<M, M>&);
#if !defined(SF_ESTIMATION_INSTANTIATING_SIGMA_POINT_STEPS) && \
    !defined(SF_ESTIMATION_IMPLICIT_INSTANCES)
extern SF_ESTIMATION_PARTICLE_DRAW(1) extern SF_ESTIMATION_PARTICLE_DRAW(2) extern SF_ESTIMATION_PARTICLE_DRAW(3) extern SF_ESTIMATION_PARTICLE_DRAW(4) extern SF_ESTIMATION_PARTICLE_DRAW(5) extern SF_ESTIMATION_PARTICLE_DRAW(6) extern SF_ESTIMATION_PARTICLE_DRAW(
    7) extern SF_ESTIMATION_NOISE_WHITENING(1) extern SF_ESTIMATION_NOISE_WHITENING(2) extern SF_ESTIMATION_NOISE_WHITENING(3) extern SF_ESTIMATION_NOISE_WHITENING(4) extern SF_ESTIMATION_NOISE_WHITENING(5) extern SF_ESTIMATION_NOISE_WHITENING(6)
#endif

}  // namespace estimation
