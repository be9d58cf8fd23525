// Tests of the particle filter's linearised proposal (particle_proposal.hpp): on a linear
// Gaussian model it is the optimal proposal, whose weights do not depend on the draw (equal
// weights from equal particles, to rounding) and whose mean is the Kalman filter's within the
// Monte-Carlo error; a gyro bias that only the sum omega + b reaches keeps the Kalman filter's
// value instead of drifting with the surviving lineage; a Q that is not positive definite is
// refused.
#include <algorithm>
#include <cmath>
#include <iostream>
#include <random>

#include <gtest/gtest.h>

#include "sf_estimation/errors.hpp"
#include "sf_estimation/kalman_filter.hpp"
#include "sf_estimation/particle_filter.hpp"

// Named, not anonymous: compiled in a unity group (sf_estimation/CMakeLists.txt).
namespace particle_proposal_test {

using estimation::Index;
using estimation::KalmanFilter;
using estimation::Matrix;
using estimation::Measurement;
using estimation::ParticleFilterParameters;
using estimation::ParticleFilterSIR;
using estimation::ParticleProposal;
using estimation::Vector;

constexpr double kT = 0.02;

/// x = (theta, omega, b): a heading from a turn rate, and a gyro z = omega + b. Linear.
struct GyroHeading {
  static constexpr int StateSize = 3, MeasurementSize = 1, ControlSize = 0;
  Index stateSize() const { return 3; }
  Index measurementSize() const { return 1; }
  Index controlSize() const { return 0; }
  template <class S>
  void transition(const Eigen::Matrix<S, 3, 1>& x, const Vector<0>&,
                  Eigen::Matrix<S, 3, 1>& next) const {
    next << x(0) + kT * x(1), x(1), x(2);
  }
  template <class S>
  void observation(const Eigen::Matrix<S, 3, 1>& x, Eigen::Matrix<S, 1, 1>& z) const {
    z << x(1) + x(2);
  }
  static Matrix<3, 3> A() { return (Matrix<3, 3>() << 1, kT, 0, 0, 1, 0, 0, 0, 1).finished(); }
  static Matrix<1, 3> H() { return (Matrix<1, 3>() << 0, 1, 1).finished(); }
};

const Matrix<3, 3> kQ = Vector<3>(1e-6 * kT, 1.0 * kT, 1e-8 * kT).asDiagonal();
const Matrix<1, 1> kR = Matrix<1, 1>::Constant(1.25e-5);
const Vector<3> kX0 = Vector<3>::Zero();
const double kBiasSigma = 0.005;

ParticleFilterSIR<GyroHeading> makeFilter(ParticleProposal proposal, const Matrix<3, 3>& P0,
                                          Index particles = 1000) {
  ParticleFilterParameters params;
  params.particles = particles;
  params.seed = 7;
  params.proposal = proposal;
  return ParticleFilterSIR<GyroHeading>(GyroHeading{}, kQ, kR, kX0, P0, params);
}

TEST(LinearisedProposal, WeightsOfEqualParticlesStayEqualOnALinearModel) {
  // From equal particles, N(z; h(x_i), R) N(x_i; f(x), Q) / N(x_i; mu, Sigma) is the same for
  // every draw x_i (Bayes' rule for a linear Gaussian step): only rounding may differ.
  auto pf = makeFilter(ParticleProposal::Linearised, Matrix<3, 3>::Zero());
  auto plain = makeFilter(ParticleProposal::Transition, Matrix<3, 3>::Zero());
  Measurement<1> z(1);
  z.value << 0.3;
  pf.estimate(z);
  plain.estimate(z);
  const double spread = pf.logWeights().maxCoeff() - pf.logWeights().minCoeff();
  std::cout << "[ measured ] one step from equal particles: linearised log-weight spread " << spread
            << ", N_eff " << pf.effectiveSampleSize() << "; transition N_eff "
            << plain.effectiveSampleSize() << "\n";
  EXPECT_LT(spread, 1e-9);
  EXPECT_NEAR(pf.effectiveSampleSize(), 1000.0, 1e-6);
  EXPECT_FALSE(pf.resampledLastStep());
  // Drawn from the transition, the accurate gyro leaves a few particles with the weight.
  EXPECT_LT(plain.effectiveSampleSize(), 100.0);
}

struct Comparison {
  double worstBias = 0.0;     // max |b_pf - b_kf| over the run
  double worstHeading = 0.0;  // max |theta_pf - theta_kf|
  double minEss = 1e300;
};

/// 3000 steps (60 s) of a turn rate 0.3 sin(0.2 t) with no bias, measured by the gyro only: the
/// bias is never told apart from the turn rate, so the Kalman filter keeps b at 0.
Comparison againstKalman(ParticleProposal proposal) {
  const Matrix<3, 3> P0 = Vector<3>(0.0, 1.0, kBiasSigma * kBiasSigma).asDiagonal();
  auto pf = makeFilter(proposal, P0);
  KalmanFilter<3, 1> kf(GyroHeading::A(), Matrix<3, 0>::Zero(3, 0), GyroHeading::H(), kQ, kR, kX0,
                        P0);
  std::mt19937_64 engine(3);
  std::normal_distribution<double> normal;
  Measurement<1> z(1);
  Comparison out;
  for (int k = 0; k < 3000; ++k) {
    z.value << 0.3 * std::sin(0.2 * kT * k) + std::sqrt(kR(0, 0)) * normal(engine);
    pf.estimate(z);
    kf.estimate(z);
    out.worstBias = std::max(out.worstBias, std::abs(pf.state()(2) - kf.state()(2)));
    out.worstHeading = std::max(out.worstHeading, std::abs(pf.state()(0) - kf.state()(0)));
    out.minEss = std::min(out.minEss, pf.effectiveSampleSize());
  }
  return out;
}

TEST(LinearisedProposal, UnobservableBiasKeepsTheKalmanFiltersValue) {
  const Comparison linearised = againstKalman(ParticleProposal::Linearised);
  const Comparison transition = againstKalman(ParticleProposal::Transition);
  std::cout << "[ measured ] 60 s gyro-only heading, 1000 particles, against the KF: linearised "
               "max |b error| "
            << linearised.worstBias << " rad/s, max |heading error| " << linearised.worstHeading
            << " rad, min N_eff " << linearised.minEss << "; transition " << transition.worstBias
            << ", " << transition.worstHeading << ", " << transition.minEss << "\n";
  // Monte-Carlo error of a mean over ~1000 draws of sigma 0.005: 1.6e-4; 0.2 sigma is 6 of them.
  EXPECT_LT(linearised.worstBias, 0.2 * kBiasSigma);
  EXPECT_LT(linearised.worstHeading, 0.2 * kBiasSigma * 60.0);
  EXPECT_GT(linearised.minEss, 10.0 * transition.minEss);
  EXPECT_LT(linearised.worstHeading, 0.5 * transition.worstHeading);
  EXPECT_GT(transition.worstBias, 0.5 * kBiasSigma);
}

TEST(LinearisedProposal, RefusesAQThatIsNotPositiveDefinite) {
  ParticleFilterParameters params;
  params.proposal = ParticleProposal::Linearised;
  Matrix<3, 3> Q = kQ;
  Q(2, 2) = 0.0;
  try {
    ParticleFilterSIR<GyroHeading> pf(GyroHeading{}, Q, kR, kX0, Matrix<3, 3>::Identity(), params);
    ADD_FAILURE() << "a singular Q was accepted";
  } catch (const estimation::ParameterError& e) {
    EXPECT_NE(std::string(e.what()).find("needs Q positive definite"), std::string::npos)
        << e.what();
  }
}

}  // namespace particle_proposal_test
