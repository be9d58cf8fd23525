// State layouts (manifold/state_layout.hpp) and means on them (manifold/mean.hpp): the flat
// layout against plain arithmetic, round trips of a mixed layout block by block, AutoDiff
// through [+] and [-] against finite differences, the eigenvector quaternion average against
// Markley's closed form for two quaternions, the tangent mean against hand values, and SE(2)
// against the matrix exponential of its Lie algebra.
#include <cmath>

#include <gtest/gtest.h>
#include <Eigen/Core>
#include <unsupported/Eigen/AutoDiff>
#include <unsupported/Eigen/MatrixFunctions>

#include "sf_estimation/errors.hpp"
#include "sf_estimation/manifold/mean.hpp"
#include "sf_estimation/manifold/se2.hpp"
#include "sf_estimation/manifold/state_layout.hpp"

namespace {

namespace mf = estimation::manifold;
using mf::So2Block;
using mf::So3Block;
using mf::StateLayout;
using mf::VectorBlock;
using Quat = Eigen::Quaterniond;
using V3 = Eigen::Vector3d;

constexpr double kPi = 3.14159265358979323846;

// x, y; heading; attitude; one more entry.
using Mixed = StateLayout<VectorBlock<2>, So2Block, So3Block, VectorBlock<1>>;
static_assert(Mixed::StoredSize == 8 && Mixed::TangentSize == 7 && !Mixed::IsFlat);
using Flat = StateLayout<VectorBlock<3>, VectorBlock<2>>;
static_assert(Flat::StoredSize == 5 && Flat::TangentSize == 5 && Flat::IsFlat);

Quat rotation(const V3& phi) { return Quat(Eigen::AngleAxisd(phi.norm(), phi.normalized())); }

Mixed::Stored<double> mixedState(double heading, const Quat& q) {
  Mixed::Stored<double> x;
  x << 1.5, -2.0, heading, q.w(), q.x(), q.y(), q.z(), 0.25;
  return x;
}

TEST(StateLayout, FlatIsPlainArithmetic) {
  for (int trial = 0; trial < 20; ++trial) {
    const Flat::Stored<double> x = 1e3 * Flat::Stored<double>::Random();
    const Flat::Tangent<double> d = Flat::Tangent<double>::Random();
    const Flat::Stored<double> sum = x + d;
    const Flat::Tangent<double> difference = x - sum;
    EXPECT_EQ(Flat::plus<double>(x, d), sum);  // bit for bit
    EXPECT_EQ(Flat::minus<double>(x, sum), difference);
    Flat::Stored<double> normalised = x;
    Flat::normalise(normalised);
    EXPECT_EQ(normalised, x);
  }
}

TEST(StateLayout, MixedBoxPlusActsBlockByBlock) {
  const Quat q = rotation(V3(0.3, -0.2, 1.0));
  const Mixed::Stored<double> x = mixedState(3.0, q);
  Mixed::Tangent<double> d;
  d << 0.1, 0.2, 0.5, 0.01, -0.02, 0.3, -1.0;
  const Mixed::Stored<double> y = Mixed::plus<double>(x, d);
  EXPECT_EQ(y(0), 1.6);
  EXPECT_EQ(y(1), -1.8);
  EXPECT_DOUBLE_EQ(y(2), 3.5 - 2.0 * kPi);  // wrapped
  const Quat expected = q * rotation(V3(0.01, -0.02, 0.3));
  EXPECT_LE((Eigen::Vector4d(y(3), y(4), y(5), y(6)) -
             Eigen::Vector4d(expected.w(), expected.x(), expected.y(), expected.z()))
                .norm(),
            1e-15);
  EXPECT_EQ(y(7), -0.75);
  EXPECT_LE((Mixed::minus<double>(y, x) - d).norm(), 1e-15);
}

TEST(StateLayout, MixedRoundTripsAndDoubleCover) {
  const Mixed::Stored<double> x = mixedState(-3.1, rotation(V3(2.0, 0.5, -0.4)));
  Mixed::Stored<double> y = mixedState(3.1, rotation(V3(-0.9, 1.1, 0.7)));
  y(0) = 7.0;
  const Mixed::Tangent<double> d = Mixed::minus<double>(y, x);
  EXPECT_NEAR(d(2), 6.2 - 2.0 * kPi, 1e-15);  // across pi, the short way
  Mixed::Stored<double> back = Mixed::plus<double>(x, d);
  const double sign = back.segment<4>(3).dot(y.segment<4>(3)) < 0.0 ? -1.0 : 1.0;
  back.segment<4>(3) *= sign;
  EXPECT_LE((back - y).norm(), 1e-14);
  Mixed::Stored<double> negated = y;  // -q is the same attitude: the same difference
  negated.segment<4>(3) *= -1.0;
  EXPECT_LE((Mixed::minus<double>(negated, x) - d).norm(), 1e-14);
}

TEST(StateLayout, NormaliseWrapsAndScales) {
  Mixed::Stored<double> x;
  x << 1.0, 2.0, 4.0, 2.0, 0.0, 0.0, 0.0, 3.0;
  Mixed::normalise(x);
  Mixed::Stored<double> expected;
  expected << 1.0, 2.0, 4.0 - 2.0 * kPi, 1.0, 0.0, 0.0, 0.0, 3.0;
  EXPECT_EQ(x, expected);
}

TEST(StateLayout, AutoDiffJacobianOfTheRetraction) {
  using Ad = Eigen::AutoDiffScalar<Eigen::Matrix<double, 7, 1>>;
  const Mixed::Stored<double> x = mixedState(3.0, rotation(V3(0.3, -0.2, 1.0)));
  const Mixed::Stored<double> x0 = mixedState(-2.0, rotation(V3(-0.5, 0.1, 0.2)));
  // g(d) = (x [+] d) [-] x0 at d0, by AutoDiff and by central differences.
  Mixed::Tangent<double> d0;
  d0 << 0.1, -0.2, 0.4, 0.2, -0.1, 0.3, 0.5;
  for (const double scale : {0.0, 1.0}) {
    Mixed::Tangent<Ad> d;
    for (int i = 0; i < 7; ++i) d(i) = Ad(scale * d0(i), 7, i);
    const Mixed::Tangent<Ad> g = Mixed::minus<Ad>(Mixed::plus<Ad>(x.cast<Ad>(), d), x0.cast<Ad>());
    Eigen::Matrix<double, 7, 7> J, Jfd;
    for (int i = 0; i < 7; ++i) J.row(i) = g(i).derivatives().transpose();
    for (int j = 0; j < 7; ++j) {
      const Mixed::Tangent<double> e = 1e-6 * Mixed::Tangent<double>::Unit(j);
      const Mixed::Tangent<double> c = scale * d0;
      Jfd.col(j) = (Mixed::minus<double>(Mixed::plus<double>(x, c + e), x0) -
                    Mixed::minus<double>(Mixed::plus<double>(x, c - e), x0)) /
                   2e-6;
    }
    EXPECT_LE((J - Jfd).cwiseAbs().maxCoeff(), 1e-8) << J << "\n\n" << Jfd;
  }
}

TEST(QuaternionAverage, TwoQuaternionsByHand) {
  // Equal weights on the identity and 90 deg about z: 45 deg about z.
  Eigen::Matrix<double, 4, 2> qs;
  const Quat a = Quat::Identity(), b = rotation(V3(0.0, 0.0, kPi / 2.0));
  qs.col(0) << a.w(), a.x(), a.y(), a.z();
  qs.col(1) << b.w(), b.x(), b.y(), b.z();
  Quat mean = mf::quaternionAverage<2>(qs, Eigen::Vector2d(0.5, 0.5));
  EXPECT_LE((mean.coeffs() - rotation(V3(0.0, 0.0, kPi / 4.0)).coeffs()).norm(), 1e-15);
  // Weights 3:1: Markley et al. 2007, eq. (19): q ~ (w1 - w2 + z) q1 + 2 w2 (q1 . q2) q2 with
  // z = sqrt((w1 - w2)^2 + 4 w1 w2 (q1 . q2)^2).
  const double w1 = 0.75, w2 = 0.25, dot = b.w();
  const double z = std::sqrt((w1 - w2) * (w1 - w2) + 4.0 * w1 * w2 * dot * dot);
  const Eigen::Vector4d closed =
      ((w1 - w2 + z) * qs.col(0) + 2.0 * w2 * dot * qs.col(1)).normalized();
  mean = mf::quaternionAverage<2>(qs, Eigen::Vector2d(w1, w2));
  EXPECT_LE((Eigen::Vector4d(mean.w(), mean.x(), mean.y(), mean.z()) - closed).norm(), 1e-15);
  // The sign of a quaternion does not matter (double cover); a naive mean of the
  // coefficients would lose the rotation.
  qs.col(1) *= -1.0;
  const Quat flipped = mf::quaternionAverage<2>(qs, Eigen::Vector2d(w1, w2));
  EXPECT_LE((flipped.coeffs() - mean.coeffs()).norm(), 1e-15);
  EXPECT_THROW(mf::quaternionAverage<2>(qs, Eigen::Vector2d(1.0, -0.5)),
               estimation::ParameterError);
  EXPECT_THROW(mf::quaternionAverage<2>(qs, Eigen::Vector2d(0.0, 0.0)), estimation::ParameterError);
}

TEST(TangentMean, AnglesAcrossPiAndSignedWeights) {
  using Angle = StateLayout<So2Block>;
  Eigen::Matrix<double, 1, 2> angles(3.0, -3.0);
  Angle::Stored<double> mean;
  mf::tangentMean<Angle, 2>(angles, Eigen::Vector2d(0.5, 0.5), Angle::Stored<double>(3.0), mean);
  EXPECT_NEAR(std::abs(mean(0)), kPi, 1e-15);  // not 0, the mean of the numbers
  // Sigma-point weights, one axis: the weighted sum of the angles, -0.075 rad about z.
  using Attitude = StateLayout<So3Block>;
  Eigen::Matrix<double, 4, 3> qs;
  const double a[] = {0.2, 0.5, 1.0};
  for (int i = 0; i < 3; ++i) {
    const Quat q = rotation(V3(0.0, 0.0, a[i]));
    qs.col(i) << q.w(), q.x(), q.y(), q.z();
  }
  Attitude::Stored<double> q;
  const int iterations =
      mf::tangentMean<Attitude, 3>(qs, Eigen::Vector3d(1.5, -0.25, -0.25), qs.col(0), q);
  const Quat expected = rotation(V3(0.0, 0.0, -0.075));
  EXPECT_LE((q - Eigen::Vector4d(expected.w(), expected.x(), expected.y(), expected.z())).norm(),
            1e-15);
  EXPECT_LE(iterations, 3);
  // Off one axis: the defining property, sum w_i (q_i [-] mean) = 0.
  for (int i = 0; i < 3; ++i) {
    const Quat r = rotation(V3(0.3 * i, -0.2, 0.1 + 0.4 * i));
    qs.col(i) << r.w(), r.x(), r.y(), r.z();
  }
  mf::tangentMean<Attitude, 3>(qs, Eigen::Vector3d(1.5, -0.25, -0.25), qs.col(0), q);
  V3 residual = V3::Zero();
  const double w[] = {1.5, -0.25, -0.25};
  for (int i = 0; i < 3; ++i) residual += w[i] * Attitude::minus<double>(qs.col(i), q);
  EXPECT_LE(residual.norm(), 1e-14);
}

// The homogeneous 3x3 matrix of a stored pose (theta, x, y).
Eigen::Matrix3d poseMatrix(const Eigen::Vector3d& x) {
  Eigen::Matrix3d T = Eigen::Matrix3d::Identity();
  T.topLeftCorner<2, 2>() = Eigen::Rotation2Dd(x(0)).toRotationMatrix();
  T.topRightCorner<2, 1>() = x.tail<2>();
  return T;
}

// exp of the se(2) element xi = (theta, rho) by Eigen's matrix exponential.
Eigen::Matrix3d algebraExp(const Eigen::Vector3d& xi) {
  Eigen::Matrix3d A = Eigen::Matrix3d::Zero();
  A(0, 1) = -xi(0);
  A(1, 0) = xi(0);
  A.topRightCorner<2, 1>() = xi.tail<2>();
  return A.exp();
}

using Pose = StateLayout<mf::Se2Block>;

TEST(Se2Block, BoxPlusIsTheBodyExponential) {
  const Eigen::Vector3d x(2.5, 1.0, -2.0);
  for (const Eigen::Vector3d& xi :
       {Eigen::Vector3d(0.0, 0.3, -0.2), Eigen::Vector3d(1e-9, 1.0, 2.0),
        Eigen::Vector3d(0.99e-4, -1.0, 0.5), Eigen::Vector3d(1.01e-4, -1.0, 0.5),
        Eigen::Vector3d(kPi / 2.0, 1.0, 0.0), Eigen::Vector3d(-3.0, 2.0, 1.0)}) {
    const Eigen::Vector3d y = Pose::plus<double>(x, xi);
    const Eigen::Matrix3d expected = poseMatrix(x) * algebraExp(xi);
    EXPECT_LE((poseMatrix(y) - expected).cwiseAbs().maxCoeff(), 1e-14) << xi.transpose();
    EXPECT_LE((Pose::minus<double>(y, x) - xi).norm(), 1e-13) << xi.transpose();
  }
  // By hand: a quarter turn at heading pi / 2 with rho = (1, 0): V rho = (2 / pi, 2 / pi),
  // rotated by pi / 2 to (-2 / pi, 2 / pi).
  const Eigen::Vector3d y = Pose::plus<double>(Eigen::Vector3d(kPi / 2.0, 1.0, 2.0),
                                               Eigen::Vector3d(kPi / 2.0, 1.0, 0.0));
  EXPECT_NEAR(y(0), kPi, 1e-15);
  EXPECT_NEAR(y(1), 1.0 - 2.0 / kPi, 1e-15);
  EXPECT_NEAR(y(2), 2.0 + 2.0 / kPi, 1e-15);
}

TEST(Se2Block, AutoDiffJacobianAgainstFiniteDifferences) {
  using Ad = Eigen::AutoDiffScalar<Eigen::Vector3d>;
  const Eigen::Vector3d x(3.0, 1.0, -2.0), x0(-2.9, 0.5, 0.3);
  for (const Eigen::Vector3d& d0 :
       {Eigen::Vector3d::Zero().eval(), Eigen::Vector3d(0.4, -1.0, 0.7)}) {
    Pose::Tangent<Ad> d;
    for (int i = 0; i < 3; ++i) d(i) = Ad(d0(i), 3, i);
    const Pose::Tangent<Ad> g = Pose::minus<Ad>(Pose::plus<Ad>(x.cast<Ad>(), d), x0.cast<Ad>());
    Eigen::Matrix3d J, Jfd;
    for (int i = 0; i < 3; ++i) J.row(i) = g(i).derivatives().transpose();
    for (int j = 0; j < 3; ++j) {
      const Eigen::Vector3d e = 1e-6 * Eigen::Vector3d::Unit(j);
      Jfd.col(j) = (Pose::minus<double>(Pose::plus<double>(x, d0 + e), x0) -
                    Pose::minus<double>(Pose::plus<double>(x, d0 - e), x0)) /
                   2e-6;
    }
    ASSERT_TRUE(J.allFinite());
    EXPECT_LE((J - Jfd).cwiseAbs().maxCoeff(), 1e-8) << J << "\n\n" << Jfd;
  }
}

}  // namespace
