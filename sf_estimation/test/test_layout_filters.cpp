// The node's filters on a state layout (layout_extended_kalman_filter.hpp,
// layout_unscented_kalman_filter.hpp, QUATERNION_STATES): the covariance embedding against a
// hand-written index map; on a flat layout the layout EKF gives the flat EKF's estimates,
// missing entries and angle inputs included; on a quaternion it follows a rotating body from
// a gyro and an accelerometer to within the accelerometer's noise, and keeps the quaternion
// unit; refusals keep the belief.
#include <cmath>

#include <gtest/gtest.h>

#include "sf_estimation/errors.hpp"
#include "sf_estimation/extended_kalman_filter.hpp"
#include "sf_estimation/layout_extended_kalman_filter.hpp"
#include "sf_estimation/layout_unscented_kalman_filter.hpp"
#include "sf_estimation/manifold/layout_embedding.hpp"
#include "sf_estimation/manifold/so3_world_block.hpp"

namespace {

namespace mf = estimation::manifold;
using estimation::Matrix;
using estimation::Measurement;
using estimation::Vector;

/// A unicycle (x, y, theta) driven by a speed and a turn rate, seeing a compass and a range:
/// the flat filters' model interface, as a configuration header generates it.
struct Unicycle {
  static constexpr int StateSize = 3, MeasurementSize = 2, ControlSize = 2;
  double T = 0.1;
  Eigen::Index stateSize() const { return 3; }
  Eigen::Index measurementSize() const { return 2; }
  Eigen::Index controlSize() const { return 2; }
  template <class S>
  void transition(const Eigen::Matrix<S, 3, 1>& x, const Vector<2>& u,
                  Eigen::Matrix<S, 3, 1>& next) const {
    using std::cos;
    using std::sin;
    next(0) = x(0) + u(0) * T * cos(x(2));
    next(1) = x(1) + u(0) * T * sin(x(2));
    next(2) = x(2) + u(1) * T;
  }
  template <class S>
  void observation(const Eigen::Matrix<S, 3, 1>& x, Eigen::Matrix<S, 2, 1>& z) const {
    using std::sqrt;
    z(0) = x(2);
    z(1) = sqrt(x(0) * x(0) + x(1) * x(1));
  }
};

/// q (w, x, y, z) turned by the gyro u, a gyro bias b; the accelerometer reads R(q)^T g.
struct Attitude {
  static constexpr int StateSize = 7, MeasurementSize = 3, ControlSize = 3;
  static constexpr double kGravity = 9.80665;
  double T = 0.01;
  template <class S>
  void transition(const Eigen::Matrix<S, 7, 1>& x, const Vector<3>& u,
                  Eigen::Matrix<S, 7, 1>& next) const {
    const mf::Vector3<S> rate = u.cast<S>() - x.template tail<3>();
    auto q = next.template head<4>();
    mf::storeQuaternion(mf::so3Plus<S>(mf::storedQuaternion(x.template head<4>()), rate * S(T)), q);
    next.template tail<3>() = x.template tail<3>();
  }
  template <class S>
  void observation(const Eigen::Matrix<S, 7, 1>& x, Eigen::Matrix<S, 3, 1>& z) const {
    z = mf::so3RotateInverse<S>(mf::storedQuaternion(x.template head<4>()),
                                mf::Vector3<S>(S(0.0), S(0.0), S(kGravity)));
  }
};
// The chart of the node's QUATERNION_STATES (quaternions.hpp).
using AttitudeLayout = mf::StateLayout<mf::So3WorldBlock, mf::VectorBlock<3>>;

TEST(LayoutEmbedding, TangentRowsSitOnTheBlocksLastEntries) {
  using Layout = mf::StateLayout<mf::VectorBlock<2>, mf::So3Block, mf::So2Block>;
  using E = mf::LayoutEmbedding<Layout>;
  const std::array<int, 6> expected{0, 1, 3, 4, 5, 6};  // the quaternion's w (2) has no row
  EXPECT_EQ(E::storedOfTangent(), expected);
  Matrix<6, 6> P = Matrix<6, 6>::Random();
  const Matrix<7, 7> stored = E::toStored(P);
  EXPECT_EQ(stored.row(2).cwiseAbs().sum() + stored.col(2).cwiseAbs().sum(), 0.0);
  EXPECT_EQ(stored(3, 6), P(2, 5));
  EXPECT_EQ(E::toTangent(stored), P);
}

TEST(So3WorldBlock, PerturbsAboutTheWorldAxesAndMinusInvertsPlus) {
  using Layout = mf::StateLayout<mf::So3WorldBlock>;
  const Eigen::Quaterniond q(Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, 2, 3).normalized()));
  Vector<4> x;
  mf::storeQuaternion(q, x);
  const Vector<3> phi(0.2, -0.1, 0.3);
  const Vector<4> moved = Layout::plus<double>(x, phi);
  // exp(phi) q, by Eigen's angle-axis: the rotation phi applied after q, about world axes.
  const Eigen::Quaterniond expected =
      Eigen::Quaterniond(Eigen::AngleAxisd(phi.norm(), phi.normalized())) * q;
  EXPECT_LT(mf::so3Log<double>(mf::storedQuaternion(moved) * expected.conjugate()).norm(), 1e-14);
  EXPECT_LT((Layout::minus<double>(moved, x) - phi).norm(), 1e-14);
  // A rotation about the world's z leaves the body's view of the world's z unchanged.
  const Vector<4> turned = Layout::plus<double>(x, Vector<3>(0.0, 0.0, 0.5));
  const Eigen::Vector3d up = mf::so3RotateInverse<double>(q, Eigen::Vector3d::UnitZ());
  EXPECT_LT(
      (mf::so3RotateInverse<double>(mf::storedQuaternion(turned), Eigen::Vector3d::UnitZ()) - up)
          .norm(),
      1e-14);
}

