// SIR particle filter (thesis Algorithms 3.4 and 3.5) with Gaussian process noise and
// Gaussian likelihood, both with full covariance. Weights are kept as logarithms so that a
// very accurate sensor does not underflow every weight to zero; resampling is systematic and
// happens when the effective sample size is at or below a threshold (N_eff <= threshold * N).
// The reported state and covariance are the moments of the weighted particles before
// resampling (resampling only adds Monte-Carlo noise to them). All buffers are allocated at
// construction, none in a step.
// With shared dead reckoning (ParticleFilterParameters::sharedDeadReckoning), the states that no
// measurement weighs (dead_reckoned_states.hpp) are one Gaussian shared by all particles instead
// of a value per particle: each step every particle is moved from the shared mean, the new mean
// is the particles' weighted mean and the covariance adds, to the particles' spread, the shared
// covariance carried through f (central differences along its square root, as the divided
// difference filter does) and Q. Carried per particle, a dead-reckoned pose is the path of the
// few ancestors resampling leaves (path degeneracy); shared, it is moved by all particles.
// With ParticleProposal::Linearised the particles are drawn from each one's Kalman posterior
// instead of the transition (particle_proposal.hpp).
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>
#include <random>
#include <string>
#include <utility>

#include <Eigen/Core>

#include "sf_estimation/angles.hpp"
#include "sf_estimation/dead_reckoned_states.hpp"
#include "sf_estimation/measurement.hpp"
#include "sf_estimation/measurement_noise.hpp"
#include "sf_estimation/measurement_prediction.hpp"
#include "sf_estimation/model.hpp"
#include "sf_estimation/numerical_repairs.hpp"
#include "sf_estimation/parameter_checks.hpp"
#include "sf_estimation/particle_filter_steps.hpp"
#include "sf_estimation/particle_proposal.hpp"
#include "sf_estimation/planar_pose_mean.hpp"
#include "sf_estimation/probability/gaussian.hpp"

namespace estimation {

/// Where the particles are drawn from: the transition N(f(x), Q) (thesis Algorithm 3.4), or the
/// Kalman posterior of each particle's prediction (particle_proposal.hpp).
enum class ParticleProposal { Transition, Linearised };

struct ParticleFilterParameters {
  /// Upper limit of `particles`, so that a mistyped count is refused instead of exhausting
  /// memory (three n x particles buffers: 168 MB for n = 7).
  static constexpr Index kMaxParticles = 1000000;
  Index particles = 1000;
  std::uint64_t seed = 42;
  /// Resample when N_eff <= threshold * particles, inclusive (0 = never, as N_eff >= 1;
  /// 1 = every step, as N_eff <= particles).
  double resamplingThreshold = 0.5;
  /// A planar pose in the state (its heading an angle state) whose reported mean is the
  /// particles' mean on SE(2) (planar_pose_mean.hpp) rather than entry by entry.
  std::optional<PlanarPoseIndices> planarPose;
  /// Carry the dead-reckoned states (dead_reckoned_states.hpp) as one Gaussian shared by the
  /// particles (see the top of this file) instead of per particle.
  bool sharedDeadReckoning = false;
  ParticleProposal proposal = ParticleProposal::Transition;
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
  using Particles = ParticleSet<N>;
  static constexpr double kInfinity = std::numeric_limits<double>::infinity();

