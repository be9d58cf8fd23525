// The rotation helpers of the model expressions (sf_filter/config/detail/rotation_helpers.hpp)
// remember their last rotation, so that a header's one-component-per-expression calls compute
// it once: each call must still return its own arguments' value, whatever was asked before
// (another quaternion, another vector, the same values with other AutoDiff derivatives),
// checked against hand-computed rotations and, to the bit, against so3.hpp's own.
#include <sf_filter/config/detail/rotation_helpers.hpp>

#include <cmath>
#include <cstdlib>

#include <gtest/gtest.h>
#include <unsupported/Eigen/AutoDiff>

namespace {

using Vector7 = Eigen::Matrix<double, 7, 1>;
using Ad = Eigen::AutoDiffScalar<Eigen::Matrix<double, 3, 1>>;
using AdVector7 = Eigen::Matrix<Ad, 7, 1>;

const double kHalf = std::sqrt(0.5);  // cos 45 deg = sin 45 deg

/// x[0..3] the quaternion w, x, y, z; x[4..6] unused.
Vector7 state(double w, double qx, double qy, double qz) {
  Vector7 x = Vector7::Zero();
  x.head<4>() << w, qx, qy, qz;
  return x;
}

TEST(RotationHelpers, EachCallRotatesItsOwnVector) {
  const Vector7 turn = state(kHalf, 0, 0, kHalf);  // 90 deg about z
  // R^T (1, 0, 0) = (0, -1, 0) and R^T (0, 1, 0) = (1, 0, 0), the components asked in turn.
  for (int repeat = 0; repeat < 2; ++repeat) {
    EXPECT_NEAR(sf_config::quat_rotate_inverse(turn, 0, 0, 1.0, 0.0, 0.0), 0.0, 1e-15);
    EXPECT_NEAR(sf_config::quat_rotate_inverse(turn, 0, 0, 0.0, 1.0, 0.0), 1.0, 1e-15);
    EXPECT_NEAR(sf_config::quat_rotate_inverse(turn, 0, 1, 1.0, 0.0, 0.0), -1.0, 1e-15);
    EXPECT_NEAR(sf_config::quat_rotate_inverse(turn, 0, 1, 0.0, 1.0, 0.0), 0.0, 1e-15);
    // The same x component, another y: R^T (1, 1, 0) = (1, -1, 0).
    EXPECT_NEAR(sf_config::quat_rotate_inverse(turn, 0, 0, 1.0, 1.0, 0.0), 1.0, 1e-15);
    EXPECT_NEAR(sf_config::quat_rotate_inverse(turn, 0, 0, 1.0, 0.0, 0.0), 0.0, 1e-15);
    // R (1, 0, 0) = (0, 1, 0); the other direction is a helper of its own.
    EXPECT_NEAR(sf_config::quat_rotate(turn, 0, 1, 1.0, 0.0, 0.0), 1.0, 1e-15);
    EXPECT_NEAR(sf_config::quat_rotate_inverse(turn, 0, 1, 1.0, 0.0, 0.0), -1.0, 1e-15);
  }
}

TEST(RotationHelpers, EachCallTurnsItsOwnQuaternion) {
  const Vector7 identity = state(1, 0, 0, 0), turn = state(kHalf, 0, 0, kHalf);
  const double quarter = M_PI / 2;
  // identity exp((0, 0, pi/2)) = (c, 0, 0, s); turn exp((0, 0, pi/2)) = 180 deg about z.
  EXPECT_NEAR(sf_config::quat_integrate(identity, 0, 3, 0.0, 0.0, quarter), kHalf, 1e-15);
  EXPECT_NEAR(sf_config::quat_integrate(turn, 0, 3, 0.0, 0.0, quarter), 1.0, 1e-15);
  EXPECT_NEAR(sf_config::quat_integrate(turn, 0, 0, 0.0, 0.0, quarter), 0.0, 1e-15);
  EXPECT_NEAR(sf_config::quat_integrate(identity, 0, 0, 0.0, 0.0, quarter), kHalf, 1e-15);
  // The same quaternion, another rotation vector: 90 deg about x.
  EXPECT_NEAR(sf_config::quat_integrate(identity, 0, 1, quarter, 0.0, 0.0), kHalf, 1e-15);
  EXPECT_NEAR(sf_config::quat_integrate(identity, 0, 3, quarter, 0.0, 0.0), 0.0, 1e-15);
  // One state holding two quaternions: the identity at 0, the turn at 4.
  Eigen::Matrix<double, 8, 1> two;
  two << 1, 0, 0, 0, kHalf, 0, 0, kHalf;
  EXPECT_NEAR(sf_config::quat_integrate(two, 4, 3, 0.0, 0.0, quarter), 1.0, 1e-15);
  EXPECT_NEAR(sf_config::quat_integrate(two, 0, 3, 0.0, 0.0, quarter), kHalf, 1e-15);
}

TEST(RotationHelpers, TheBitsOfTheirOwnComputation) {
  // Pseudo-random quaternions and vectors, each asked for twice in a row and then interleaved
  // with the next: every component has the bits of so3.hpp's rotation of its own arguments.
  namespace mf = estimation::manifold;
  std::srand(7);
  const auto uniform = [] { return 2.0 * std::rand() / RAND_MAX - 1.0; };
  Vector7 previous = state(1, 0, 0, 0);
  for (int trial = 0; trial < 50; ++trial) {
    Vector7 x = Vector7::Zero();
    x.head<4>() = Eigen::Vector4d(uniform(), uniform(), uniform(), uniform()).normalized();
    const Eigen::Vector3d v(uniform(), uniform(), uniform());
    for (const Vector7* at : {&x, &x, &previous, &x}) {
      const mf::Quaternion<double> q = mf::storedQuaternion(at->head<4>());
      const Eigen::Vector3d inverse = mf::so3RotateInverse<double>(q, v);
      const mf::Quaternion<double> turned = mf::so3Plus<double>(q, v);
      for (int k = 0; k < 3; ++k) {
        EXPECT_EQ(sf_config::quat_rotate_inverse(*at, 0, k, v(0), v(1), v(2)), inverse(k));
      }
      EXPECT_EQ(sf_config::quat_integrate(*at, 0, 0, v(0), v(1), v(2)), turned.w());
      for (int k = 1; k < 4; ++k) {
        EXPECT_EQ(sf_config::quat_integrate(*at, 0, k, v(0), v(1), v(2)), turned.vec()(k - 1));
      }
    }
    previous = x;
  }
}

TEST(RotationHelpers, AutoDiffDerivativesFollowTheirArguments) {
  // d(R^T v)/d seeds: v's derivatives times R^T. The same values with other derivatives must
  // give the new derivatives (the EKF's Jacobians are these).
  AdVector7 x;
  for (int i = 0; i < 7; ++i) x(i) = Ad(0.0, Eigen::Vector3d::Zero());
  x(0).value() = kHalf;
  x(3).value() = kHalf;  // 90 deg about z
  const Ad vxSeed0(1.0, 3, 0), vxSeed1(1.0, 3, 1), zero(0.0, Eigen::Vector3d::Zero());
  // R^T (vx, 0, 0) = (0, -vx, 0): component 1 carries -d vx.
  const Ad first = sf_config::quat_rotate_inverse(x, 0, 1, vxSeed0, zero, zero);
  const Ad second = sf_config::quat_rotate_inverse(x, 0, 1, vxSeed1, zero, zero);
  EXPECT_NEAR(first.value(), -1.0, 1e-15);
  EXPECT_NEAR(second.value(), -1.0, 1e-15);
  EXPECT_NEAR(first.derivatives()(0), -1.0, 1e-15);
  EXPECT_NEAR(first.derivatives()(1), 0.0, 1e-15);
  EXPECT_NEAR(second.derivatives()(0), 0.0, 1e-15);
  EXPECT_NEAR(second.derivatives()(1), -1.0, 1e-15);
}

}  // namespace