TEST(LayoutFilters, FlatLayoutGivesTheFlatEkfWithMissingEntriesAndAngles) {
  Matrix<3, 3> Q = Matrix<3, 3>::Identity() * 1e-3, P0;
  P0 << 0.5, 0.1, 0.0, 0.1, 0.4, 0.05, 0.0, 0.05, 0.2;
  const Matrix<2, 2> R = Vector<2>(0.01, 0.04).asDiagonal();
  const Vector<3> x0(3.0, -1.0, 3.0);
  const estimation::AngularComponents angles{{}, {0}};  // the compass: wrapped innovations
  estimation::ExtendedKalmanFilter<Unicycle> flat(Unicycle(), Q, R, x0, P0, angles);
  // VectorBlocks only: the flat filter's heading is not an angle state either.
  estimation::LayoutExtendedKalmanFilter<Unicycle, mf::FlatLayout<3>> layout(Unicycle(), Q, R, x0,
                                                                             P0, angles);
  for (int k = 0; k < 80; ++k) {
    const Vector<2> u(1.0, 0.4 * std::sin(0.1 * k));
    flat.setControl(u);
    layout.setControl(u);
    Measurement<2> z = Measurement<2>::complete(Vector<2>(-3.1 + 0.01 * k, 3.0 + 0.05 * k));
    z.available(0) = k % 2 == 0;
    z.available(1) = k % 3 != 0;
    flat.estimate(z);
    layout.estimate(z);
    ASSERT_LE((layout.state() - flat.state()).cwiseAbs().maxCoeff(), 1e-10) << "step " << k;
    ASSERT_LE((layout.covariance() - flat.covariance()).cwiseAbs().maxCoeff(), 1e-10)
        << "step " << k;
  }
}

