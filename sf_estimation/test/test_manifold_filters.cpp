// The filters on a state layout (manifold_extended_kalman_filter.hpp,
// manifold_unscented_kalman_filter.hpp): on a flat linear model both equal the library's
// Kalman filter; one step on SO(2) and one quaternion update against hand computations; the
// error-state Jacobians against finite differences; UKF-M's mean is f(x) itself; refusals.
#include <cmath>

#include <gtest/gtest.h>

#include "manifold_test_models.hpp"
#include "sf_estimation/errors.hpp"
#include "sf_estimation/kalman_filter.hpp"
#include "sf_estimation/manifold/state_layout.hpp"
#include "sf_estimation/manifold_extended_kalman_filter.hpp"
#include "sf_estimation/manifold_unscented_kalman_filter.hpp"

namespace {

namespace mf = estimation::manifold;
using estimation::Matrix;
using estimation::Vector;
using manifold_test::AttitudeModel;
using manifold_test::HeadingModel;
using manifold_test::LinearModel;
using Quat = Eigen::Quaterniond;
using V3 = Eigen::Vector3d;

constexpr double kPi = 3.14159265358979323846;

template <class Filter>
void expectMatchesKalmanFilter() {
  const LinearModel model;
  Matrix<2, 2> Q, R;
  Q << 0.04, 0.01, 0.01, 0.09;
  R << 0.5, 0.1, 0.1, 0.3;
  Matrix<3, 3> P0;
  P0 << 2.0, 0.3, 0.0, 0.3, 1.0, 0.2, 0.0, 0.2, 0.5;
  const Vector<3> x0(10.0, -1.0, 0.5);
  Filter filter(model, Q, R, x0, P0);
  estimation::KalmanFilter<3, 2, 1> kf(model.A, model.B, model.H, model.G * Q * model.G.transpose(),
                                       R, x0, P0);
  for (int k = 0; k < 60; ++k) {
    const Vector<1> u(std::sin(0.3 * k));
    const Vector<2> z(10.0 + 0.2 * k + std::cos(k), 0.3 * std::sin(0.7 * k));
    kf.setControl(u);
    filter.predict(u);
    if (k % 3 == 0) {
      filter.update(z);
      kf.estimate(estimation::Measurement<2>::complete(z));
    } else {
      kf.estimate(estimation::Measurement<2>::missing());  // no entry: the time update alone
    }
    ASSERT_LE((filter.state() - kf.state()).cwiseAbs().maxCoeff(),
              1e-10 * (1.0 + kf.state().norm()))
        << "step " << k;
    ASSERT_LE((filter.covariance() - kf.covariance()).cwiseAbs().maxCoeff(),
              1e-10 * kf.covariance().norm())
        << "step " << k;
  }
}

TEST(ManifoldFilters, FlatLinearModelEqualsTheKalmanFilter) {
  expectMatchesKalmanFilter<estimation::ManifoldExtendedKalmanFilter<LinearModel>>();
  expectMatchesKalmanFilter<estimation::ManifoldUnscentedKalmanFilter<LinearModel>>();
}

// tol: the UKF's sigma points lie alpha = 1e-3 times the standard deviation from the mean, so
// that the rounding of the state (1e-16 of 3 rad) is amplified to about 1e-12 relative.
template <class Filter>
void expectHandComputedHeadingStep(double tol) {
  Filter filter(HeadingModel(), Vector<1>(0.01), Vector<1>(0.02), Vector<1>(3.0), Vector<1>(0.04));
  filter.predict(Vector<1>(0.2));
  // 3.2 wrapped; P = 0.04 + 0.01.
  EXPECT_NEAR(filter.state()(0), 3.2 - 2.0 * kPi, 1e-15);
  EXPECT_NEAR(filter.covariance()(0, 0), 0.05, tol);
  // z = 3.05 lies 0.15 behind, across pi from the wrapped state; K = 0.05 / 0.07.
  filter.update(Vector<1>(3.05));
  const double innovation = -0.15;
  EXPECT_NEAR(filter.state()(0), 3.2 + innovation * 5.0 / 7.0, 100.0 * tol);  // back below pi
  EXPECT_NEAR(filter.covariance()(0, 0), 0.05 * 0.02 / 0.07, tol);
}

TEST(ManifoldFilters, HandComputedHeadingStepAcrossPi) {
  expectHandComputedHeadingStep<estimation::ManifoldExtendedKalmanFilter<HeadingModel>>(1e-16);
  expectHandComputedHeadingStep<estimation::ManifoldUnscentedKalmanFilter<HeadingModel>>(1e-13);
}

using AttitudeState = Vector<7>;

AttitudeState attitudeState(const Quat& q, const V3& bias) {
  AttitudeState x;
  x << q.w(), q.x(), q.y(), q.z(), bias;
  return x;
}

Quat rotation(const V3& phi) { return Quat(Eigen::AngleAxisd(phi.norm(), phi.normalized())); }

template <class Filter>
void expectHandComputedQuaternionUpdate(double tol) {
  // P = p I on the attitude, no bias correlation: the update is the body-frame rotation
  // K log(q^-1 z) with K = p / (p + r), P+ = p r / (p + r). The measurement is given with
  // w < 0 (the same rotation): [-] must take the short way.
  const double p = 0.03, r = 0.01;
  const Quat q = rotation(V3(0.5, -1.0, 2.0));
  const V3 offset(0.2, 0.1, -0.3);
  const Quat z = q * rotation(offset);
  Matrix<6, 6> P0 = Matrix<6, 6>::Zero();
  P0.topLeftCorner<3, 3>() = p * Eigen::Matrix3d::Identity();
  P0.bottomRightCorner<3, 3>() = 1e-4 * Eigen::Matrix3d::Identity();
  Filter filter(AttitudeModel(), 1e-4 * Eigen::Matrix3d::Identity(),
                r * Eigen::Matrix3d::Identity(), attitudeState(q, V3::Zero()), P0);
  filter.update(Eigen::Vector4d(-z.w(), -z.x(), -z.y(), -z.z()));
  const Quat expected = q * rotation(p / (p + r) * offset);
  const Eigen::Vector4d got = filter.state().template head<4>();
  const Eigen::Vector4d wanted(expected.w(), expected.x(), expected.y(), expected.z());
  const double sign = got.dot(wanted) < 0.0 ? -1.0 : 1.0;
  EXPECT_LE((sign * got - wanted).norm(), tol);
  EXPECT_LE((filter.covariance().template topLeftCorner<3, 3>() -
             p * r / (p + r) * Eigen::Matrix3d::Identity())
                .norm(),
            tol * p);
  EXPECT_LE(filter.state().template tail<3>().norm(), 1e-15);  // uncorrelated bias untouched
}

TEST(ManifoldFilters, HandComputedQuaternionUpdate) {
  expectHandComputedQuaternionUpdate<estimation::ManifoldExtendedKalmanFilter<AttitudeModel>>(
      1e-15);
  expectHandComputedQuaternionUpdate<estimation::ManifoldUnscentedKalmanFilter<AttitudeModel>>(
      1e-11);
}

TEST(ManifoldFilters, ErrorStateJacobiansAgainstFiniteDifferences) {
  using Filter = estimation::ManifoldExtendedKalmanFilter<AttitudeModel>;
  using Space = AttitudeModel::StateSpace;
  const AttitudeState x = attitudeState(rotation(V3(0.3, 2.0, -1.0)), V3(0.01, -0.02, 0.03));
  const Filter filter(AttitudeModel(), 1e-4 * Eigen::Matrix3d::Identity(),
                      1e-2 * Eigen::Matrix3d::Identity(), x, 0.01 * Matrix<6, 6>::Identity());
  const Vector<3> u(0.5, -2.0, 1.0);
  AttitudeState next;
  Matrix<6, 6> F;
  Matrix<6, 3> G;
  filter.transitionJacobians(u, next, F, G);
  const AttitudeModel model;
  const auto f = [&](const Vector<6>& e, const Vector<3>& w) {
    AttitudeState out;
    model.transition<double>(Space::plus<double>(x, e), u, w, out);
    return Vector<6>(Space::minus<double>(out, next));
  };
  const double h = 1e-6;
  for (int j = 0; j < 6; ++j) {
    const Vector<6> e = h * Vector<6>::Unit(j);
    const Vector<6> column = (f(e, V3::Zero()) - f(-e, V3::Zero())) / (2.0 * h);
    EXPECT_LE((F.col(j) - column).norm(), 1e-8) << "F column " << j;
  }
  for (int j = 0; j < 3; ++j) {
    const V3 w = h * V3::Unit(j);
    const Vector<6> column = (f(Vector<6>::Zero(), w) - f(Vector<6>::Zero(), -w)) / (2.0 * h);
    EXPECT_LE((G.col(j) - column).norm(), 1e-8) << "G column " << j;
  }
  // The bias enters the attitude error with -dt times (nearly) the identity: a non-trivial F.
  EXPECT_NEAR(F(0, 3), -0.1, 0.01);
}

// Unicycle with an uncertain heading: position += v cos(theta), v sin(theta).
struct UnicycleModel {
  using StateSpace = mf::StateLayout<mf::So2Block, mf::VectorBlock<2>>;
  using MeasurementSpace = mf::FlatLayout<2>;
  static constexpr int NoiseSize = 1, ControlSize = 1;
  template <class S>
  void transition(const Eigen::Matrix<S, 3, 1>& x, const Vector<1>& u,
                  const Eigen::Matrix<S, 1, 1>& w, Eigen::Matrix<S, 3, 1>& next) const {
    using std::cos;
    using std::sin;
    next(0) = mf::so2Plus<S>(x(0), w(0));
    next(1) = x(1) + S(u(0)) * cos(x(0));
    next(2) = x(2) + S(u(0)) * sin(x(0));
  }
  template <class S>
  void observation(const Eigen::Matrix<S, 3, 1>& x, Eigen::Matrix<S, 2, 1>& z) const {
    z = x.template tail<2>();
  }
};

TEST(ManifoldFilters, UnscentedMeanIsThePropagatedMean) {
  // A heading variance of 3 rad^2: the weighted mean of the sigma points' cos(theta) would
  // shrink the step (here to 1 - 3/2 and below); UKF-M moves the mean by f itself.
  estimation::ManifoldUnscentedKalmanFilter<UnicycleModel> filter(
      UnicycleModel(), Vector<1>(1e-4), 0.01 * Eigen::Matrix2d::Identity(),
      Vector<3>(0.0, 0.0, 0.0), Eigen::Vector3d(3.0, 0.0, 0.0).asDiagonal().toDenseMatrix(),
      estimation::ManifoldUnscentedParameters{0.5, 1e-3, 1e-3});
  filter.predict(Vector<1>(1.0));
  EXPECT_EQ(filter.state(), Vector<3>(0.0, 1.0, 0.0));
  // The position's variance grows by the spread of sin(theta) across the sigma points.
  EXPECT_GT(filter.covariance()(2, 2), 0.5);
}

TEST(ManifoldFilters, BadInputIsRefusedAndTheBeliefKept) {
  using Filter = estimation::ManifoldUnscentedKalmanFilter<HeadingModel>;
  EXPECT_THROW(
      Filter(HeadingModel(), Vector<1>(0.01), Vector<1>(0.0), Vector<1>(0.0), Vector<1>(1.0)),
      estimation::ParameterError);  // R must be positive definite
  EXPECT_THROW(Filter(HeadingModel(), Vector<1>(0.01), Vector<1>(0.1), Vector<1>(0.0),
                      Vector<1>(1.0), estimation::ManifoldUnscentedParameters{0.0, 1e-3, 1e-3}),
               estimation::ParameterError);
  Filter filter(HeadingModel(), Vector<1>(0.01), Vector<1>(0.1), Vector<1>(0.5), Vector<1>(1.0));
  EXPECT_THROW(filter.update(Vector<1>(std::nan(""))), estimation::InvalidInputError);
  EXPECT_THROW(filter.predict(Vector<1>(INFINITY)), estimation::InvalidInputError);
  EXPECT_EQ(filter.state()(0), 0.5);
  EXPECT_EQ(filter.covariance()(0, 0), 1.0);
}

}  // namespace