 public:
  ParticleFilterSIR(Model model, const Matrix<N, N>& Q, const Matrix<M, M>& R, const Vector<N>& x0,
                    const Matrix<N, N>& P0, const ParticleFilterParameters& params = {},
                    const AngularComponents& angles = {})
      : model_(std::move(model)),
        Q_(Q),
        R_(R),
        x0_(x0),
        P0_(P0),
        params_(params),
        sharedRoot_(Q.rows()) {
    const std::string method = "ParticleFilterSIR";
    requireFilterParameters(method, Q, R, x0, P0);
    const Index n = Q.rows();
    checkModelSizes(method, model_, n, R.rows());
    if (params.particles < 1 || params.particles > ParticleFilterParameters::kMaxParticles) {
      throw ParameterError(method + ": parameter 'particles' must be from 1 to " +
                           std::to_string(ParticleFilterParameters::kMaxParticles) + ", got " +
                           std::to_string(params.particles));
    }
    if (!(params.resamplingThreshold >= 0.0 && params.resamplingThreshold <= 1.0)) {
      throw ParameterError(method + ": parameter 'resampling-threshold' must be in [0, 1]");
    }
    angleStates_ = AngleMask<N>(angles.states, n, method, "state");
    angleMeasurements_ = AngleMask<M>(angles.measurements, R.rows(), method, "measurement");
    if (params.planarPose) {
      const PlanarPoseIndices& pose = *params.planarPose;
      requirePlanarPose(method, pose, n,
                        pose.heading >= 0 && pose.heading < n && angleStates_(pose.heading));
    }
    noiseRoot_ = probability::covarianceSquareRoot(Q);
    findNoiseSources();
    deadReckoned_ = Mask<N>::Constant(n, false);
    if (params.sharedDeadReckoning) {
      deadReckoned_ = estimation::deadReckonedStates(model_, x0, model_.controlSize());
      anyDeadReckoned_ = deadReckoned_.any();
    }
    sharedSpread_.resize(n, n);
    if (params.proposal == ParticleProposal::Linearised) {
      proposal_.emplace(Q, deadReckoned_, R.rows());
    }
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
    if (!noiseWhitening(R_, noiseFactor_, fullWhitening_)) {
      throw ParameterError(method + ": R must be positive definite");
    }
    maskedWhitening_ = fullWhitening_;
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
  /// The states carried as one shared Gaussian (none unless sharedDeadReckoning).
  const Mask<N>& deadReckonedStates() const { return deadReckoned_; }
  /// Effective sample size after the last step, before any resampling: 1 / sum w_i^2,
  /// capped at the particle count (rounding can exceed it by an ulp for equal weights).
  double effectiveSampleSize() const { return effectiveSampleSize_; }
  bool resampledLastStep() const { return resampled_; }
  const AngleMask<N>& angleStates() const { return angleStates_; }
  const AngleMask<M>& angleMeasurements() const { return angleMeasurements_; }
  /// Steps whose measurement made every particle weight vanish (numerical_repairs.hpp).
  const NumericalRepairs& numericalRepairs() const { return repairs_; }

  const Matrix<M, M>& measurementNoise() const { return R_; }

  /// The belief is a sample: a reading far outside its spread leaves a few particles with all
  /// the weight, so a belief set from a reading (the node's first readings) starts from the
  /// reading's own variance instead of keeping P (sf_filter's FusionCore).
  static constexpr bool kSampledBelief = true;

  /// Draws the particles anew from N(x, P) with equal weights (the node's set_pose and first
  /// readings; the shared dead-reckoned block takes x and P as they are). Throws
  /// ParameterError for a wrong size, a non-finite x or a P that is not a covariance
  /// (requireCovariance), leaving the filter (its engine included) as it was.
  void setBelief(const Vector<N>& x, const Matrix<N, N>& P) {
    const std::string method = "ParticleFilterSIR";
    requireSize(method, "x", x, stateSize(), 1);
    requireCovariance(method, "P", P, stateSize(), false);
    const probability::RandomEngine savedEngine = engine_;
    try {
      drawGaussianParticles(engine_, x, P, scratch_, noise_);
    } catch (...) {
      engine_ = savedEngine;
      throw;
    }
    particles_.swap(scratch_);
    angleStates_.wrap(particles_);
    logWeights_.setConstant(-std::log(static_cast<double>(particleCount())));
    weights_.setConstant(1.0 / static_cast<double>(particleCount()));
    updateMoments();
    setSharedBlock(x, P);
    effectiveSampleSize_ = static_cast<double>(particleCount());
    resampled_ = false;
  }

  void setControl(const Vector<L>& u) {
    validateControl(u, controlSize());
    u_ = u;
  }

  /// Re-seeds the engine and draws the initial particles from N(x0, P0).
  void reset() {
    engine_.seed(params_.seed);
    drawGaussianParticles(engine_, x0_, P0_, particles_, noise_);
    angleStates_.wrap(particles_);
    logWeights_.setConstant(-std::log(static_cast<double>(particleCount())));
    weights_.setConstant(1.0 / static_cast<double>(particleCount()));
    updateMoments();
    setSharedBlock(x0_, P0_);
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
    return filterDescription("ParticleFilterSIR", stateSize(), measurementSize(), controlSize(),
                             "particles", particleCount());
  }

  /// z^ and the covariance of h over the particles the next step will draw (the same random
  /// numbers, from a copy of the engine, with the current control and weights); the filter is
  /// unchanged. The moments are accumulated in one pass (West's weighted update), so no
  /// buffer of p predicted particles is needed.
  void predictMeasurement(MeasurementPrediction<M>& out) const;  // defined below, as step

  const Model& model() const { return model_; }
  Model& model() { return model_; }

 private:
  // One step (sampling, weighing, resampling), most of the filter's compile cost: defined
  // below, out of the class (not inline), so that a node compiles it in its second unit
  // (SF_ESTIMATION_PARTICLE_FILTER_STEP).
  void step(const Measurement<M>& z);

  /// sample = f(in, u) + w with w ~ N(0, Q) drawn from `engine`; `out` and `noise` are
  /// scratch. Throws NumericalError for a non-finite sample. Shared dead reckoning: `in`'s
  /// dead-reckoned states are set to their shared mean first, and they get no noise of their
  /// own (Q enters their shared covariance).
  void sampleTransition(Vector<N>& in, probability::RandomEngine& engine, Vector<N>& out,
                        Vector<N>& noise, Vector<N>& sample) const {
    const Index n = stateSize();
    if (anyDeadReckoned_) in = deadReckoned_.select(state_, in);
    model_.transition(in, u_, out);
    probability::fillStandardNormal(engine, noise);
    if (noisePerRow_) {
      for (Index r = 0; r < n; ++r) sample(r) = noiseScale_(r) * noise(noiseSource_(r));
    } else {
      sample.noalias() = noiseRoot_ * noise;
    }
    sample += out;
    if (anyDeadReckoned_) sample = deadReckoned_.select(out, sample);
    angleStates_.wrap(sample);
    if (!sample.allFinite()) {
      throw NumericalError(
          "ParticleFilterSIR: the state transition produced a non-finite "
          "particle; step rejected");
    }
  }

  /// The linearised proposal (particle_proposal.hpp): the particles' predictions and their mean
  /// first (the point of H), then each particle's draw; newLogWeights_ gains the ratio of the
  /// transition's density to the proposal's.
  void sampleFromProposal(const Measurement<M>& z) {
    const Index n = stateSize(), p = particleCount();
    Vector<N> in(n), predicted(n), noise(n), sample(n), mean = Vector<N>::Zero(n);
    for (Index i = 0; i < p; ++i) {
      in = particles_.col(i);
      if (anyDeadReckoned_) in = deadReckoned_.select(state_, in);
      model_.transition(in, u_, predicted);
      angleStates_.wrap(predicted);
      scratch_.col(i) = predicted;
      // The mean in the chart around the first prediction (angles), weighted as the particles.
      in = predicted - scratch_.col(0);
      angleStates_.wrap(in);
      mean += weights_(i) * in;
    }
    mean += scratch_.col(0);
    angleStates_.wrap(mean);
    proposal_->prepare(model_, mean, z, R_, angleMeasurements_);
    for (Index i = 0; i < p; ++i) {
      probability::fillStandardNormal(engine_, noise);
      predicted = scratch_.col(i);
      const double ratio =
          proposal_->draw(model_, predicted, z, angleStates_, angleMeasurements_, noise, sample);
      if (!sample.allFinite()) {
        throw NumericalError(
            "ParticleFilterSIR: the proposal produced a non-finite particle; step rejected");
      }
      scratch_.col(i) = sample;
      newLogWeights_(i) += ratio;
    }
  }

  void weigh(const Measurement<M>& z) {
    const Index m = measurementSize(), p = particleCount();
    const Matrix<M, M>* whitening = &fullWhitening_;
    if (z.availableCount() != m || z.varianceGiven.any() || z.covarianceGiven.any()) {
      effectiveMeasurementNoise(R_, z, reducedR_);
      if (!noiseWhitening(reducedR_, noiseFactor_, maskedWhitening_)) {
        throw NumericalError("ParticleFilterSIR: measurement noise is not positive definite");
      }
      whitening = &maskedWhitening_;
    }
    const bool complete = z.availableCount() == m;
    Vector<N> in(stateSize());
    Vector<M> expected(m), residual(m), whitened(m);
    for (Index i = 0; i < p; ++i) {
      in = scratch_.col(i);  // the freshly sampled particles, not yet committed
      model_.observation(in, expected);
      residual = z.value - expected;
      angleMeasurements_.wrap(residual);
      for (Index j = 0; !complete && j < m; ++j) {
        if (!z.available(j)) residual(j) = 0.0;
      }
      whitened.noalias() = *whitening * residual;
      const double squaredDistance = whitened.squaredNorm();
      // A likelihood that is not a number (h gave NaN or inf for this particle) is zero.
      newLogWeights_(i) =
          std::isnan(squaredDistance) ? -kInfinity : newLogWeights_(i) - 0.5 * squaredDistance;
    }
  }

  /// A diagonal Q (the usual case) has a root with at most one nonzero per row: a diagonal
  /// permuted by the pivoting of the LDLT. Then entry r of the process noise is the single
  /// product noiseScale_(r) * w(noiseSource_(r)), the same value the full row of the matrix
  /// product gives (its other terms are zero), at a seventh of the cost for n = 7.
  void findNoiseSources() {
    const Index n = noiseRoot_.rows();
    noiseSource_.setZero(n);
    noiseScale_.setZero(n);
    noisePerRow_ = true;
    for (Index r = 0; r < n; ++r) {
      Index nonzeros = 0;
      for (Index c = 0; c < n; ++c) {
        if (noiseRoot_(r, c) == 0.0) continue;
        ++nonzeros;
        noiseSource_(r) = c;
        noiseScale_(r) = noiseRoot_(r, c);
      }
      if (nonzeros > 1) noisePerRow_ = false;
    }
  }

  /// The shared dead-reckoned block starts as given, not as the sample of it.
  void setSharedBlock(const Vector<N>& x, const Matrix<N, N>& P) {
    if (!anyDeadReckoned_) return;
    for (Index r = 0; r < stateSize(); ++r) {
      if (!deadReckoned_(r)) continue;
      state_(r) = x(r);
      covariance_.row(r) = P.row(r);
      covariance_.col(r) = P.col(r);
    }
    angleStates_.wrap(state_);
  }

  /// sharedSpread_ = D S S^T D^T + Q on the dead-reckoned block (zero elsewhere): the shared
  /// covariance P = S S^T carried through f by central differences along the columns of S about
  /// the mean, D s = (f(x + h s) - f(x - h s)) / 2h with h = sqrt(3) (exact for a linear f);
  /// the particles' spread, added after the step, is the rest. Throws NumericalError for a
  /// non-finite result, before anything is changed.
  void propagateSharedCovariance() {
    constexpr double h = 1.7320508075688772;
    const Index n = stateSize();
    sharedSpread_.setZero();
    for (Index r = 0; r < n; ++r) {
      for (Index c = 0; c < n; ++c) {
        if (deadReckoned_(r) && deadReckoned_(c)) sharedSpread_(r, c) = covariance_(r, c);
      }
    }
    sharedRoot_.compute(sharedSpread_);
    const Matrix<N, N>& S = sharedRoot_.matrix();
    Vector<N> ahead(n), behind(n), forward(n), backward(n), difference(n);
    sharedSpread_.setZero();
    for (Index c = 0; c < n; ++c) {
      if (S.col(c).isZero(0.0)) continue;
      ahead = state_ + h * S.col(c);
      behind = state_ - h * S.col(c);
      model_.transition(ahead, u_, forward);
      model_.transition(behind, u_, backward);
      difference = forward - backward;
      angleStates_.wrap(difference);
      difference = deadReckoned_.select(difference / (2.0 * h), Vector<N>::Zero(n));
      sharedSpread_.noalias() += difference * difference.transpose();
    }
    for (Index r = 0; r < n; ++r) {
      for (Index c = 0; c < n; ++c) {
        if (deadReckoned_(r) && deadReckoned_(c)) sharedSpread_(r, c) += Q_(r, c);
      }
    }
    if (!sharedSpread_.allFinite()) {
      throw NumericalError(
          "ParticleFilterSIR: the shared dead-reckoned covariance is not finite; step rejected");
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
    weights_.setConstant(step);
  }

  /// Normalises newLogWeights_ (log-sum-exp) and sets weights_ to the normalised weights, one
  /// exp per particle serving both: w_i = e_i / sum_j e_j with e_i = exp(l_i - max_j l_j).
  /// An e_i below e^-700 is taken as zero: it cannot change the sum, which contains e^0 = 1,
  /// and computing it would give a denormal number, on which x86 arithmetic is many times
  /// slower (with an accurate sensor most particles are there).
  void normaliseWeights() {
    constexpr double kLogFloor = -700.0;
    const double largest = newLogWeights_.maxCoeff();
    if (!std::isfinite(largest) || newLogWeights_.hasNaN()) {
      // Not reachable: step() restores the previous (normalised) weights first.
      throw NumericalError("ParticleFilterSIR: all particle weights vanished; step rejected");
    }
    double sum = 0.0;
    for (Index i = 0; i < newLogWeights_.size(); ++i) {
      const double relative = newLogWeights_(i) - largest;
      weights_(i) = relative < kLogFloor ? 0.0 : std::exp(relative);
      sum += weights_(i);
    }
    newLogWeights_.array() -= largest + std::log(sum);
    weights_ /= sum;
  }

  /// Weighted mean and covariance of the particles; weights_ must be up to date. Both are sums
  /// over the particles, one at a time: Eigen evaluates the mean's n x p times p product as n
  /// strided dot products, and the covariance as one n x p x n product would need the
  /// deviations scaled and stored first, both slower at these sizes.
  /// Angle states: the circular mean atan2(sum w sin, sum w cos) of the particles, and
  /// deviations from it wrapped to (-pi, pi]. A planar pose: the SE(2) mean, from that
  /// start; the covariance is then the mean square deviation from it.
  void updateMoments();  // defined below, as step

  /// Calls f(i, w) for each run of equal adjacent particles, with i its first particle and w
  /// their summed weight, skipping zero weights. Resampling copies a particle to adjacent
  /// places, and after resampling with an accurate sensor most particles are such copies.
  template <class F>
  void forEachDistinctParticle(F&& f) const {
    const Index p = particles_.cols();
    for (Index i = 0; i < p;) {
      double weight = weights_(i);
      Index next = i + 1;
      while (next < p && particles_.col(next) == particles_.col(i)) weight += weights_(next++);
      if (weight != 0.0) f(i, weight);
      i = next;
    }
  }

  Model model_;
  Matrix<N, N> Q_;
  Matrix<M, M> R_;
  Vector<N> x0_;
  Matrix<N, N> P0_;
  ParticleFilterParameters params_;
  Matrix<N, N> noiseRoot_;
  bool noisePerRow_ = false;  // see findNoiseSources()
  Eigen::Matrix<Index, N, 1> noiseSource_;
  Vector<N> noiseScale_;
  Matrix<M, M> noiseFactor_;                      // scratch of noiseWhitening()
  Matrix<M, M> fullWhitening_, maskedWhitening_;  // L^-1 of R and of this step's noise
  Matrix<M, M> reducedR_;
  Vector<L> u_;
  probability::RandomEngine engine_;
  Particles particles_, scratch_, noise_;
  Eigen::VectorXd logWeights_, newLogWeights_, weights_;
  Vector<N> state_;
  Matrix<N, N> covariance_;
  double effectiveSampleSize_ = 0.0;
  bool resampled_ = false;
  AngleMask<N> angleStates_;
  AngleMask<M> angleMeasurements_;
  NumericalRepairs repairs_;
  Mask<N> deadReckoned_;  // carried as one shared Gaussian (sharedDeadReckoning)
  bool anyDeadReckoned_ = false;
  probability::CovarianceSquareRoot<N> sharedRoot_;
  Matrix<N, N> sharedSpread_;  // what the shared block adds to the particles' spread in a step
  std::optional<LinearisedProposal<Model>> proposal_;  // ParticleProposal::Linearised
};

template <class Model>
void ParticleFilterSIR<Model>::updateMoments() {
  state_.setZero();
  forEachDistinctParticle([&](Index i, double w) { state_ += w * particles_.col(i); });
  if (angleStates_.any()) {
    for (Index r = 0; r < stateSize(); ++r) {
      if (!angleStates_(r)) continue;
      double s = 0.0, c = 0.0;
      forEachDistinctParticle([&](Index i, double w) {
        s += w * std::sin(particles_(r, i));
        c += w * std::cos(particles_(r, i));
      });
      state_(r) = std::atan2(s, c);
    }
  }
  if (params_.planarPose) {
    planarPoseMean(
        *params_.planarPose,
        [&](auto&& f) {
          forEachDistinctParticle([&](Index i, double w) { f(particles_.col(i), w); });
        },
        state_);
  }
  Vector<N> deviation(stateSize()), weighted(stateSize());
  covariance_.setZero();
  forEachDistinctParticle([&](Index i, double w) {
    deviation = particles_.col(i) - state_;
    angleStates_.wrap(deviation);
    weighted = w * deviation;
    covariance_.noalias() += weighted * deviation.transpose();
  });
  symmetrize(covariance_);
}

template <class Model>
void ParticleFilterSIR<Model>::predictMeasurement(MeasurementPrediction<M>& out) const {
  const Index n = stateSize(), m = measurementSize(), p = particleCount();
  probability::RandomEngine engine = engine_;
  Vector<N> in(n), transitioned(n), noise(n), sample(n);
  Vector<M> expected(m), deviation(m), after(m);
  // Sized here: a caller's prediction of dynamic size may come in empty (or of another
  // size); for a fixed M, m is M.
  out.mean.setZero(m);
  out.covariance.setZero(m, m);
  double weightSum = 0.0;
  for (Index i = 0; i < p; ++i) {
    in = particles_.col(i);
    sampleTransition(in, engine, transitioned, noise, sample);
    const double w = weights_(i);
    if (w == 0.0) continue;
    model_.observation(sample, expected);
    weightSum += w;
    // For an angle the running mean moves by the wrapped deviation: the mean on the
    // circle in the chart around the running mean.
    deviation = expected - out.mean;
    angleMeasurements_.wrap(deviation);
    out.mean += (w / weightSum) * deviation;
    angleMeasurements_.wrap(out.mean);
    after = expected - out.mean;
    angleMeasurements_.wrap(after);
    out.covariance.noalias() += w * deviation * after.transpose();
  }
  out.covariance /= weightSum;
  symmetrize(out.covariance);
  out.noise = R_;
  out.angular = angleMeasurements_.mask();
}

template <class Model>
void ParticleFilterSIR<Model>::step(const Measurement<M>& z) {
  const Index n = stateSize(), p = particleCount();
  // Sample: x_i' = f(x_i, u) + w_i, w_i ~ N(0, Q). One particle at a time, so that its
  // values stay in registers; the normals are drawn in the same order as when filling a
  // whole n x p matrix column by column.
  if (anyDeadReckoned_) propagateSharedCovariance();
  newLogWeights_ = logWeights_;
  if (proposal_ && z.anyAvailable()) {
    sampleFromProposal(z);
  } else {
    Vector<N> in(n), out(n), noise(n), sample(n);
    for (Index i = 0; i < p; ++i) {
      in = particles_.col(i);
      sampleTransition(in, engine_, out, noise, sample);
      scratch_.col(i) = sample;
    }
  }
  // Weight: log w_i += log N(z; h(x_i), R) over the present entries.
  if (z.anyAvailable()) weigh(z);
  // Every weight vanished (the likelihood is zero or not a number for every particle): the
  // measurement is dropped, the weights stay those before it.
  const bool weightsVanished = !(newLogWeights_.maxCoeff() > -kInfinity);
  if (weightsVanished) newLogWeights_ = logWeights_;
  normaliseWeights();

  particles_.swap(scratch_);
  logWeights_.swap(newLogWeights_);
  effectiveSampleSize_ = std::min(1.0 / weights_.squaredNorm(), static_cast<double>(p));
  // The moments of the weighted particles, before resampling replaces them by copies.
  updateMoments();
  if (anyDeadReckoned_) covariance_ += sharedSpread_;
  resampled_ = effectiveSampleSize_ <= params_.resamplingThreshold * static_cast<double>(p);
  if (resampled_) resample();
  if (weightsVanished) ++repairs_.weights;
}

}  // namespace estimation

// The step of FILTER (a ParticleFilterSIR), declared extern (PREFIX extern) in a node's unit
// and instantiated (PREFIX empty) in its second unit, like the smoothers (doc/build_cost.md,
// "The 3D headers' Jacobians and the particle filter's step").
#define SF_ESTIMATION_PARTICLE_FILTER_STEP(PREFIX, FILTER)                                       \
  PREFIX template void FILTER::step(const estimation::Measurement<FILTER::M>&);                  \
  PREFIX template void FILTER::predictMeasurement(estimation::MeasurementPrediction<FILTER::M>&) \
      const;                                                                                     \
  PREFIX template void FILTER::updateMoments();