/// Runs a filter on a body turning at a known rate with a biased gyro; returns the largest
/// tilt error (rad, angle between the true and the estimated up) over the last 5 s.
template <class Filter>
double attitudeTiltError(Filter& filter, Vector<7>& last) {
  const Eigen::Vector3d rate(0.3, -0.2, 0.5), bias(0.01, -0.02, 0.015);
  Eigen::Quaterniond truth(Eigen::AngleAxisd(0.4, Eigen::Vector3d(1, 1, 0).normalized()));
  double worst = 0.0;
  for (int k = 0; k < 2000; ++k) {
    truth = mf::so3Plus<double>(truth, rate * 0.01);
    filter.setControl(rate + bias);
    const Eigen::Vector3d g = truth.conjugate() * Eigen::Vector3d(0, 0, Attitude::kGravity);
    filter.estimate(Measurement<3>::complete(g));
    const Vector<7> x = filter.state();
    const Eigen::Quaterniond q = mf::storedQuaternion(x.head<4>());
    EXPECT_NEAR(q.norm(), 1.0, 1e-12);
    const Eigen::Vector3d up = (q.conjugate() * Eigen::Vector3d::UnitZ());
    const Eigen::Vector3d trueUp = (truth.conjugate() * Eigen::Vector3d::UnitZ());
    if (k >= 1500) worst = std::max(worst, std::acos(std::min(1.0, up.dot(trueUp))));
  }
  last = filter.state();
  return worst;
}

/// Q and P0 in the stored form (the quaternion's w row zero), R, x0 at the identity.
struct AttitudeNoise {
  Matrix<7, 7> Q = Matrix<7, 7>::Zero(), P0 = Matrix<7, 7>::Zero();
  Matrix<3, 3> R = Matrix<3, 3>::Identity() * 1e-4;
  Vector<7> x0 = Vector<7>::Zero();
  AttitudeNoise() {
    Q.diagonal() << 0, 1e-6, 1e-6, 1e-6, 1e-10, 1e-10, 1e-10;
    P0.diagonal() << 0, 1, 1, 1, 1e-3, 1e-3, 1e-3;
    x0(0) = 1.0;
  }
};

template <class Filter, class... Own>
void expectFollowsTheAttitude(const Own&... own) {
  const AttitudeNoise a;
  Filter filter(Attitude(), a.Q, a.R, a.x0, a.P0, own...);
  Vector<7> last;
  const double worst = attitudeTiltError(filter, last);
  // Noise-free readings: the tilt is pinned far below the 0.01 rad of R's standard deviation.
  EXPECT_LT(worst, 1e-3);
  // Roll and pitch observe the bias's horizontal part after 20 s of turning.
  EXPECT_NEAR(last(4), 0.01, 2e-3);
  EXPECT_NEAR(last(5), -0.02, 2e-3);
}

TEST(LayoutFilters, EkfFollowsARotatingBodyFromGyroAndAccelerometer) {
  expectFollowsTheAttitude<estimation::LayoutExtendedKalmanFilter<Attitude, AttitudeLayout>>();
}

TEST(LayoutFilters, UkfFollowsARotatingBodyFromGyroAndAccelerometer) {
  expectFollowsTheAttitude<estimation::LayoutUnscentedKalmanFilter<Attitude, AttitudeLayout>>(
      estimation::ManifoldUnscentedParameters());
}

TEST(LayoutFilters, RefusalsKeepTheBelief) {
  const AttitudeNoise a;
  const Matrix<7, 7>&Q = a.Q, &P0 = a.P0;
  const Matrix<3, 3>& R = a.R;
  const Vector<7>& x0 = a.x0;
  using Ekf = estimation::LayoutExtendedKalmanFilter<Attitude, AttitudeLayout>;
  Matrix<7, 7> wRow = Q;
  wRow(0, 0) = 1e-6;  // a variance on the quaternion's w: not a tangent row
  EXPECT_THROW(Ekf(Attitude(), wRow, R, x0, P0), estimation::ParameterError);
  EXPECT_THROW(Ekf(Attitude(), Q, R, Vector<7>::Zero(), P0), estimation::ParameterError);
  Ekf ekf(Attitude(), Q, R, x0, P0);
  const Vector<7> before = ekf.state();
  EXPECT_THROW(ekf.setBelief(Vector<7>::Zero(), P0), estimation::ParameterError);
  EXPECT_THROW(ekf.setBelief(x0, wRow), estimation::ParameterError);
  EXPECT_EQ(ekf.state(), before);
  EXPECT_EQ(ekf.covariance(), P0);
}

}  // namespace
