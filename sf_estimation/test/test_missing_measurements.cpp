// Missing measurements and per-entry variances (measurement.hpp, measurement_noise.hpp,
// kalman_correction.hpp) for KF, EKF, UKF and PF. A partly missing measurement must give the
// estimate and covariance of the same filter built with only the present rows of H/h and R
// (built here from the same belief); a wholly missing one the time update alone; a per-entry
// variance the filter built with that R(i,i).
#include <cmath>
#include <limits>
#include <vector>

#include <Eigen/Cholesky>

#include <gtest/gtest.h>

#include "filter_test_utils.hpp"
#include "sf_estimation/extended_kalman_filter.hpp"
#include "sf_estimation/kalman_filter.hpp"
#include "sf_estimation/models/navigation.hpp"
#include "sf_estimation/particle_filter.hpp"
#include "sf_estimation/unscented_kalman_filter.hpp"

namespace {

using estimation::Dynamic;
using estimation::ExtendedKalmanFilter;
using estimation::Index;
using estimation::KalmanFilter;
using estimation::Matrix;
using estimation::Measurement;
using estimation::ParticleFilterParameters;
using estimation::ParticleFilterSIR;
using estimation::UnscentedKalmanFilter;
using estimation::UnscentedParameters;
using estimation::Vector;
using estimation::models::Nav3Ctrl;
using estimation::models::Nav3Reduced;
using sftest::relDiff;
using sftest::RowSubsetModel;

using DynamicKalman = KalmanFilter<Dynamic, Dynamic, Dynamic>;

constexpr double kRelative = 1e-12;

/// Every mask of 4 entries with at least one present and at least one missing.
std::vector<Measurement<4>> partialMasks(const Vector<4>& values) {
  std::vector<Measurement<4>> out;
  for (int bits = 1; bits < 15; ++bits) {
    Measurement<4> z = Measurement<4>::complete(values);
    for (int i = 0; i < 4; ++i) z.available(i) = ((bits >> i) & 1) != 0;
    out.push_back(z);
  }
  return out;
}

Vector<7> nav3State() {
  Vector<7> x;
  x << 2.0, -1.0, 0.6, 0.25, 0.04, 0.45, 0.2;
  return x;
}

Matrix<7, 7> nav3Covariance() {
  Matrix<7, 7> L = Matrix<7, 7>::Identity() * 0.3;
  L(2, 0) = 0.05;
  L(4, 2) = -0.02;
  L(5, 3) = 0.04;
  L(6, 5) = 0.1;
  L(3, 1) = 0.03;
  return L * L.transpose();
}

// ---------------------------------------------------------------------------------------------
// Kalman filter.
// ---------------------------------------------------------------------------------------------

TEST(MissingMeasurementsKalman, PartialEqualsReducedFilterOverARun) {
  const Nav3Reduced model;
  const Matrix<3, 3> A = model.transitionMatrix();
  const Matrix<3, 2> B = model.controlMatrix();
  const Matrix<4, 3> H = model.observationMatrix();
  const Matrix<3, 3> Q = estimation::models::nav3ReducedProcessNoise();
  const Matrix<4, 4> R = sftest::correlatedNav3MeasurementNoise();
  KalmanFilter<3, 4, 2> kf(A, B, H, Q, R, Vector<3>(0.1, 0.3, 0.0), Matrix<3, 3>::Identity());

  int partial = 0, none = 0;
  for (const auto& step : sftest::simulateNav3Drive(300, 41, 0.5, 9)) {
    const Vector<3> x = kf.state();
    const Matrix<3, 3> P = kf.covariance();
    kf.setControl(step.u);
    kf.estimate(step.z);
    const auto rows = sftest::presentRows(step.z);
    if (rows.empty()) {
      // Time update only, computed here.
      ++none;
      const Vector<3> expectedX = A * x + B * step.u;
      const Matrix<3, 3> expectedP = A * P * A.transpose() + Q;
      ASSERT_LE(relDiff(kf.state(), expectedX), kRelative);
      ASSERT_LE(relDiff(kf.covariance(), expectedP), kRelative);
      continue;
    }
    if (rows.size() < 4) ++partial;
    DynamicKalman reduced(A, B, sftest::selectRows(H, rows), Q, sftest::selectSquare(R, rows), x,
                          P);
    reduced.setControl(step.u);
    reduced.estimate(sftest::selectMeasurement(step.z, rows));
    ASSERT_LE(relDiff(kf.state(), reduced.state()), kRelative) << rows.size() << " rows";
    ASSERT_LE(relDiff(kf.covariance(), reduced.covariance()), kRelative);
  }
  EXPECT_GT(partial, 100);  // the run exercised the partial case
  EXPECT_GT(none, 20);      // and the wholly missing one
}

TEST(MissingMeasurementsKalman, EveryMaskEqualsReducedFilter) {
  const Nav3Reduced model;
  const Matrix<4, 4> R = sftest::correlatedNav3MeasurementNoise();
  const Matrix<3, 3> Q = estimation::models::nav3ReducedProcessNoise();
  const Vector<3> x0(0.2, 0.5, -0.1);
  Matrix<3, 3> P0;
  P0 << 0.4, 0.05, 0.0, 0.05, 0.3, -0.02, 0.0, -0.02, 0.2;
  for (const auto& z : partialMasks(Vector<4>(0.3, 0.1, 420.0, 610.0))) {
    KalmanFilter<3, 4, 2> kf(model.transitionMatrix(), model.controlMatrix(),
                             model.observationMatrix(), Q, R, x0, P0);
    kf.setControl(Vector<2>(0.5, 0.3));
    kf.estimate(z);
    const auto rows = sftest::presentRows(z);
    DynamicKalman reduced(model.transitionMatrix(), model.controlMatrix(),
                          sftest::selectRows(model.observationMatrix(), rows), Q,
                          sftest::selectSquare(R, rows), x0, P0);
    reduced.setControl(Eigen::Vector2d(0.5, 0.3));
    reduced.estimate(sftest::selectMeasurement(z, rows));
    EXPECT_LE(relDiff(kf.state(), reduced.state()), kRelative) << z.available.transpose();
    EXPECT_LE(relDiff(kf.covariance(), reduced.covariance()), kRelative);
  }
}

TEST(MissingMeasurementsKalman, MissingValuesAreIgnoredEvenWhenNotFinite) {
  // A missing entry's value (here NaN) and variance must not matter.
  const Nav3Reduced model;
  const Matrix<4, 4> R = estimation::models::nav3MeasurementNoise();
  const Matrix<3, 3> Q = estimation::models::nav3ReducedProcessNoise();
  KalmanFilter<3, 4, 2> a(model.transitionMatrix(), model.controlMatrix(),
                          model.observationMatrix(), Q, R);
  KalmanFilter<3, 4, 2> b = a;
  Measurement<4> za = Measurement<4>::complete(Vector<4>(0.3, 0.1, 420.0, 610.0));
  za.available(2) = false;
  Measurement<4> zb = za;
  zb.value(2) = std::numeric_limits<double>::quiet_NaN();
  zb.varianceGiven(2) = true;
  zb.variance(2) = -1.0;
  a.estimate(za);
  b.estimate(zb);
  EXPECT_EQ(a.state(), b.state());
  EXPECT_EQ(a.covariance(), b.covariance());
}

TEST(MissingMeasurementsKalman, GivenVarianceEqualsFilterWithThatR) {
  const Nav3Reduced model;
  const Matrix<4, 4> R = sftest::correlatedNav3MeasurementNoise();
  const Matrix<3, 3> Q = estimation::models::nav3ReducedProcessNoise();
  const Vector<3> x0(0.2, 0.5, -0.1);
  const Matrix<3, 3> P0 = Matrix<3, 3>::Identity() * 0.3;
  Measurement<4> z = Measurement<4>::complete(Vector<4>(0.3, 0.1, 420.0, 610.0));
  z.varianceGiven << false, true, false, true;
  z.variance << 99.0, 0.7, 99.0, 5.0;  // ignored where not given
  Matrix<4, 4> R2 = R;
  R2(1, 1) = 0.7;
  R2(3, 3) = 5.0;
  KalmanFilter<3, 4, 2> kf(model.transitionMatrix(), model.controlMatrix(),
                           model.observationMatrix(), Q, R, x0, P0);
  KalmanFilter<3, 4, 2> ref(model.transitionMatrix(), model.controlMatrix(),
                            model.observationMatrix(), Q, R2, x0, P0);
  for (int k = 0; k < 5; ++k) {
    kf.estimate(z);
    ref.estimate(Measurement<4>::complete(z.value));
    EXPECT_LE(relDiff(kf.state(), ref.state()), kRelative);
    EXPECT_LE(relDiff(kf.covariance(), ref.covariance()), kRelative);
  }
  // Only for that step: without the variances the configured R is used again.
  KalmanFilter<3, 4, 2> plain(model.transitionMatrix(), model.controlMatrix(),
                              model.observationMatrix(), Q, R, kf.state(), kf.covariance());
  kf.estimate(Measurement<4>::complete(z.value));
  plain.estimate(Measurement<4>::complete(z.value));
  EXPECT_EQ(kf.state(), plain.state());
  EXPECT_EQ(kf.covariance(), plain.covariance());
}

// ---------------------------------------------------------------------------------------------
// Extended Kalman filter (nonlinear transition of nav3ctrl).
// ---------------------------------------------------------------------------------------------

TEST(MissingMeasurementsExtended, PartialEqualsReducedModelFilter) {
  const Nav3Ctrl model;
  const Matrix<7, 7> Q = estimation::models::nav3ProcessNoise();
  const Matrix<4, 4> R = sftest::correlatedNav3MeasurementNoise();
  for (const auto& z : partialMasks(Vector<4>(0.28, -0.1, 380.0, 560.0))) {
    ExtendedKalmanFilter<Nav3Ctrl> ekf(model, Q, R, nav3State(), nav3Covariance());
    ekf.setControl(Vector<2>(0.5, 0.3));
    ekf.estimate(z);
    const auto rows = sftest::presentRows(z);
    ExtendedKalmanFilter<RowSubsetModel<Nav3Ctrl>> reduced(RowSubsetModel<Nav3Ctrl>{model, rows}, Q,
                                                           sftest::selectSquare(R, rows),
                                                           nav3State(), nav3Covariance());
    reduced.setControl(Vector<2>(0.5, 0.3));
    reduced.estimate(sftest::selectMeasurement(z, rows));
    EXPECT_LE(relDiff(ekf.state(), reduced.state()), kRelative) << z.available.transpose();
    EXPECT_LE(relDiff(ekf.covariance(), reduced.covariance()), kRelative);
  }
}

TEST(MissingMeasurementsExtended, WhollyMissingIsTheTimeUpdate) {
  const Nav3Ctrl model;
  const Matrix<7, 7> Q = estimation::models::nav3ProcessNoise();
  ExtendedKalmanFilter<Nav3Ctrl> ekf(model, Q, estimation::models::nav3MeasurementNoise(),
                                     nav3State(), nav3Covariance());
  const Vector<2> u(0.5, 0.3);
  ekf.setControl(u);
  Measurement<4> z = Measurement<4>::missing();
  z.value << 1e9, 1e9, 1e9, 1e9;  // must be ignored
  ekf.estimate(z);
  Vector<7> expectedX;
  model.transition(nav3State(), u, expectedX);
  const Matrix<7, 7> A = sftest::nav3CtrlTransitionJacobian(model, nav3State());
  const Matrix<7, 7> expectedP = A * nav3Covariance() * A.transpose() + Q;
  EXPECT_LE(relDiff(ekf.state(), expectedX), kRelative);
  EXPECT_LE(relDiff(ekf.covariance(), expectedP), kRelative);
}

TEST(MissingMeasurementsExtended, GivenVarianceEqualsFilterWithThatR) {
  const Nav3Ctrl model;
  const Matrix<7, 7> Q = estimation::models::nav3ProcessNoise();
  const Matrix<4, 4> R = sftest::correlatedNav3MeasurementNoise();
  Measurement<4> z = Measurement<4>::complete(Vector<4>(0.28, -0.1, 380.0, 560.0));
  z.available << true, true, false, true;
  z.varianceGiven << true, false, true, false;  // entry 2 is missing: its variance is ignored
  z.variance << 0.01, 0.0, 3.0, 0.0;
  Matrix<4, 4> R2 = R;
  R2(0, 0) = 0.01;
  ExtendedKalmanFilter<Nav3Ctrl> ekf(model, Q, R, nav3State(), nav3Covariance());
  ExtendedKalmanFilter<Nav3Ctrl> ref(model, Q, R2, nav3State(), nav3Covariance());
  Measurement<4> zRef = Measurement<4>::complete(z.value);
  zRef.available = z.available;
  ekf.estimate(z);
  ref.estimate(zRef);
  EXPECT_LE(relDiff(ekf.state(), ref.state()), kRelative);
  EXPECT_LE(relDiff(ekf.covariance(), ref.covariance()), kRelative);
}

// ---------------------------------------------------------------------------------------------
// Unscented Kalman filter.
// ---------------------------------------------------------------------------------------------

using sftest::alphaOne;

// The default alpha = 1e-3 gives mean weights W0 = 1 - 1/alpha^2 = -999999 and W_i = 1/(2
// alpha^2) = 5e5, so the predicted measurement cancels terms 2e6 times larger than itself: the
// masked (4 rows) and reduced (k rows) products, summed in different orders by Eigen, each
// carry up to 2n u 2e6 |z| = 14 * 1.1e-16 * 2e6 * 525 mm/s = 1.6e-6 mm/s of rounding in the
// wheels' prediction (|z| <= 1000 v + 300 omega = 525 mm/s here), which the largest gain
// (acceleration per wheel, ~(1/T)/2000 = 5e-3) maps to 8e-9 of state; relative to the
// state's scale 2 and for the difference of two such computations: 8e-9. With alpha = 1 the
// weights are 0 and 1/14 and the 1e-12 tolerance applies. The covariances are computed from
// centred points, which cancel the mean's rounding, and meet 1e-12 for both.
constexpr double kDefaultAlphaStateTolerance = 8e-9;

TEST(MissingMeasurementsUnscented, PartialEqualsReducedModelFilter) {
  // Same sigma points and weights in both filters, so this holds for any alpha (up to the
  // rounding discussed above).
  const Nav3Ctrl model;
  const Matrix<7, 7> Q = estimation::models::nav3ProcessNoise();
  const Matrix<4, 4> R = sftest::correlatedNav3MeasurementNoise();
  for (const UnscentedParameters& params : {UnscentedParameters{}, alphaOne()}) {
    for (const auto& z : partialMasks(Vector<4>(0.28, -0.1, 380.0, 560.0))) {
      UnscentedKalmanFilter<Nav3Ctrl> ukf(model, Q, R, nav3State(), nav3Covariance(), params);
      ukf.setControl(Vector<2>(0.5, 0.3));
      ukf.estimate(z);
      const auto rows = sftest::presentRows(z);
      UnscentedKalmanFilter<RowSubsetModel<Nav3Ctrl>> reduced(
          RowSubsetModel<Nav3Ctrl>{model, rows}, Q, sftest::selectSquare(R, rows), nav3State(),
          nav3Covariance(), params);
      reduced.setControl(Vector<2>(0.5, 0.3));
      reduced.estimate(sftest::selectMeasurement(z, rows));
      const double stateTolerance = params.alpha == 1.0 ? kRelative : kDefaultAlphaStateTolerance;
      EXPECT_LE(relDiff(ukf.state(), reduced.state()), stateTolerance)
          << "alpha " << params.alpha << ", mask " << z.available.transpose();
      EXPECT_LE(relDiff(ukf.covariance(), reduced.covariance()), kRelative)
          << "alpha " << params.alpha << ", mask " << z.available.transpose();
    }
  }
}

TEST(MissingMeasurementsUnscented, WhollyMissingIsTheTimeUpdateOfALinearModel) {
  // nav3red is linear, so the unscented time update is exactly x = A x + B u,
  // P = A P A^T + Q; alpha = 1 keeps the rounding at the level of the matrix products.
  const Nav3Reduced model;
  const Matrix<3, 3> Q = estimation::models::nav3ReducedProcessNoise();
  const Vector<3> x0(0.2, 0.5, -0.1);
  Matrix<3, 3> P0;
  P0 << 0.4, 0.05, 0.0, 0.05, 0.3, -0.02, 0.0, -0.02, 0.2;
  UnscentedKalmanFilter<Nav3Reduced> ukf(model, Q, estimation::models::nav3MeasurementNoise(), x0,
                                         P0, alphaOne());
  const Vector<2> u(0.5, 0.3);
  ukf.setControl(u);
  ukf.estimate(Measurement<4>::missing());
  const Matrix<3, 3> A = model.transitionMatrix();
  const Vector<3> expectedX = A * x0 + model.controlMatrix() * u;
  const Matrix<3, 3> expectedP = A * P0 * A.transpose() + Q;
  EXPECT_LE(relDiff(ukf.state(), expectedX), kRelative);
  EXPECT_LE(relDiff(ukf.covariance(), expectedP), kRelative);
}

TEST(MissingMeasurementsUnscented, WhollyMissingIsTheUnscentedTimeUpdate) {
  // nav3ctrl (nonlinear): the unscented prediction written out here (eqs. 3.5-3.10) with
  // alpha = 1, beta = 2, kappa = 0: lambda = 0, points x, x +- sqrt(7) L_i (P = L L^T),
  // mean weights 0 and 1/14, covariance weights 2 and 1/14.
  const Nav3Ctrl model;
  const Matrix<7, 7> Q = estimation::models::nav3ProcessNoise();
  const Vector<2> u(0.5, 0.3);
  UnscentedKalmanFilter<Nav3Ctrl> ukf(model, Q, estimation::models::nav3MeasurementNoise(),
                                      nav3State(), nav3Covariance(), alphaOne());
  ukf.setControl(u);
  ukf.estimate(Measurement<4>::missing());

  const Eigen::MatrixXd L = Eigen::LLT<Eigen::MatrixXd>(7.0 * nav3Covariance()).matrixL();
  std::vector<Vector<7>> points;
  std::vector<double> wm, wc;
  Vector<7> next;
  model.transition(nav3State(), u, next);
  points.push_back(next);
  wm.push_back(0.0);
  wc.push_back(2.0);
  for (int i = 0; i < 7; ++i) {
    for (double sign : {1.0, -1.0}) {
      model.transition(Vector<7>(nav3State() + sign * L.col(i)), u, next);
      points.push_back(next);
      wm.push_back(1.0 / 14.0);
      wc.push_back(1.0 / 14.0);
    }
  }
  Vector<7> mean = Vector<7>::Zero();
  for (std::size_t i = 0; i < points.size(); ++i) mean += wm[i] * points[i];
  Matrix<7, 7> P = Q;
  for (std::size_t i = 0; i < points.size(); ++i) {
    P += wc[i] * (points[i] - mean) * (points[i] - mean).transpose();
  }
  EXPECT_LE(relDiff(ukf.state(), mean), kRelative);
  EXPECT_LE(relDiff(ukf.covariance(), P), kRelative);
}

TEST(MissingMeasurementsUnscented, GivenVarianceEqualsFilterWithThatR) {
  const Nav3Ctrl model;
  const Matrix<7, 7> Q = estimation::models::nav3ProcessNoise();
  const Matrix<4, 4> R = sftest::correlatedNav3MeasurementNoise();
  Measurement<4> z = Measurement<4>::complete(Vector<4>(0.28, -0.1, 380.0, 560.0));
  z.varianceGiven << false, true, true, false;
  z.variance << 0.0, 2.0, 7.5, 0.0;
  Matrix<4, 4> R2 = R;
  R2(1, 1) = 2.0;
  R2(2, 2) = 7.5;
  for (const UnscentedParameters& params : {UnscentedParameters{}, alphaOne()}) {
    UnscentedKalmanFilter<Nav3Ctrl> ukf(model, Q, R, nav3State(), nav3Covariance(), params);
    UnscentedKalmanFilter<Nav3Ctrl> ref(model, Q, R2, nav3State(), nav3Covariance(), params);
    ukf.estimate(z);
    ref.estimate(Measurement<4>::complete(z.value));
    EXPECT_LE(relDiff(ukf.state(), ref.state()), kRelative);
    EXPECT_LE(relDiff(ukf.covariance(), ref.covariance()), kRelative);
  }
}

// ---------------------------------------------------------------------------------------------
// Particle filter: same seed -> the same particles and weights.
// ---------------------------------------------------------------------------------------------

ParticleFilterParameters particleParameters() {
  ParticleFilterParameters p;
  p.particles = 400;
  p.seed = 1234;
  p.resamplingThreshold = 0.5;
  return p;
}

TEST(MissingMeasurementsParticle, MaskedFullModelEqualsReducedModel) {
  // Gyro and left wheel present in every step (some steps wholly missing); the reduced
  // filter observes only those two rows.
  const Nav3Ctrl model;
  const Matrix<7, 7> Q = estimation::models::nav3ParticleProcessNoise();
  const Matrix<4, 4> R = sftest::correlatedNav3MeasurementNoise();
  const std::vector<Index> rows = {0, 2};
  ParticleFilterSIR<Nav3Ctrl> full(model, Q, R, nav3State(), nav3Covariance(),
                                   particleParameters());
  ParticleFilterSIR<RowSubsetModel<Nav3Ctrl>> reduced(RowSubsetModel<Nav3Ctrl>{model, rows}, Q,
                                                      sftest::selectSquare(R, rows), nav3State(),
                                                      nav3Covariance(), particleParameters());
  ASSERT_EQ(full.particles(), reduced.particles());  // same seed, same initial draw

  int resampled = 0;
  const auto run = sftest::simulateNav3Drive(40, 42, 0.0, 6);
  for (std::size_t k = 0; k < run.size(); ++k) {
    Measurement<4> z = run[k].z;
    const bool none = !z.anyAvailable();
    z.available << !none, false, !none, false;
    full.setControl(run[k].u);
    reduced.setControl(run[k].u);
    full.estimate(z);
    reduced.estimate(none ? Measurement<Dynamic>::missing(2) : sftest::selectMeasurement(z, rows));
    resampled += full.resampledLastStep() ? 1 : 0;
    ASSERT_EQ(full.resampledLastStep(), reduced.resampledLastStep()) << "step " << k;
    ASSERT_LE(relDiff(full.particles(), reduced.particles()), kRelative) << "step " << k;
    ASSERT_LE(sftest::maxAbsDiff(full.logWeights(), reduced.logWeights()), 1e-12) << "step " << k;
    ASSERT_LE(relDiff(full.state(), reduced.state()), kRelative);
    ASSERT_LE(relDiff(full.covariance(), reduced.covariance()), kRelative);
  }
  EXPECT_GT(resampled, 3);  // resampling (which uses the engine) happened in both
}

TEST(MissingMeasurementsParticle, WhollyMissingMovesParticlesAndKeepsWeights) {
  // With Q = 0 the time update is deterministic: particles -> f(particles), and a wholly
  // missing measurement leaves the (non-uniform) weights as they were.
  const Nav3Ctrl model;
  const Matrix<7, 7> Q = Matrix<7, 7>::Zero();
  ParticleFilterParameters params = particleParameters();
  params.resamplingThreshold = 0.0;  // keep non-uniform weights
  ParticleFilterSIR<Nav3Ctrl> pf(model, Q, estimation::models::nav3MeasurementNoise(), nav3State(),
                                 nav3Covariance(), params);
  const Vector<2> u(0.5, 0.3);
  pf.setControl(u);
  pf.estimate(Measurement<4>::complete(Vector<4>(0.28, -0.1, 380.0, 560.0)));
  const Eigen::MatrixXd before = pf.particles();
  const Eigen::VectorXd weightsBefore = pf.logWeights();
  ASSERT_GT(weightsBefore.maxCoeff() - weightsBefore.minCoeff(), 1.0);

  pf.estimate(Measurement<4>::missing());
  // Unchanged up to the renormalisation by logSumExp of already normalised weights (~1e-16).
  EXPECT_LE(sftest::maxAbsDiff(pf.logWeights(), weightsBefore), 1e-12);
  Vector<7> next;
  for (Index i = 0; i < before.cols(); ++i) {
    model.transition(Vector<7>(before.col(i)), u, next);
    ASSERT_EQ(Vector<7>(pf.particles().col(i)), next) << "particle " << i;
  }
  // The estimate is the weighted mean of the moved particles.
  const Eigen::VectorXd w = pf.logWeights().array().exp();
  EXPECT_LE(relDiff(pf.state(), (pf.particles() * w).eval()), kRelative);
}

TEST(MissingMeasurementsParticle, GivenVarianceEqualsFilterWithThatR) {
  const Nav3Ctrl model;
  const Matrix<7, 7> Q = estimation::models::nav3ParticleProcessNoise();
  const Matrix<4, 4> R = sftest::correlatedNav3MeasurementNoise();
  Matrix<4, 4> R2 = R;
  R2(0, 0) = 0.02;
  R2(3, 3) = 6.0;
  ParticleFilterSIR<Nav3Ctrl> pf(model, Q, R, nav3State(), nav3Covariance(), particleParameters());
  ParticleFilterSIR<Nav3Ctrl> ref(model, Q, R2, nav3State(), nav3Covariance(),
                                  particleParameters());
  for (const auto& step : sftest::simulateNav3Drive(20, 43, 0.0, 0)) {
    Measurement<4> z = step.z;
    z.varianceGiven << true, false, false, true;
    z.variance << 0.02, 0.0, 0.0, 6.0;
    pf.setControl(step.u);
    ref.setControl(step.u);
    pf.estimate(z);
    ref.estimate(step.z);
    ASSERT_LE(relDiff(pf.particles(), ref.particles()), kRelative);
    ASSERT_LE(sftest::maxAbsDiff(pf.logWeights(), ref.logWeights()), 1e-12);
  }
}

}  // namespace
