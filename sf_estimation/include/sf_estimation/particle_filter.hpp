// SIR particle filter (thesis Algorithms 3.4 and 3.5) with Gaussian process noise and
// Gaussian likelihood, both with full covariance. Weights are kept as logarithms so that a
// very accurate sensor does not underflow every weight to zero; resampling is systematic and
// happens when the effective sample size falls below a threshold. All buffers are allocated
// at construction, none in a step.
#pragma once

#include <cmath>
#include <cstdint>
#include <random>
#include <string>
#include <utility>

#include <Eigen/Cholesky>

#include "sf_estimation/measurement.hpp"
#include "sf_estimation/measurement_noise.hpp"
#include "sf_estimation/model.hpp"
#include "sf_estimation/parameter_checks.hpp"
#include "sf_estimation/probability/gaussian.hpp"

namespace estimation {

struct ParticleFilterParameters {
  Index particles = 1000;
  std::uint64_t seed = 42;
  /// Resample when N_eff < threshold * particles (0 = never, 1 = every step).
  double resamplingThreshold = 0.5;
};

template <class Model>
class ParticleFilterSIR {
 public:
  static constexpr int StateSize = Model::StateSize;
  static constexpr int MeasurementSize = Model::MeasurementSize;
  static constexpr int ControlSize = Model::ControlSize;

 private:
  static constexpr int N = StateSize;
  static constexpr int M = MeasurementSize;
  static constexpr int L = ControlSize;
  using Particles = Eigen::Matrix<double, N, Dynamic>;

 public:
  ParticleFilterSIR(Model model, const Matrix<N, N>& Q, const Matrix<M, M>& R, const Vector<N>& x0,
                    const Matrix<N, N>& P0, const ParticleFilterParameters& params = {})
      : model_(std::move(model)), Q_(Q), R_(R), x0_(x0), P0_(P0), params_(params) {
    const std::string method = "ParticleFilterSIR";
    const Index n = Q.rows();
    requireCovariance(method, "Q", Q, n, false);
    requireCovariance(method, "R", R, R.rows(), true);
    requireSize(method, "x0", x0, n, 1);
    requireCovariance(method, "P0", P0, n, false);
    checkModelSizes(method, model_, n, R.rows());
    if (params.particles < 1) {
      throw ParameterError(method + ": parameter 'particles' must be at least 1, got " +
                           std::to_string(params.particles));
    }
    if (!(params.resamplingThreshold >= 0.0 && params.resamplingThreshold <= 1.0)) {
      throw ParameterError(method + ": parameter 'resampling-threshold' must be in [0, 1]");
    }
    noiseRoot_ = probability::covarianceSquareRoot(Q);
    const Index m = R.rows(), p = params.particles;
    u_ = Vector<L>::Zero(model_.controlSize());
    particles_.resize(n, p);
    scratch_.resize(n, p);
    noise_.resize(n, p);
    logWeights_.resize(p);
    newLogWeights_.resize(p);
    weights_.resize(p);
    state_.resize(n);
    covariance_.resize(n, n);
    fullNoise_.compute(R);
    maskedNoise_ = fullNoise_;
    reducedR_.resize(m, m);
    reset();
  }

  Index stateSize() const { return Q_.rows(); }
  Index measurementSize() const { return R_.rows(); }
  Index controlSize() const { return u_.size(); }
  Index particleCount() const { return particles_.cols(); }

  const Vector<N>& state() const { return state_; }
  const Matrix<N, N>& covariance() const { return covariance_; }
  const Vector<L>& control() const { return u_; }
  const Particles& particles() const { return particles_; }
  const Eigen::VectorXd& logWeights() const { return logWeights_; }
  /// Effective sample size after the last step, before any resampling.
  double effectiveSampleSize() const { return effectiveSampleSize_; }
  bool resampledLastStep() const { return resampled_; }

  void setControl(const Vector<L>& u) {
    validateControl(u, controlSize());
    u_ = u;
  }

  /// Re-seeds the engine and draws the initial particles from N(x0, P0).
  void reset() {
    engine_.seed(params_.seed);
    const Matrix<N, N> root = probability::covarianceSquareRoot(P0_);
    probability::fillStandardNormal(engine_, noise_);
    particles_.noalias() = root * noise_;
    particles_.colwise() += x0_;
    logWeights_.setConstant(-std::log(static_cast<double>(particleCount())));
    updateWeights();
    updateMoments();
    effectiveSampleSize_ = static_cast<double>(particleCount());
    resampled_ = false;
  }

  void estimate(const Measurement<M>& z) {
    z.validate(measurementSize());
    const probability::RandomEngine savedEngine = engine_;
    try {
      step(z);
    } catch (...) {
      engine_ = savedEngine;  // a rejected step must not change the filter, its engine included
      throw;
    }
  }

  std::string description() const {
    return "ParticleFilterSIR(n=" + std::to_string(stateSize()) + ", m=" +
           std::to_string(measurementSize()) + ", l=" + std::to_string(controlSize()) +
           ", particles=" + std::to_string(particleCount()) + ")";
  }

  const Model& model() const { return model_; }
  Model& model() { return model_; }

