// Tests of the Jacobians (jacobian.hpp, function_model.hpp): automatic differentiation of the
// templated model code must give the hand-derived Jacobians of nav3ctrl (eqs. 5.8-5.18), the
// run-time-sized FunctionModel must give the same, and a model's own Jacobian must be used
// instead of automatic differentiation.
#include <cmath>
#include <random>

#include <gtest/gtest.h>
#include <Eigen/LU>

#include "filter_test_utils.hpp"
#include "sf_estimation/errors.hpp"
#include "sf_estimation/extended_kalman_filter.hpp"
#include "sf_estimation/function_model.hpp"
#include "sf_estimation/jacobian.hpp"
#include "sf_estimation/models/navigation.hpp"

namespace {

using estimation::FunctionModel;
using estimation::Index;
using estimation::Matrix;
using estimation::Measurement;
using estimation::Vector;
using estimation::models::Nav3Ctrl;
using estimation::models::Nav3Reduced;
using sftest::maxAbsDiff;

/// A random nav3ctrl state: position in [-50, 50] m, any heading (several turns), omega in
/// [-1.2, 1.2] rad/s, delta_s in [-0.2, 0.2] m, v in [-1.5, 1.5] m/s, a in [-3, 3] m/s^2.
Vector<7> randomState(std::mt19937_64& rng) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  Vector<7> x;
  x << 50 * u(rng), 50 * u(rng), 20 * u(rng), 1.2 * u(rng), 0.2 * u(rng), 1.5 * u(rng), 3 * u(rng);
  return x;
}

TEST(JacobianNav3Ctrl, AutomaticTransitionJacobianEqualsAnalytic) {
  std::mt19937_64 rng(31);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (const double T : {0.1, 0.05, 1.0}) {
    Nav3Ctrl model;
    model.T = T;
    for (int k = 0; k < 25; ++k) {
      const Vector<7> x = randomState(rng);
      const Vector<2> control(u(rng), 0.7 * u(rng));
      Matrix<7, 7> A;
      estimation::transitionJacobian(model, x, control, A);
      const Matrix<7, 7> expected = sftest::nav3CtrlTransitionJacobian(model, x);
      ASSERT_LE(maxAbsDiff(A, expected), 1e-12)
          << "T = " << T << ", x = " << x.transpose() << "\nA =\n"
          << A << "\nexpected =\n"
          << expected;
      // omega' = u1 does not depend on the state at all.
      EXPECT_EQ(A.row(3), (Matrix<1, 7>::Zero()));
      EXPECT_EQ(A(6, 5), -1.0 / T);
    }
  }
}

TEST(JacobianNav3Ctrl, AutomaticObservationJacobianEqualsAnalytic) {
  std::mt19937_64 rng(32);
  for (const double radius : {0.3, 0.25}) {
    Nav3Ctrl model;
    model.radius = radius;
    for (int k = 0; k < 25; ++k) {
      const Vector<7> x = randomState(rng);
      Matrix<4, 7> H;
      estimation::observationJacobian(model, x, H);
      ASSERT_LE(maxAbsDiff(H, sftest::nav3CtrlObservationJacobian(model)), 1e-12)
          << "radius " << radius << "\n"
          << H;
    }
  }
  // The rows written out: gyro, accelerometer, left and right wheel (R = 0.3).
  Matrix<4, 7> H;
  estimation::observationJacobian(Nav3Ctrl{}, Vector<7>::Constant(0.4), H);
  Matrix<4, 7> rows;
  rows << 0, 0, 0, 1, 0, 0, 0,    //
      0, 0, 0, 0, 0, 0, 1,        //
      0, 0, 0, -300, 0, 1000, 0,  //
      0, 0, 0, 300, 0, 1000, 0;
  EXPECT_LE(maxAbsDiff(H, rows), 1e-12);
}

