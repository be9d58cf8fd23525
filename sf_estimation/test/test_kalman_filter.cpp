// Tests of KalmanFilter (thesis Algorithm 3.1) against hand computations, the analytic and
// numerical solutions of the discrete algebraic Riccati equation, and a textbook reference
// implementation written here in plain Eigen.
#include <algorithm>
#include <cmath>
#include <random>

#include <gtest/gtest.h>
#include <Eigen/LU>

#include "filter_test_utils.hpp"

#include "sf_estimation/errors.hpp"
#include "sf_estimation/kalman_filter.hpp"
#include "sf_estimation/measurement.hpp"
#include "sf_estimation/models/moving_train.hpp"

namespace {

using estimation::InvalidInputError;
using estimation::KalmanFilter;
using estimation::Matrix;
using estimation::Measurement;
using estimation::Vector;

using sftest::maxAbsDiff;
using sftest::scaleOf;

// ---------------------------------------------------------------------------------------------
// Moving train (section 2.2.1), one step by hand.
// ---------------------------------------------------------------------------------------------

TEST(KalmanFilterTrain, OneStepMatchesHandComputation) {
  // Moving train, T = 0.1:  A = [1 0.1; 0 1], H = I (v and a measured directly), no control.
  // Chosen so that the numbers stay small:
  //   x0 = (1, 2), P0 = I, Q = diag(0.99, 1), R = I, z = (1.5, 1.0).
  //
  // Time update:
  //   x- = A x0 = (1 + 0.1 * 2, 2) = (1.2, 2)
  //   A P0 A^T = [1 + 0.01, 0.1; 0.1, 1] = [1.01 0.1; 0.1 1]
  //   P- = A P0 A^T + Q = [2 0.1; 0.1 2]
  // Measurement update (H = I):
  //   S = P- + R = [3 0.1; 0.1 3],  det S = 9 - 0.01 = 8.99
  //   S^-1 = [3 -0.1; -0.1 3] / 8.99
  //   K = P- S^-1 = [2*3 - 0.1*0.1, -2*0.1 + 0.1*3; 0.1*3 - 2*0.1, -0.1*0.1 + 2*3] / 8.99
  //     = [5.99 0.1; 0.1 5.99] / 8.99
  //   y = z - x- = (0.3, -1.0)
  //   K y = (5.99*0.3 - 0.1*1.0, 0.1*0.3 - 5.99*1.0) / 8.99 = (1.697, -5.96) / 8.99
  //   x = x- + K y = (1.2 + 1.697/8.99, 2 - 5.96/8.99) = (1.38876529477..., 1.33704115684...)
  //   P = (I - K) P- ; with H = I and R = I, I - K = R S^-1 = S^-1, so
  //   P = S^-1 P- = [3*2 - 0.1*0.1, 3*0.1 - 0.1*2; -0.1*2 + 3*0.1, -0.1*0.1 + 3*2] / 8.99
  //     = [5.99 0.1; 0.1 5.99] / 8.99   (= K, as expected for R = I)
  const estimation::models::MovingTrain train;
  Matrix<2, 2> Q = Matrix<2, 2>::Zero();
  Q.diagonal() << 0.99, 1.0;
  const Vector<2> x0(1.0, 2.0);
  KalmanFilter<2, 2> kf(train.transitionMatrix(), train.controlMatrix(), train.observationMatrix(),
                        Q, Matrix<2, 2>::Identity(), x0, Matrix<2, 2>::Identity());

  kf.estimate(Measurement<2>::complete(Vector<2>(1.5, 1.0)));

  const Vector<2> expectedX(1.2 + 1.697 / 8.99, 2.0 - 5.96 / 8.99);
  Matrix<2, 2> expectedP;
  expectedP << 5.99 / 8.99, 0.1 / 8.99, 0.1 / 8.99, 5.99 / 8.99;
  EXPECT_NEAR(kf.state()(0), 1.388765294771969, 1e-12);
  EXPECT_NEAR(kf.state()(1), 1.337041156840934, 1e-12);
  EXPECT_LE(maxAbsDiff(kf.state(), expectedX), 1e-12);
  EXPECT_LE(maxAbsDiff(kf.covariance(), expectedP), 1e-12);
}

TEST(KalmanFilterTrain, SecondStepWithOnlyVelocityMeasured) {
  // Continues the hand computation above with the acceleration sensor missing (z = (v) only):
  //   x1 = (1.2 + 1.697/8.99, 2 - 5.96/8.99), P1 = [5.99 0.1; 0.1 5.99]/8.99
  //   x- = (x1_0 + 0.1 x1_1, x1_1)
  //   P- = A P1 A^T + Q with A P1 A^T = [p + 0.2 c + 0.01 p, c + 0.1 p; c + 0.1 p, p],
  //        p = 5.99/8.99, c = 0.1/8.99
  //   H = [1 0]: s = P-_00 + 1, K = (P-_00, P-_10) / s, x = x- + K (z_v - x-_0),
  //   P = P- - K K^T s.
  const estimation::models::MovingTrain train;
  Matrix<2, 2> Q = Matrix<2, 2>::Zero();
  Q.diagonal() << 0.99, 1.0;
  KalmanFilter<2, 2> kf(train.transitionMatrix(), train.controlMatrix(), train.observationMatrix(),
                        Q, Matrix<2, 2>::Identity(), Vector<2>(1.0, 2.0), Matrix<2, 2>::Identity());
  kf.estimate(Measurement<2>::complete(Vector<2>(1.5, 1.0)));

  Measurement<2> z(2);
  z.value << 1.4, 1234.0;  // the acceleration value must be ignored
  z.available << true, false;
  kf.estimate(z);

  const double p = 5.99 / 8.99, c = 0.1 / 8.99;
  const double x10 = 1.2 + 1.697 / 8.99, x11 = 2.0 - 5.96 / 8.99;
  const double xp0 = x10 + 0.1 * x11, xp1 = x11;
  const double P00 = p + 0.2 * c + 0.01 * p + 0.99, P01 = c + 0.1 * p, P11 = p + 1.0;
  const double s = P00 + 1.0;
  const double k0 = P00 / s, k1 = P01 / s;
  const double y = 1.4 - xp0;
  EXPECT_NEAR(kf.state()(0), xp0 + k0 * y, 1e-12);
  EXPECT_NEAR(kf.state()(1), xp1 + k1 * y, 1e-12);
  EXPECT_NEAR(kf.covariance()(0, 0), P00 - k0 * k0 * s, 1e-12);
  EXPECT_NEAR(kf.covariance()(0, 1), P01 - k0 * k1 * s, 1e-12);
  EXPECT_NEAR(kf.covariance()(1, 0), P01 - k0 * k1 * s, 1e-12);
  EXPECT_NEAR(kf.covariance()(1, 1), P11 - k1 * k1 * s, 1e-12);
}

// ---------------------------------------------------------------------------------------------
// Steady state = solution of the discrete algebraic Riccati equation.
// ---------------------------------------------------------------------------------------------

TEST(KalmanFilterRiccati, RandomWalkSteadyStateMatchesClosedForm) {
  // x' = x + w, z = x + v, Q = q, R = r. The steady-state prior variance P satisfies
  //   P = (P - P^2 / (P + r)) + q   ->   P^2 / (P + r) = q   ->   P^2 - q P - q r = 0
  //   ->   P = (q + sqrt(q^2 + 4 q r)) / 2,
  // with gain K = P / (P + r) and posterior variance P r / (P + r).
  // q = 0.5, r = 2: P = (0.5 + sqrt(4.25)) / 2 = 1.2807764064044151, K = 0.3903882032022075.
  const double q = 0.5, r = 2.0;
  const double Pprior = (q + std::sqrt(q * q + 4.0 * q * r)) / 2.0;
  const double gain = Pprior / (Pprior + r);
  const double Ppost = Pprior * r / (Pprior + r);
  ASSERT_NEAR(Pprior, 1.2807764064044151, 1e-15);

  KalmanFilter<1, 1> kf(Matrix<1, 1>::Constant(1.0), Matrix<1, 0>(), Matrix<1, 1>::Constant(1.0),
                        Matrix<1, 1>::Constant(q), Matrix<1, 1>::Constant(r), Vector<1>::Zero(),
                        Matrix<1, 1>::Constant(10.0));
  // The variance contracts by about (1 - K)^2 = 0.37 per step: 200 steps reach the fixed point.
  for (int k = 0; k < 200; ++k) kf.estimate(Measurement<1>::complete(Vector<1>::Zero()));
  EXPECT_NEAR(kf.covariance()(0, 0), Ppost, 1e-14);
  EXPECT_EQ(kf.state()(0), 0.0);

  // Gain: with x = 0 and z = 1 the new estimate is K * 1.
  kf.estimate(Measurement<1>::complete(Vector<1>::Constant(1.0)));
  EXPECT_NEAR(kf.state()(0), gain, 1e-14);
  EXPECT_NEAR(kf.state()(0), 0.3903882032022075, 1e-14);
}

/// Solves the filtering DARE  P = A P A^T - A P H^T (H P H^T + R)^-1 H P A^T + Q  with the
/// structured doubling algorithm (Chu, Fan, Lin 2005), applied to the dual control DARE
/// (A -> A^T, B -> H^T): A0 = A^T, G0 = H^T R^-1 H, H0 = Q,
///   W = (I + G H)^-1, A' = A W A, G' = G + A W G A^T, H' = H + A^T H W A;  H_k -> P.
/// This is a different algorithm from the filter's recursion (quadratic convergence, no gain).
Eigen::Matrix2d solveFilterDare(const Eigen::Matrix2d& A, const Eigen::RowVector2d& H,
                                const Eigen::Matrix2d& Q, double R) {
  Eigen::Matrix2d Ak = A.transpose();
  Eigen::Matrix2d Gk = H.transpose() * H / R;
  Eigen::Matrix2d Hk = Q;
  for (int k = 0; k < 60; ++k) {
    const Eigen::Matrix2d W = (Eigen::Matrix2d::Identity() + Gk * Hk).inverse();
    const Eigen::Matrix2d An = Ak * W * Ak;
    const Eigen::Matrix2d Gn = Gk + Ak * W * Gk * Ak.transpose();
    const Eigen::Matrix2d Hn = Hk + Ak.transpose() * Hk * W * Ak;
    Ak = An;
    Gk = Gn;
    Hk = Hn;
  }
  return Hk;
}

TEST(KalmanFilterRiccati, ConstantVelocitySteadyStateMatchesDareSolution) {
  // Constant velocity: state (position, velocity), T = 0.1, position measured with R = 0.25,
  // white-noise acceleration q = 2: Q = q [T^3/3 T^2/2; T^2/2 T].
  const double T = 0.1, q = 2.0, r = 0.25;
  Eigen::Matrix2d A;
  A << 1, T, 0, 1;
  const Eigen::RowVector2d H(1.0, 0.0);
  Eigen::Matrix2d Q;
  Q << T * T * T / 3.0, T * T / 2.0, T * T / 2.0, T;
  Q *= q;

  const Eigen::Matrix2d Pdare = solveFilterDare(A, H, Q, r);
  // The reference solves the equation it claims to solve.
  const double s = H * Pdare * H.transpose() + r;
  const Eigen::Matrix2d residual = A * Pdare * A.transpose() -
                                   A * Pdare * H.transpose() * (H * Pdare * A.transpose()) / s + Q -
                                   Pdare;
  ASSERT_LE(residual.cwiseAbs().maxCoeff(), 1e-14 * scaleOf(Pdare));
  const Eigen::Vector2d Kdare = Pdare * H.transpose() / s;
  const Eigen::Matrix2d PpostDare = Pdare - Kdare * s * Kdare.transpose();

  KalmanFilter<2, 1> kf(A, Matrix<2, 0>(), H, Q, Matrix<1, 1>::Constant(r), Vector<2>::Zero(),
                        Matrix<2, 2>::Identity() * 5.0);
  for (int k = 0; k < 3000; ++k) kf.estimate(Measurement<1>::complete(Vector<1>::Zero()));

  const Eigen::Matrix2d Pprior = A * kf.covariance() * A.transpose() + Q;
  EXPECT_LE(maxAbsDiff(Pprior, Pdare), 1e-12 * scaleOf(Pdare)) << Pprior << "\n" << Pdare;
  EXPECT_LE(maxAbsDiff(kf.covariance(), PpostDare), 1e-12 * scaleOf(PpostDare));

  // Gain: the state is exactly 0 (all measurements were 0), so z = 1 moves it to K.
  ASSERT_EQ(kf.state(), Vector<2>::Zero());
  kf.estimate(Measurement<1>::complete(Vector<1>::Constant(1.0)));
  EXPECT_LE(maxAbsDiff(kf.state(), Kdare), 1e-12 * scaleOf(Kdare)) << kf.state().transpose();
}

// ---------------------------------------------------------------------------------------------
// Controls.
// ---------------------------------------------------------------------------------------------

/// Textbook Algorithm 3.1 (explicit inverse, P = (I - K H) P-), for comparison.
struct ReferenceKalman {
  Eigen::MatrixXd A, B, H, Q, R;
  Eigen::VectorXd x;
  Eigen::MatrixXd P;