 private:
  void step(const Measurement<M>& z) {
    const Index n = stateSize(), p = particleCount();
    // Sample: x_i' = f(x_i, u) + w_i, w_i ~ N(0, Q). One particle at a time, so that its
    // values stay in registers; the normals are drawn in the same order as when filling a
    // whole n x p matrix column by column.
    Vector<N> in(n), out(n), noise(n);
    for (Index i = 0; i < p; ++i) {
      in = particles_.col(i);
      model_.transition(in, u_, out);
      probability::fillStandardNormal(engine_, noise);
      scratch_.col(i).noalias() = noiseRoot_ * noise;
      scratch_.col(i) += out;
      if (!scratch_.col(i).allFinite()) {
        throw NumericalError("ParticleFilterSIR: the state transition produced a non-finite "
                             "particle; step rejected");
      }
    }
    // Weight: log w_i += log N(z; h(x_i), R) over the present entries.
    newLogWeights_ = logWeights_;
    if (z.anyAvailable()) weigh(z);
    const double total = probability::logSumExp(newLogWeights_);
    if (!std::isfinite(total)) {
      throw NumericalError("ParticleFilterSIR: all particle weights vanished; step rejected");
    }
    newLogWeights_.array() -= total;

    particles_.swap(scratch_);
    logWeights_.swap(newLogWeights_);
    updateWeights();
    effectiveSampleSize_ = 1.0 / weights_.squaredNorm();
    resampled_ = effectiveSampleSize_ < params_.resamplingThreshold * static_cast<double>(p);
    if (resampled_) resample();
    updateMoments();
  }

  void weigh(const Measurement<M>& z) {
    const Index m = measurementSize(), p = particleCount();
    const Eigen::LLT<Matrix<M, M>>* noise = &fullNoise_;
    if (z.availableCount() != m || z.varianceGiven.any()) {
      effectiveMeasurementNoise(R_, z, reducedR_);
      maskedNoise_.compute(reducedR_);
      if (maskedNoise_.info() != Eigen::Success) {
        throw NumericalError("ParticleFilterSIR: measurement noise is not positive definite");
      }
      noise = &maskedNoise_;
    }
    const bool complete = z.availableCount() == m;
    Vector<N> in(stateSize());
    Vector<M> expected(m), residual(m);
    for (Index i = 0; i < p; ++i) {
      in = scratch_.col(i);  // the freshly sampled particles, not yet committed
      model_.observation(in, expected);
      residual = z.value - expected;
      for (Index j = 0; !complete && j < m; ++j) {
        if (!z.available(j)) residual(j) = 0.0;
      }
      noise->matrixL().solveInPlace(residual);
      newLogWeights_(i) -= 0.5 * residual.squaredNorm();
    }
  }

  /// Systematic resampling (thesis Algorithm 3.5): one uniform draw, N equidistant pointers.
  void resample() {
    const Index p = particleCount();
    const double step = 1.0 / static_cast<double>(p);
    std::uniform_real_distribution<double> uniform(0.0, step);
    double pointer = uniform(engine_);
    double cumulative = weights_(0);
    Index i = 0;
    for (Index j = 0; j < p; ++j) {
      while (pointer > cumulative && i + 1 < p) cumulative += weights_(++i);
      scratch_.col(j) = particles_.col(i);
      pointer += step;
    }
    particles_.swap(scratch_);
    logWeights_.setConstant(-std::log(static_cast<double>(p)));
    updateWeights();
  }

  /// weights_ = exp(logWeights_), except that weights below e^-700 are exactly zero. Such a
  /// weight cannot change any sum the filter forms (the largest weight is at least 1/p), and
  /// computing it would yield a denormal number (Eigen's exp returns about 5.6e-309 for any
  /// argument below -709), on which x86 arithmetic is many times slower: with an accurate
  /// sensor most particles are in that range.
  void updateWeights() {
    constexpr double kLogFloor = -700.0;
    weights_ = logWeights_.array().max(kLogFloor).exp();
    for (Index i = 0; i < weights_.size(); ++i) {
      if (logWeights_(i) < kLogFloor) weights_(i) = 0.0;
    }
  }

  /// Weighted mean and covariance of the particles; weights_ must be up to date.
  void updateMoments() {
    state_.noalias() = particles_ * weights_;
    // sum_i w_i d_i d_i^T, one small outer product per particle: cheaper than one n x p x n
    // matrix product, which needs the deviations scaled and stored first.
    Vector<N> deviation(stateSize()), weighted(stateSize());
    covariance_.setZero();
    for (Index i = 0; i < particles_.cols(); ++i) {
      deviation = particles_.col(i) - state_;
      weighted = weights_(i) * deviation;
      covariance_.noalias() += weighted * deviation.transpose();
    }
    symmetrize(covariance_);
  }

  Model model_;
  Matrix<N, N> Q_;
  Matrix<M, M> R_;
  Vector<N> x0_;
  Matrix<N, N> P0_;
  ParticleFilterParameters params_;
  Matrix<N, N> noiseRoot_;
  Eigen::LLT<Matrix<M, M>> fullNoise_, maskedNoise_;
  Matrix<M, M> reducedR_;
  Vector<L> u_;
  probability::RandomEngine engine_;
  Particles particles_, scratch_, noise_;
  Eigen::VectorXd logWeights_, newLogWeights_, weights_;
  Vector<N> state_;
  Matrix<N, N> covariance_;
  double effectiveSampleSize_ = 0.0;
  bool resampled_ = false;
};

}  // namespace estimation