TEST(JacobianNav3Reduced, AutomaticJacobiansEqualTheModelMatrices) {
  const Nav3Reduced model;
  const Vector<3> x(0.3, -0.8, 1.7);
  Matrix<3, 3> A;
  Matrix<4, 3> H;
  estimation::transitionJacobian(model, x, Vector<2>(0.5, 0.2), A);
  estimation::observationJacobian(model, x, H);
  // A = [0 0 0; 0 1 T; 0 -1/T 0], H = [1 0 0; 0 0 1; -1000R 1000 0; 1000R 1000 0]
  Matrix<3, 3> expectedA;
  expectedA << 0, 0, 0, 0, 1, 0.1, 0, -10, 0;
  Matrix<4, 3> expectedH;
  expectedH << 1, 0, 0, 0, 0, 1, -300, 1000, 0, 300, 1000, 0;
  EXPECT_LE(maxAbsDiff(A, expectedA), 1e-12);
  EXPECT_LE(maxAbsDiff(H, expectedH), 1e-12);
  EXPECT_LE(maxAbsDiff(model.transitionMatrix(), expectedA), 1e-12);
  EXPECT_LE(maxAbsDiff(model.observationMatrix(), expectedH), 1e-12);
}

// ---------------------------------------------------------------------------------------------
// Run-time-sized models (FunctionModel).
// ---------------------------------------------------------------------------------------------

/// nav3ctrl written as generic lambdas (the form the factory takes).
FunctionModel nav3CtrlFunctionModel(double T, double radius) {
  return estimation::makeFunctionModel(
      7, 4, 2,
      [T](const auto& x, const auto& u, auto& next) {
        using std::cos;
        using std::sin;
        next(0) = x(0) + x(4) * cos(x(2));
        next(1) = x(1) + x(4) * sin(x(2));
        next(2) = x(2) + x(3) * T;
        next(3) = u(1);
        next(4) = x(5) * T;
        next(5) = x(5) + x(6) * T;
        next(6) = (u(0) - x(5)) / T;
      },
      [radius](const auto& x, auto& z) {
        z(0) = x(3);
        z(1) = x(6);
        z(2) = (x(5) - x(3) * radius) * 1000.0;
        z(3) = (x(5) + x(3) * radius) * 1000.0;
      });
}

TEST(JacobianFunctionModel, GenericLambdasGiveTheAnalyticJacobians) {
  const FunctionModel model = nav3CtrlFunctionModel(0.1, 0.3);
  ASSERT_TRUE(model.hasJacobians());
  EXPECT_EQ(model.stateSize(), 7);
  EXPECT_EQ(model.measurementSize(), 4);
  EXPECT_EQ(model.controlSize(), 2);
  const Nav3Ctrl reference;
  std::mt19937_64 rng(33);
  for (int k = 0; k < 25; ++k) {
    const Eigen::VectorXd x = randomState(rng);
    const Eigen::VectorXd u = Eigen::Vector2d(0.4, -0.2);
    Eigen::MatrixXd A, H;
    model.transitionJacobian(x, u, A);
    model.observationJacobian(x, H);
    ASSERT_EQ(A.rows(), 7);
    ASSERT_EQ(A.cols(), 7);
    ASSERT_EQ(H.rows(), 4);
    ASSERT_EQ(H.cols(), 7);
    EXPECT_LE(maxAbsDiff(A, sftest::nav3CtrlTransitionJacobian(reference, x)), 1e-12);
    EXPECT_LE(maxAbsDiff(H, sftest::nav3CtrlObservationJacobian(reference)), 1e-12);

    // The generic entry points dispatch to the model's (type-erased) Jacobians.
    Eigen::MatrixXd A2, H2;
    estimation::transitionJacobian(model, x, u, A2);
    estimation::observationJacobian(model, x, H2);
    EXPECT_EQ(A2, A);
    EXPECT_EQ(H2, H);

    // Values: same as the fixed-size model.
    Eigen::VectorXd next, z;
    model.transition(x, u, next);
    model.observation(x, z);
    Vector<7> nextRef;
    Vector<4> zRef;
    reference.transition(Vector<7>(x), Vector<2>(u), nextRef);
    reference.observation(Vector<7>(x), zRef);
    EXPECT_LE(maxAbsDiff(next, nextRef), 1e-12);
    EXPECT_LE(maxAbsDiff(z, zRef), 1e-12);
  }
}

