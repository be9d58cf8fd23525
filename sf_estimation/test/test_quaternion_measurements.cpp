// A measured quaternion in the layout filters (measurement_rows.hpp, the node's
// QUATERNION_INPUTS): the update by a small rotation against the hand-computed one (innovation
// the rotation vector, gain p / (p + r), posterior variance p r / (p + r)), the same update for
// the reading -q, the scalar rows beside it untouched by the comparison, a missing quaternion
// leaving its rows out, an R with a variance on the quaternion's w refused, and the tangent rows
// of H (derivative block by block) against central differences of the innovation and against
// AutoDiff over all stored entries.
#include <cmath>

#include <Eigen/Core>
#include <unsupported/Eigen/AutoDiff>

#include <gtest/gtest.h>

#include "sf_estimation/errors.hpp"
#include "sf_estimation/layout_extended_kalman_filter.hpp"
#include "sf_estimation/layout_unscented_kalman_filter.hpp"
#include "sf_estimation/manifold/measurement_rows.hpp"
#include "sf_estimation/manifold/so3_world_block.hpp"

namespace {

namespace mf = estimation::manifold;
using estimation::Matrix;
using estimation::Measurement;
using estimation::Vector;

/// A constant orientation q and a height a; the inputs are q itself and a.
struct HeldPose {
  static constexpr int StateSize = 5, MeasurementSize = 5, ControlSize = 1;
  template <class S>
  void transition(const Eigen::Matrix<S, 5, 1>& x, const Vector<1>&,
                  Eigen::Matrix<S, 5, 1>& next) const {
    next = x;
  }
  template <class S>
  void observation(const Eigen::Matrix<S, 5, 1>& x, Eigen::Matrix<S, 5, 1>& z) const {
    z = x;
  }
};
using Layout = mf::StateLayout<mf::So3WorldBlock, mf::VectorBlock<1>>;
using Ekf = estimation::LayoutExtendedKalmanFilter<HeldPose, Layout, Layout>;
using Ukf = estimation::LayoutUnscentedKalmanFilter<HeldPose, Layout, Layout>;

constexpr double kP = 0.04, kR = 0.01, kHeightP = 2.0, kHeightR = 0.5;

struct Scene {
  Eigen::Quaterniond q0{Eigen::AngleAxisd(0.9, Eigen::Vector3d(1, -2, 0.5).normalized())};
  Vector<3> phi{0.03, -0.02, 0.05};  // the reading: exp(phi) q0, a small rotation about the world
  Matrix<5, 5> Q = Matrix<5, 5>::Zero(), P0 = Matrix<5, 5>::Zero(), R = Matrix<5, 5>::Zero();
  Vector<5> x0;
  Scene() {
    P0.diagonal() << 0, kP, kP, kP, kHeightP;
    R.diagonal() << 0, kR, kR, kR, kHeightR;  // the rotation vector's 3 x 3 on x, y, z
    mf::storeQuaternion(q0, x0);
    x0(4) = 1.0;
  }
  Measurement<5> reading(double sign, double height) const {
    const Eigen::Quaterniond q =
        Eigen::Quaterniond(Eigen::AngleAxisd(phi.norm(), phi.normalized())) * q0;
    Vector<5> z;
    z << sign * q.w(), sign * q.x(), sign * q.y(), sign * q.z(), height;
    return Measurement<5>::complete(z);
  }
};

/// The filter's state and covariance after one update match the hand-computed ones, to within
/// rounding: the UKF's sigma-point sums scale theirs by 1 / alpha^2; the update itself moves
/// the quaternion by 0.05 rad.
constexpr double kTolerance = 1e-9;
template <class Filter, class... Own>
void expectHandComputedUpdate(double sign, const Own&... own) {
  const Scene s;
  Filter filter(HeldPose(), s.Q, s.R, s.x0, s.P0, own...);
  filter.estimate(s.reading(sign, 3.0));
  const double gain = kP / (kP + kR);
  const Eigen::Quaterniond expected =
      Eigen::Quaterniond(Eigen::AngleAxisd(gain * s.phi.norm(), s.phi.normalized())) * s.q0;
  const Eigen::Quaterniond q = mf::storedQuaternion(filter.state().template head<4>());
  EXPECT_LT(mf::so3Log<double>(q * expected.conjugate()).norm(), kTolerance);
  EXPECT_NEAR(filter.state()(4), 1.0 + kHeightP / (kHeightP + kHeightR) * 2.0, kTolerance);
  Matrix<5, 5> P = Matrix<5, 5>::Zero();
  P.diagonal() << 0, kP * kR / (kP + kR), kP * kR / (kP + kR), kP * kR / (kP + kR),
      kHeightP * kHeightR / (kHeightP + kHeightR);
  EXPECT_LT((filter.covariance() - P).cwiseAbs().maxCoeff(), kTolerance) << filter.covariance();
}

TEST(QuaternionMeasurements, EkfUpdateIsTheHandComputedOne) { expectHandComputedUpdate<Ekf>(1.0); }

TEST(QuaternionMeasurements, EkfTakesMinusQAsQ) { expectHandComputedUpdate<Ekf>(-1.0); }

TEST(QuaternionMeasurements, UkfUpdateIsTheHandComputedOne) {
  expectHandComputedUpdate<Ukf>(1.0, estimation::ManifoldUnscentedParameters());
}

TEST(QuaternionMeasurements, UkfTakesMinusQAsQ) {
  expectHandComputedUpdate<Ukf>(-1.0, estimation::ManifoldUnscentedParameters());
}

TEST(QuaternionMeasurements, AMissingQuaternionLeavesItsRowsOut) {
  const Scene s;
  Ekf ekf(HeldPose(), s.Q, s.R, s.x0, s.P0);
  Measurement<5> z = s.reading(1.0, 3.0);
  for (int i = 0; i < 4; ++i) z.available(i) = false;
  ekf.estimate(z);
  EXPECT_EQ(ekf.state().head<4>(), s.x0.head<4>());
  // The prediction's F is the identity up to rounding (AutoDiff through exp and log).
  EXPECT_LT((ekf.covariance().topLeftCorner<4, 4>() - s.P0.topLeftCorner<4, 4>()).norm(), 1e-15);
  EXPECT_NEAR(ekf.state()(4), 1.0 + kHeightP / (kHeightP + kHeightR) * 2.0, 1e-12);
}

template <class Filter, class... Own>
void expectLeftOutWholeWhenAComponentIsMissing(const Own&... own) {
  const Scene s;
  for (int missing = 0; missing < 4; ++missing) {
    Filter filter(HeldPose(), s.Q, s.R, s.x0, s.P0, own...);
    Measurement<5> z = s.reading(1.0, 3.0);
    z.available(missing) = false;
    z.value(missing) = 0.0;  // what a missing entry may hold
    filter.estimate(z);
    EXPECT_LT((filter.state().template head<4>() - s.x0.template head<4>()).norm(), 1e-12)
        << "missing " << missing;
    EXPECT_TRUE(filter.state().allFinite());
  }
}

TEST(QuaternionMeasurements, AQuaternionWithAMissingComponentIsLeftOutWhole) {
  expectLeftOutWholeWhenAComponentIsMissing<Ekf>();
  expectLeftOutWholeWhenAComponentIsMissing<Ukf>(estimation::ManifoldUnscentedParameters());
}

TEST(QuaternionMeasurements, MessageCovarianceOnTheTangentRowsIsUsed) {
  const Scene s;
  Ekf ekf(HeldPose(), s.Q, s.R, s.x0, s.P0);
  Measurement<5> z = s.reading(1.0, 3.0);
  const double r = 4.0 * kR;  // a message's 3 x 3 rad^2 block on the x, y, z rows
  for (int i = 1; i < 4; ++i) {
    z.varianceGiven(i) = true;
    z.variance(i) = r;
  }
  ekf.estimate(z);
  const Eigen::Quaterniond expected =
      Eigen::Quaterniond(Eigen::AngleAxisd(kP / (kP + r) * s.phi.norm(), s.phi.normalized())) *
      s.q0;
  const Eigen::Quaterniond q = mf::storedQuaternion(ekf.state().head<4>());
  EXPECT_LT(mf::so3Log<double>(q * expected.conjugate()).norm(), 1e-12);
}

TEST(QuaternionMeasurements, AVarianceOnTheQuaternionsWIsRefused) {
  Scene s;
  s.R(0, 0) = kR;
  EXPECT_THROW(Ekf(HeldPose(), s.Q, s.R, s.x0, s.P0), estimation::ParameterError);
  s.R(0, 0) = 0.0;
  s.R(0, 2) = s.R(2, 0) = 1e-4;
  EXPECT_THROW(Ukf(HeldPose(), s.Q, s.R, s.x0, s.P0, estimation::ManifoldUnscentedParameters()),
               estimation::ParameterError);
}

/// A flat block, a quaternion and another flat block: 7 stored entries, 6 tangent ones.
using Mixed = mf::StateLayout<mf::VectorBlock<2>, mf::So3WorldBlock, mf::VectorBlock<1>>;
using MixedRows = mf::MeasurementRows<Mixed>;
constexpr int kMixedD = 5;  // the state's tangent size: any

struct MixedScene {
  Vector<7> h;
  Matrix<7, kMixedD> H;  // dh/de: no zeros, no structure
  MixedScene() {
    const Eigen::Quaterniond q(Eigen::AngleAxisd(0.9, Eigen::Vector3d(1, -2, 0.5).normalized()));
    h << 1.5, -0.7, q.w(), q.x(), q.y(), q.z(), 2.0;
    for (int i = 0; i < 7; ++i) {
      for (int j = 0; j < kMixedD; ++j) H(i, j) = std::sin(1.0 + 3.0 * i + 7.0 * j);
    }
  }
};

/// d innovation(z, h)/dz at z = h by central differences, times H: the tangent rows that
/// MeasurementRows<L>::tangentRows should give, computed without it.
template <class L, int D>
Matrix<L::StoredSize, D> centralDifferenceRows(const Vector<L::StoredSize>& h,
                                               const Matrix<L::StoredSize, D>& H) {
  constexpr int N = L::StoredSize;
  constexpr double kStep = 1e-6;
  Matrix<N, N> dInnovation;
  for (int i = 0; i < N; ++i) {
    Vector<N> up = h, down = h;
    up(i) += kStep;
    down(i) -= kStep;
    dInnovation.col(i) =
        (mf::MeasurementRows<L>::innovation(up, h) - mf::MeasurementRows<L>::innovation(down, h)) /
        (2.0 * kStep);
  }
  return dInnovation * H;
}

TEST(QuaternionMeasurements, TangentRowsAreTheInnovationsCentralDifferences) {
  const MixedScene s;
  Matrix<7, kMixedD> H = s.H;
  MixedRows::tangentRows(s.h, H);
  const Matrix<7, kMixedD> expected = centralDifferenceRows<Mixed>(s.h, s.H);
  EXPECT_LT((H - expected).cwiseAbs().maxCoeff(), 1e-8) << H << "\n\n" << expected;
  // The flat blocks' rows are H's own; the quaternion's w row (no tangent coordinate) is zero.
  EXPECT_EQ(H.topRows<2>(), s.H.topRows<2>());
  EXPECT_EQ(H.row(6), s.H.row(6));
  EXPECT_EQ(H.row(2), (Matrix<1, kMixedD>::Zero()));
}

TEST(QuaternionMeasurements, TangentRowsOfBlocksWithoutAClosedFormAreTheCentralDifferences) {
  // So3Block (body frame) and So2Block have no minusDerivative: AutoDiff over their entries.
  using Other = mf::StateLayout<mf::VectorBlock<1>, mf::So3Block, mf::So2Block>;
  const MixedScene s;
  Vector<6> h;
  h << 0.4, s.h.segment<4>(2), 2.5;
  const Matrix<6, kMixedD> H0 = s.H.topRows<6>();
  Matrix<6, kMixedD> H = H0;
  mf::MeasurementRows<Other>::tangentRows(h, H);
  const Matrix<6, kMixedD> expected = centralDifferenceRows<Other>(h, H0);
  EXPECT_LT((H - expected).cwiseAbs().maxCoeff(), 1e-8) << H << "\n\n" << expected;
}

TEST(QuaternionMeasurements, TangentRowsAreTheFullSizeAutoDiffsToTheBit) {
  const MixedScene s;
  Matrix<7, kMixedD> H = s.H;
  MixedRows::tangentRows(s.h, H);
  // d[z [-] h]/dz over all 7 stored entries at once (measurement_rows.hpp before the derivative
  // went block by block); equal up to an exact zero's sign, which == ignores.
  using Ad = Eigen::AutoDiffScalar<Vector<7>>;
  Eigen::Matrix<Ad, 7, 1> z;
  for (int i = 0; i < 7; ++i) z(i) = Ad(s.h(i), 7, i);
  const Eigen::Matrix<Ad, 6, 1> d = Mixed::minus<Ad>(z, s.h.cast<Ad>());
  const std::array<int, 6> rows = mf::LayoutEmbedding<Mixed>::storedOfTangent();
  Matrix<7, kMixedD> expected = Matrix<7, kMixedD>::Zero();
  for (int t = 0; t < 6; ++t) expected.row(rows[t]) = d(t).derivatives().transpose() * s.H;
  EXPECT_TRUE((H.array() == expected.array()).all()) << H << "\n\n" << expected;
}

}  // namespace