  void step(const Eigen::VectorXd& u, const Eigen::VectorXd& z) {
    x = A * x + B * u;
    P = A * P * A.transpose() + Q;
    const Eigen::MatrixXd K = P * H.transpose() * (H * P * H.transpose() + R).inverse();
    x = x + K * (z - H * x);
    const Eigen::MatrixXd I = Eigen::MatrixXd::Identity(x.size(), x.size());
    P = (I - K * H) * P;
  }
};

struct AccelerationInputModel {
  // state (position, velocity), control acceleration: x' = A x + B u, both entries measured.
  static constexpr double T = 0.1;
  Matrix<2, 2> A = (Matrix<2, 2>() << 1, T, 0, 1).finished();
  Matrix<2, 1> B = (Matrix<2, 1>() << T * T / 2.0, T).finished();
  Matrix<2, 2> H = Matrix<2, 2>::Identity();
  Matrix<2, 2> Q = (Matrix<2, 2>() << 0.01, 0.002, 0.002, 0.05).finished();
  Matrix<2, 2> R = (Matrix<2, 2>() << 0.3, 0.05, 0.05, 0.2).finished();
};

TEST(KalmanFilterControl, PredictionWithControlIsAxPlusBu) {
  const AccelerationInputModel m;
  const Vector<2> x0(3.0, -1.0);
  Matrix<2, 2> P0;
  P0 << 2.0, 0.3, 0.3, 1.0;
  KalmanFilter<2, 2, 1> kf(m.A, m.B, m.H, m.Q, m.R, x0, P0);
  kf.setControl(Vector<1>::Constant(4.0));
  kf.estimate(Measurement<2>::missing());
  // x' = (3 + 0.1 * (-1) + 0.005 * 4, -1 + 0.1 * 4) = (2.92, -0.6)
  EXPECT_NEAR(kf.state()(0), 2.92, 1e-14);
  EXPECT_NEAR(kf.state()(1), -0.6, 1e-14);
  const Matrix<2, 2> expectedP = m.A * P0 * m.A.transpose() + m.Q;
  EXPECT_LE(maxAbsDiff(kf.covariance(), expectedP), 1e-14);

  // The control is kept for the following steps until it is set again.
  kf.estimate(Measurement<2>::missing());
  EXPECT_NEAR(kf.state()(0), 2.92 + 0.1 * -0.6 + 0.005 * 4.0, 1e-14);
  EXPECT_NEAR(kf.state()(1), -0.6 + 0.4, 1e-14);
  EXPECT_EQ(kf.control()(0), 4.0);
}

TEST(KalmanFilterControl, ManyStepsEqualTextbookReference) {
  const AccelerationInputModel m;
  ReferenceKalman ref{
      m.A, m.B, m.H, m.Q, m.R, Eigen::Vector2d(0.5, 0.1), Eigen::Matrix2d::Identity()};
  KalmanFilter<2, 2, 1> kf(m.A, m.B, m.H, m.Q, m.R, ref.x, ref.P);
  // Same algorithm with run-time sizes.
  KalmanFilter<estimation::Dynamic, estimation::Dynamic, estimation::Dynamic> dyn(
      ref.A, ref.B, ref.H, ref.Q, ref.R, ref.x, ref.P);

  std::mt19937_64 rng(7);
  std::normal_distribution<double> normal(0.0, 1.0);
  Eigen::VectorXd u = Eigen::VectorXd::Zero(1);
  double maxStateDiff = 0.0, maxCovDiff = 0.0;
  for (int k = 0; k < 100; ++k) {
    if (k % 3 == 0) {  // controls change only every third step; the last one is kept
      u(0) = 2.0 * normal(rng);
      kf.setControl(u);
      dyn.setControl(u);
    }
    const Eigen::Vector2d z(0.5 + 0.1 * k + normal(rng), normal(rng));
    ref.step(u, z);
    kf.estimate(Measurement<2>::complete(z));
    Measurement<estimation::Dynamic> zd = Measurement<estimation::Dynamic>::complete(z);
    dyn.estimate(zd);
    maxStateDiff = std::max(maxStateDiff, maxAbsDiff(kf.state(), ref.x) / scaleOf(ref.x));
    maxCovDiff = std::max(maxCovDiff, maxAbsDiff(kf.covariance(), ref.P) / scaleOf(ref.P));
    ASSERT_LE(maxAbsDiff(dyn.state(), kf.state()), 1e-12 * scaleOf(ref.x)) << "step " << k;
    ASSERT_LE(maxAbsDiff(dyn.covariance(), kf.covariance()), 1e-12 * scaleOf(ref.P));
  }
  EXPECT_LE(maxStateDiff, 1e-12);
  EXPECT_LE(maxCovDiff, 1e-12);
}

TEST(KalmanFilterControl, NoControlsWithZeroColumnB) {
  // The moving train has no control: B is 2x0, fixed-size and run-time-size.
  const estimation::models::MovingTrain train;
  const Matrix<2, 2> Q = Matrix<2, 2>::Identity() * 0.01;
  const Matrix<2, 2> R = Matrix<2, 2>::Identity() * 0.1;
  KalmanFilter<2, 2> fixed(train.transitionMatrix(), Matrix<2, 0>(), train.observationMatrix(), Q,
                           R);
  KalmanFilter<estimation::Dynamic, estimation::Dynamic, estimation::Dynamic> dyn(
      Eigen::MatrixXd(train.transitionMatrix()), Eigen::MatrixXd(2, 0),
      Eigen::MatrixXd(train.observationMatrix()), Eigen::MatrixXd(Q), Eigen::MatrixXd(R));
  EXPECT_EQ(fixed.controlSize(), 0);
  EXPECT_EQ(dyn.controlSize(), 0);
  EXPECT_EQ(dyn.controlMatrix().cols(), 0);
  dyn.setControl(Eigen::VectorXd(0));  // an empty control is accepted
  EXPECT_THROW(dyn.setControl(Eigen::VectorXd::Zero(1)), InvalidInputError);

  // Starting from x = 0, P = I the filter equals the textbook reference with B u = 0.
  ReferenceKalman ref{Eigen::MatrixXd(train.transitionMatrix()),
                      Eigen::MatrixXd(2, 0),
                      Eigen::MatrixXd(train.observationMatrix()),
                      Eigen::MatrixXd(Q),
                      Eigen::MatrixXd(R),
                      Eigen::VectorXd::Zero(2),
                      Eigen::MatrixXd::Identity(2, 2)};
  for (int k = 0; k < 20; ++k) {
    const Eigen::Vector2d z(0.2 * k, 2.0 + 0.1 * (k % 4));
    ref.step(Eigen::VectorXd(0), z);
    fixed.estimate(Measurement<2>::complete(z));
    dyn.estimate(Measurement<estimation::Dynamic>::complete(z));
  }
  EXPECT_LE(maxAbsDiff(fixed.state(), ref.x), 1e-12 * scaleOf(ref.x));
  EXPECT_LE(maxAbsDiff(fixed.covariance(), ref.P), 1e-12 * scaleOf(ref.P));
  EXPECT_LE(maxAbsDiff(dyn.state(), ref.x), 1e-12 * scaleOf(ref.x));
  EXPECT_LE(maxAbsDiff(dyn.covariance(), ref.P), 1e-12 * scaleOf(ref.P));
}

TEST(KalmanFilterControl, ResetRestoresInitialBeliefButKeepsControl) {
  const AccelerationInputModel m;
  const Vector<2> x0(1.0, 2.0);
  KalmanFilter<2, 2, 1> kf(m.A, m.B, m.H, m.Q, m.R, x0, Matrix<2, 2>::Identity());
  kf.setControl(Vector<1>::Constant(1.5));
  kf.estimate(Measurement<2>::complete(Vector<2>(4.0, 4.0)));
  ASSERT_NE(kf.state(), x0);
  kf.reset();
  EXPECT_EQ(kf.state(), x0);
  EXPECT_EQ(kf.covariance(), (Matrix<2, 2>::Identity()));
  EXPECT_EQ(kf.control()(0), 1.5);
}

}  // namespace