TEST(JacobianFunctionModel, GivenJacobiansAreUsedAndMissingOnesRefused) {
  // Without Jacobians: refused with ParameterError.
  FunctionModel plain(
      2, 1, 0, [](const Eigen::VectorXd& x, const Eigen::VectorXd&, Eigen::VectorXd& n) { n = x; },
      [](const Eigen::VectorXd& x, Eigen::VectorXd& z) { z(0) = x(0); });
  EXPECT_FALSE(plain.hasJacobians());
  Eigen::MatrixXd A, H;
  EXPECT_THROW(plain.transitionJacobian(Eigen::Vector2d::Zero(), Eigen::VectorXd(0), A),
               estimation::ParameterError);
  EXPECT_THROW(plain.observationJacobian(Eigen::Vector2d::Zero(), H), estimation::ParameterError);

  // With given Jacobians: exactly those are returned.
  plain.setJacobians(
      [](const Eigen::VectorXd&, const Eigen::VectorXd&, Eigen::MatrixXd& a) { a << 1, 2, 3, 4; },
      [](const Eigen::VectorXd&, Eigen::MatrixXd& h) { h << 5, 6; });
  ASSERT_TRUE(plain.hasJacobians());
  plain.transitionJacobian(Eigen::Vector2d::Zero(), Eigen::VectorXd(0), A);
  plain.observationJacobian(Eigen::Vector2d::Zero(), H);
  EXPECT_EQ(A, (Eigen::Matrix2d() << 1, 2, 3, 4).finished());
  EXPECT_EQ(H, (Eigen::RowVector2d() << 5, 6).finished());
}

// ---------------------------------------------------------------------------------------------
// A model's own Jacobian takes precedence over automatic differentiation.
// ---------------------------------------------------------------------------------------------

/// f(x) = x, h(x) = x, but with deliberately different own Jacobians (2 I and 3 I): only a
/// filter that uses the model's Jacobians sees them.
struct OwnJacobianModel {
  static constexpr int StateSize = 2;
  static constexpr int MeasurementSize = 2;
  static constexpr int ControlSize = 0;
  Index stateSize() const { return 2; }
  Index measurementSize() const { return 2; }
  Index controlSize() const { return 0; }
  template <class S>
  void transition(const Eigen::Matrix<S, 2, 1>& x, const Vector<0>&,
                  Eigen::Matrix<S, 2, 1>& next) const {
    next = x;
  }
  template <class S>
  void observation(const Eigen::Matrix<S, 2, 1>& x, Eigen::Matrix<S, 2, 1>& z) const {
    z = x;
  }
  void transitionJacobian(const Vector<2>&, const Vector<0>&, Matrix<2, 2>& A) const {
    A = 2.0 * Matrix<2, 2>::Identity();
  }
  void observationJacobian(const Vector<2>&, Matrix<2, 2>& H) const {
    H = 3.0 * Matrix<2, 2>::Identity();
  }
};

/// Same, with only its own transition Jacobian: the observation one is differentiated.
struct OwnTransitionJacobianModel {
  static constexpr int StateSize = 2;
  static constexpr int MeasurementSize = 2;
  static constexpr int ControlSize = 0;
  Index stateSize() const { return 2; }
  Index measurementSize() const { return 2; }
  Index controlSize() const { return 0; }
  template <class S>
  void transition(const Eigen::Matrix<S, 2, 1>& x, const Vector<0>&,
                  Eigen::Matrix<S, 2, 1>& next) const {
    next = x;
  }
  template <class S>
  void observation(const Eigen::Matrix<S, 2, 1>& x, Eigen::Matrix<S, 2, 1>& z) const {
    z(0) = x(0) * x(1);  // H = [x1 x0; 0 2 x1]
    z(1) = x(1) * x(1);
  }
  void transitionJacobian(const Vector<2>&, const Vector<0>&, Matrix<2, 2>& A) const {
    A = 2.0 * Matrix<2, 2>::Identity();
  }
};

