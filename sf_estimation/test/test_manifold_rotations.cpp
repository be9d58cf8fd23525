// SO(2) and SO(3) primitives (manifold/so2.hpp, so3.hpp) against independent references:
// Eigen's AngleAxis for exp and the rotations, hand values for the wrapped retraction, central
// finite differences for the AutoDiff Jacobians, and a long run of small steps for the drift of
// the unit norm.
#include <cmath>

#include <gtest/gtest.h>
#include <Eigen/Core>
#include <unsupported/Eigen/AutoDiff>

#include "sf_estimation/manifold/so2.hpp"
#include "sf_estimation/manifold/so3.hpp"

namespace {

namespace mf = estimation::manifold;
using Quat = Eigen::Quaterniond;
using V3 = Eigen::Vector3d;
using Ad3 = Eigen::AutoDiffScalar<Eigen::Vector3d>;
using AdV3 = Eigen::Matrix<Ad3, 3, 1>;

constexpr double kPi = 3.14159265358979323846;

Quat angleAxis(const V3& phi) {
  const double t = phi.norm();
  return t == 0.0 ? Quat::Identity() : Quat(Eigen::AngleAxisd(t, phi / t));
}

// The same rotation (q and -q are one rotation).
void expectSameRotation(const Quat& a, const Quat& b, double tol) {
  const double sign = a.coeffs().dot(b.coeffs()) < 0.0 ? -1.0 : 1.0;
  EXPECT_LE((a.coeffs() - sign * b.coeffs()).cwiseAbs().maxCoeff(), tol)
      << a.coeffs().transpose() << " vs " << b.coeffs().transpose();
}

TEST(So2, WrappedRetractionHandValues) {
  EXPECT_DOUBLE_EQ(mf::so2Plus(3.0, 0.5), 3.5 - 2.0 * kPi);
  EXPECT_DOUBLE_EQ(mf::so2Plus(-3.0, -0.5), -3.5 + 2.0 * kPi);
  EXPECT_DOUBLE_EQ(mf::so2Minus(-3.0, 3.0), 2.0 * kPi - 6.0);  // across pi: short way, positive
  EXPECT_DOUBLE_EQ(mf::so2Minus(3.0, -3.0), 6.0 - 2.0 * kPi);
  EXPECT_EQ(mf::so2Minus(0.25, 0.25), 0.0);
}

TEST(So2, RoundTripsIncludingNearPi) {
  const double bases[] = {0.0, 1.0, -2.5, kPi - 1e-12, -kPi + 1e-12, kPi};
  const double steps[] = {0.0, 1e-12, -1e-12, 0.7, -3.0, kPi - 1e-9, -kPi + 1e-9};
  for (const double a : bases) {
    for (const double d : steps) {
      const double b = mf::so2Plus(a, d);
      EXPECT_GT(b, -kPi);
      EXPECT_LE(b, kPi);
      EXPECT_NEAR(mf::so2Minus(b, a), d, 1e-15) << a << " [+] " << d;
      EXPECT_NEAR(mf::so2Minus(mf::so2Plus(a, mf::so2Minus(b, a)), b), 0.0, 1e-15);
    }
  }
}

TEST(So2, AutoDiffThroughTheWrap) {
  // d/dd wrap(a + d) = 1 on both sides of the wrap; the value wraps.
  using Ad1 = Eigen::AutoDiffScalar<Eigen::Matrix<double, 1, 1>>;
  const Ad1 d(0.5, 1, 0);
  const Ad1 b = mf::so2Plus(Ad1(3.0), d);
  EXPECT_DOUBLE_EQ(b.value(), 3.5 - 2.0 * kPi);
  EXPECT_EQ(b.derivatives()(0), 1.0);
  const Ad1 m = mf::so2Minus(Ad1(-3.0), d);
  EXPECT_EQ(m.derivatives()(0), -1.0);
}

TEST(So3, ExpAgainstAngleAxis) {
  const V3 axis = V3(1.0, -2.0, 0.5).normalized();
  // Both sides of the series threshold (t^2 = 1e-6), tiny, moderate, near and at pi.
  for (const double t : {0.0, 1e-12, 1e-6, 0.999e-3, 1.001e-3, 0.3, 2.0, kPi - 1e-9, kPi}) {
    expectSameRotation(mf::so3Exp<double>(t * axis), angleAxis(t * axis), 2e-16 * 4);
    EXPECT_NEAR(mf::so3Exp<double>(t * axis).norm(), 1.0, 4e-16);
  }
}

TEST(So3, LogInvertsExpUpToPi) {
  const V3 axis = V3(-0.3, 0.4, 1.2).normalized();
  for (const double t : {0.0, 1e-12, 1e-7, 0.999e-3, 1.001e-3, 1.0, 3.0, kPi - 1e-6, kPi - 1e-9}) {
    const V3 phi = t * axis;
    EXPECT_LE((mf::so3Log<double>(mf::so3Exp<double>(phi)) - phi).norm(), 2e-15 * (1.0 + t))
        << "angle " << t;
    EXPECT_LE((mf::so3Log<double>(angleAxis(phi)) - phi).norm(), 2e-15 * (1.0 + t));
  }
}

TEST(So3, LogIsTheShortestRotationOfEitherSign) {
  const V3 axis = V3(0.2, -0.9, 0.4).normalized();
  const V3 phi = (kPi + 0.5) * axis;  // past pi: the short way is 2 pi - |phi| the other way
  const V3 shortest = -(kPi - 0.5) * axis;
  const Quat q = angleAxis(phi);
  EXPECT_LE((mf::so3Log<double>(q) - shortest).norm(), 1e-14);
  const Quat negated(-q.w(), -q.x(), -q.y(), -q.z());  // double cover: the same rotation
  EXPECT_LE((mf::so3Log<double>(negated) - shortest).norm(), 1e-14);
  // Small rotation stored with w < 0.
  const Quat small = angleAxis(1e-5 * axis);
  const Quat smallNegated(-small.w(), -small.x(), -small.y(), -small.z());
  EXPECT_LE((mf::so3Log<double>(smallNegated) - 1e-5 * axis).norm(), 1e-20);
  // Not unit: the rotation of the normalised quaternion.
  const Quat scaled(3.0 * q.w(), 3.0 * q.x(), 3.0 * q.y(), 3.0 * q.z());
  EXPECT_LE((mf::so3Log<double>(scaled) - shortest).norm(), 1e-14);
}

TEST(So3, RotationsAgainstTheRotationMatrix) {
  const Quat q = angleAxis(V3(0.4, -1.1, 2.0));
  const Eigen::Matrix3d R =
      Eigen::AngleAxisd(2.0 * std::atan2(q.vec().norm(), q.w()), q.vec().normalized())
          .toRotationMatrix();
  const V3 v(1.0, 2.0, -3.0);
  EXPECT_LE((mf::so3Rotate<double>(q, v) - R * v).norm(), 1e-14);
  EXPECT_LE((mf::so3RotateInverse<double>(q, v) - R.transpose() * v).norm(), 1e-14);
  const Quat p = angleAxis(V3(-0.7, 0.2, 0.1));
  const Eigen::Matrix3d Rp =
      Eigen::AngleAxisd(2.0 * std::atan2(p.vec().norm(), p.w()), p.vec().normalized())
          .toRotationMatrix();
  EXPECT_LE((mf::so3Product<double>(q, p).toRotationMatrix() - R * Rp).norm(), 1e-14);
  const Quat drifted(1.01 * q.w(), 1.01 * q.x(), 1.01 * q.y(), 1.01 * q.z());
  expectSameRotation(mf::so3Normalised<double>(drifted), q, 4e-16);
}

TEST(So3, BoxPlusIsTheRightPerturbation) {
  const Quat q = angleAxis(V3(0.0, 0.0, 1.2));
  const V3 phi(0.3, 0.0, 0.0);
  // q exp(phi): rotate about the body x axis (after the yaw), not the world x axis.
  const Eigen::Matrix3d expected =
      q.toRotationMatrix() * Eigen::AngleAxisd(0.3, V3::UnitX()).toRotationMatrix();
  EXPECT_LE((mf::so3Plus<double>(q, phi).toRotationMatrix() - expected).norm(), 1e-15);
  // The body-frame difference, and both round trips.
  const Quat q1 = mf::so3Plus<double>(q, phi);
  EXPECT_LE((mf::so3Minus<double>(q1, q) - phi).norm(), 1e-15);
  const Quat q2 = angleAxis(V3(-2.0, 0.5, 0.9));
  expectSameRotation(mf::so3Plus<double>(q, mf::so3Minus<double>(q2, q)), q2, 1e-15);
}

TEST(So3, NormStaysUnitOverAMillionBoxPlusSteps) {
  // 10^6 steps of 1e-5 rad about one axis: 10 rad in all, compared with the closed form.
  const V3 axis = V3(1.0, 1.0, -1.0).normalized();
  Quat q = angleAxis(V3(0.1, 0.2, 0.3));
  const Quat start = q;
  double worst = 0.0;
  for (int i = 0; i < 1000000; ++i) {
    q = mf::so3Plus<double>(q, 1e-5 * axis);
    worst = std::max(worst, std::abs(q.norm() - 1.0));
  }
  EXPECT_LE(worst, 4.0 * std::numeric_limits<double>::epsilon());
  expectSameRotation(q, start * angleAxis(10.0 * axis), 1e-9);
}

// AutoDiff Jacobian of v(d) at d0, d in R^3.
template <class F>
Eigen::Matrix3d autoDiffJacobian(const F& f, const V3& d0) {
  AdV3 d;
  for (int i = 0; i < 3; ++i) d(i) = Ad3(d0(i), 3, i);
  const AdV3 v = f(d);
  Eigen::Matrix3d J;
  for (int i = 0; i < 3; ++i) J.row(i) = v(i).derivatives().transpose();
  return J;
}

template <class F>
Eigen::Matrix3d finiteDifferenceJacobian(const F& f, const V3& d0, double h) {
  Eigen::Matrix3d J;
  for (int i = 0; i < 3; ++i) {
    const V3 e = h * V3::Unit(i);
    J.col(i) = (f(V3(d0 + e)) - f(V3(d0 - e))) / (2.0 * h);
  }
  return J;
}

TEST(So3, AutoDiffJacobiansAgainstFiniteDifferences) {
  const Quat q = angleAxis(V3(0.5, -0.4, 2.2));
  const Quat q0 = angleAxis(V3(-1.0, 0.3, 0.2));
  // g(d) = (q [+] d) [-] q0, at 0 (series branches), small and large d.
  const auto g = [&](const auto& d) {
    using S = typename std::decay_t<decltype(d)>::Scalar;
    return mf::so3Minus<S>(mf::so3Plus<S>(q.cast<S>(), d), q0.cast<S>());
  };
  for (const V3& d0 : {V3(0.0, 0.0, 0.0), V3(1e-5, -2e-5, 0.5e-5), V3(0.3, -0.2, 0.6)}) {
    const Eigen::Matrix3d J = autoDiffJacobian(g, d0);
    const Eigen::Matrix3d Jfd = finiteDifferenceJacobian(g, d0, 1e-6);
    ASSERT_TRUE(J.allFinite()) << d0.transpose();
    EXPECT_LE((J - Jfd).cwiseAbs().maxCoeff(), 1e-8) << d0.transpose() << "\n" << J << "\n" << Jfd;
  }
  // At d = 0 the Jacobian of (q [+] d) [-] q is exactly the identity.
  const auto self = [&](const auto& d) {
    using S = typename std::decay_t<decltype(d)>::Scalar;
    return mf::so3Minus<S>(mf::so3Plus<S>(q.cast<S>(), d), q.cast<S>());
  };
  EXPECT_LE((autoDiffJacobian(self, V3::Zero()) - Eigen::Matrix3d::Identity()).norm(), 1e-15);
}

TEST(So3, AutoDiffOfExpAndLogAtTheIdentity) {
  // d exp / d phi at 0 = (0; I / 2), d log / d v at the identity = 2 I: finite, not NaN.
  AdV3 phi;
  for (int i = 0; i < 3; ++i) phi(i) = Ad3(0.0, 3, i);
  const Eigen::Quaternion<Ad3> q = mf::so3Exp<Ad3>(phi);
  EXPECT_EQ(q.w().derivatives(), V3::Zero());
  EXPECT_EQ(q.x().derivatives(), V3(0.5, 0.0, 0.0));
  EXPECT_EQ(q.z().derivatives(), V3(0.0, 0.0, 0.5));
  const Eigen::Quaternion<Ad3> identity(Ad3(1.0), phi(0), phi(1), phi(2));
  const AdV3 v = mf::so3Log<Ad3>(identity);
  EXPECT_EQ(v(1).derivatives(), V3(0.0, 2.0, 0.0));
}

}  // namespace
