// Tests of ExtendedKalmanFilter (thesis Algorithm 3.2): on linear models it must be the
// Kalman filter (Jacobians = the model matrices), and on a nonlinear observation one step is
// checked against a hand computation (Jacobian evaluated at the predicted state).
#include <algorithm>
#include <cmath>
#include <iostream>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "filter_test_utils.hpp"
#include "sf_estimation/extended_kalman_filter.hpp"
#include "sf_estimation/kalman_filter.hpp"
#include "sf_estimation/models/moving_train.hpp"
#include "sf_estimation/models/navigation.hpp"

namespace {

using estimation::ExtendedKalmanFilter;
using estimation::KalmanFilter;
using estimation::Matrix;
using estimation::Measurement;
using estimation::Vector;
using estimation::models::MovingTrain;
using estimation::models::Nav3Reduced;
using sftest::relDiff;

/// Runs KF and EKF over the same inputs; returns the largest relative differences of state
/// and covariance over all steps.
template <class Model, int N = Model::StateSize, int M = Model::MeasurementSize,
          int L = Model::ControlSize>
std::pair<double, double> compareWithKalman(const Model& model, const Matrix<N, N>& A,
                                            const Matrix<N, L>& B, const Matrix<M, N>& H,
                                            const Matrix<N, N>& Q, const Matrix<M, M>& R,
                                            const Vector<N>& x0, const Matrix<N, N>& P0,
                                            const std::vector<sftest::Step<M, L>>& run) {
  KalmanFilter<N, M, L> kf(A, B, H, Q, R, x0, P0);
  ExtendedKalmanFilter<Model> ekf(model, Q, R, x0, P0);
  double stateDiff = 0.0, covDiff = 0.0;
  for (const auto& step : run) {
    kf.setControl(step.u);
    ekf.setControl(step.u);
    kf.estimate(step.z);
    ekf.estimate(step.z);
    stateDiff = std::max(stateDiff, relDiff(ekf.state(), kf.state()));
    covDiff = std::max(covDiff, relDiff(ekf.covariance(), kf.covariance()));
  }
  return {stateDiff, covDiff};
}

TEST(ExtendedKalmanFilterLinear, MovingTrainEqualsKalmanFilter) {
  const MovingTrain train;
  Matrix<2, 2> Q;
  Q << 0.02, 0.001, 0.001, 0.05;
  Matrix<2, 2> R;
  R << 0.4, 0.02, 0.02, 0.1;
  const Vector<2> x0(1.0, 0.5);
  const Matrix<2, 2> P0 = Matrix<2, 2>::Identity();
  const auto run =
      sftest::simulateLinear<2, 2, 0>(train.transitionMatrix(), train.controlMatrix(),
                                      train.observationMatrix(), Q, R, x0, 500, 11, 0.3, 10, 0.0);
  const auto diff = compareWithKalman(train, train.transitionMatrix(), train.controlMatrix(),
                                      train.observationMatrix(), Q, R, x0, P0, run);
  std::cout << "[ measured ] EKF vs KF, moving train, 500 steps: state " << diff.first
            << ", covariance " << diff.second << " (max relative)\n";
  EXPECT_LE(diff.first, 1e-9);
  EXPECT_LE(diff.second, 1e-9);
}

TEST(ExtendedKalmanFilterLinear, Nav3ReducedWithControlsEqualsKalmanFilter) {
  const Nav3Reduced model;
  const Matrix<3, 3> Q = estimation::models::nav3ReducedProcessNoise();
  const Matrix<4, 4> R = estimation::models::nav3MeasurementNoise();
  const Vector<3> x0(0.1, 0.2, 0.0);
  const Matrix<3, 3> P0 = Vector<3>(0.3, 0.2, 0.1).asDiagonal();
  const auto run = sftest::simulateNav3Drive(1000, 12, 0.3, 7);
  const auto diff = compareWithKalman(model, model.transitionMatrix(), model.controlMatrix(),
                                      model.observationMatrix(), Q, R, x0, P0, run);
  std::cout << "[ measured ] EKF vs KF, nav3red, 1000 steps: state " << diff.first
            << ", covariance " << diff.second << " (max relative)\n";
  EXPECT_LE(diff.first, 1e-9);
  EXPECT_LE(diff.second, 1e-9);
}

TEST(ExtendedKalmanFilterLinear, CorrelatedNoiseNav3ReducedEqualsKalmanFilter) {
  const Nav3Reduced model;
  Matrix<3, 3> Q;
  Q << 0.5, 0.01, 0.0, 0.01, 0.02, 0.005, 0.0, 0.005, 0.3;
  const Matrix<4, 4> R = sftest::correlatedNav3MeasurementNoise();
  const Vector<3> x0(-0.2, 0.4, 0.1);
  const Matrix<3, 3> P0 = Matrix<3, 3>::Identity();
  const auto run = sftest::simulateNav3Drive(500, 13, 0.4, 5);
  const auto diff = compareWithKalman(model, model.transitionMatrix(), model.controlMatrix(),
                                      model.observationMatrix(), Q, R, x0, P0, run);
  EXPECT_LE(diff.first, 1e-9);
  EXPECT_LE(diff.second, 1e-9);
}

using sftest::ShiftSquareModel;

TEST(ExtendedKalmanFilterNonlinear, OneStepMatchesHandComputation) {
  // x0 = 1, P0 = 0.5, Q = 0.1, R = 0.2, z = 5.
  //   x- = 2, P- = 0.5 + 0.1 = 0.6
  //   H = dh/dx at x- = 2 * 2 = 4          (at the previous state it would be 2)
  //   S = 16 * 0.6 + 0.2 = 9.8, K = 0.6 * 4 / 9.8 = 2.4 / 9.8
  //   y = 5 - 2^2 = 1, x = 2 + 2.4 / 9.8
  //   P = (1 - K H) P- = (1 - 9.6 / 9.8) 0.6 = 0.12 / 9.8
  ExtendedKalmanFilter<ShiftSquareModel> ekf(ShiftSquareModel{}, Matrix<1, 1>::Constant(0.1),
                                             Matrix<1, 1>::Constant(0.2), Vector<1>::Constant(1.0),
                                             Matrix<1, 1>::Constant(0.5));
  ekf.estimate(Measurement<1>::complete(Vector<1>::Constant(5.0)));
  EXPECT_NEAR(ekf.state()(0), 2.0 + 2.4 / 9.8, 1e-14);
  EXPECT_NEAR(ekf.covariance()(0, 0), 0.12 / 9.8, 1e-14);
}

TEST(ExtendedKalmanFilterNonlinear, Nav3CtrlPredictionUsesJacobianAtPreviousState) {
  // Wholly missing measurement: x = f(x, u) and P = A P A^T + Q with A the hand-derived
  // Jacobian at the previous state.
  const estimation::models::Nav3Ctrl model;
  const Matrix<7, 7> Q = estimation::models::nav3ProcessNoise();
  const Matrix<4, 4> R = estimation::models::nav3MeasurementNoise();
  Vector<7> x0;
  x0 << 1.0, -2.0, 0.7, 0.2, 0.05, 0.5, 0.1;
  Matrix<7, 7> P0 = Matrix<7, 7>::Identity() * 0.1;
  P0(2, 4) = P0(4, 2) = 0.02;
  ExtendedKalmanFilter<estimation::models::Nav3Ctrl> ekf(model, Q, R, x0, P0);
  const Vector<2> u(0.6, -0.3);
  ekf.setControl(u);
  ekf.estimate(Measurement<4>::missing());

  const double T = model.T;
  Vector<7> expectedX;
  expectedX << 1.0 + 0.05 * std::cos(0.7), -2.0 + 0.05 * std::sin(0.7), 0.7 + 0.2 * T, -0.3,
      0.5 * T, 0.5 + 0.1 * T, (0.6 - 0.5) / T;
  const Matrix<7, 7> A = sftest::nav3CtrlTransitionJacobian(model, x0);
  const Matrix<7, 7> expectedP = A * P0 * A.transpose() + Q;
  EXPECT_LE(sftest::maxAbsDiff(ekf.state(), expectedX), 1e-14);
  EXPECT_LE(sftest::maxAbsDiff(ekf.covariance(), expectedP), 1e-14);
}

}  // namespace