TEST(JacobianOwnModel, DetectionTraits) {
  using estimation::detail::HasObservationJacobian;
  using estimation::detail::HasTransitionJacobian;
  EXPECT_TRUE(HasTransitionJacobian<OwnJacobianModel>::value);
  EXPECT_TRUE(HasObservationJacobian<OwnJacobianModel>::value);
  EXPECT_TRUE(HasTransitionJacobian<OwnTransitionJacobianModel>::value);
  EXPECT_FALSE(HasObservationJacobian<OwnTransitionJacobianModel>::value);
  EXPECT_FALSE(HasTransitionJacobian<Nav3Ctrl>::value);
  EXPECT_FALSE(HasObservationJacobian<Nav3Ctrl>::value);
  EXPECT_TRUE(HasTransitionJacobian<FunctionModel>::value);
  EXPECT_TRUE(HasObservationJacobian<FunctionModel>::value);
}

TEST(JacobianOwnModel, OwnJacobiansAreReturnedAndUsedByTheEkf) {
  const OwnJacobianModel model;
  Matrix<2, 2> A, H;
  estimation::transitionJacobian(model, Vector<2>(1.0, 2.0), Vector<0>(), A);
  estimation::observationJacobian(model, Vector<2>(1.0, 2.0), H);
  EXPECT_EQ(A, (2.0 * Matrix<2, 2>::Identity()).eval());  // autodiff would give I
  EXPECT_EQ(H, (3.0 * Matrix<2, 2>::Identity()).eval());

  Matrix<2, 2> P0;
  P0 << 1.0, 0.2, 0.2, 0.5;
  const Matrix<2, 2> Q = 0.1 * Matrix<2, 2>::Identity();
  const Matrix<2, 2> R = 0.3 * Matrix<2, 2>::Identity();
  const Vector<2> x0(1.0, -1.0);

  // Time update only: P = A P0 A^T + Q = 4 P0 + Q (with the Jacobian I it would be P0 + Q);
  // the state follows f, not the Jacobian: x = x0.
  estimation::ExtendedKalmanFilter<OwnJacobianModel> ekf(model, Q, R, x0, P0);
  ekf.estimate(Measurement<2>::missing());
  EXPECT_EQ(ekf.state(), x0);
  EXPECT_LE(maxAbsDiff(ekf.covariance(), (4.0 * P0 + Q).eval()), 1e-14);

  // Update with H = 3 I: K = P- 3 (9 P- + R)^-1, x = x- + K (z - h(x-)) = x- + K (z - x-),
  // P = (I - 3 K) P-.
  estimation::ExtendedKalmanFilter<OwnJacobianModel> ekf2(model, Q, R, x0, P0);
  const Vector<2> z(2.0, 0.5);
  ekf2.estimate(Measurement<2>::complete(z));
  const Matrix<2, 2> Pp = 4.0 * P0 + Q;
  const Matrix<2, 2> K = 3.0 * Pp * (9.0 * Pp + R).inverse();
  const Vector<2> expectedX = x0 + K * (z - x0);
  const Matrix<2, 2> expectedP = (Matrix<2, 2>::Identity() - 3.0 * K) * Pp;
  EXPECT_LE(maxAbsDiff(ekf2.state(), expectedX), 1e-14);
  EXPECT_LE(maxAbsDiff(ekf2.covariance(), expectedP), 1e-14);
}

TEST(JacobianOwnModel, OnlyTheProvidedJacobianReplacesAutomaticDifferentiation) {
  const OwnTransitionJacobianModel model;
  const Vector<2> x(1.5, -0.5);
  Matrix<2, 2> A, H;
  estimation::transitionJacobian(model, x, Vector<0>(), A);
  estimation::observationJacobian(model, x, H);
  EXPECT_EQ(A, (2.0 * Matrix<2, 2>::Identity()).eval());
  Matrix<2, 2> expectedH;
  expectedH << -0.5, 1.5, 0.0, -1.0;  // [x1 x0; 0 2 x1]
  EXPECT_LE(maxAbsDiff(H, expectedH), 1e-15);
}

}  // namespace
