// The 19-state inertial+vision ego-motion model of Armesto, Tornero and Vincze, "Fast
// ego-motion estimation with multi-rate fusion of inertial and vision" (doc/armesto.md), as a
// model of the manifold filters (manifold_extended_kalman_filter.hpp,
// manifold_unscented_kalman_filter.hpp): the quaternion is an So3Block, so that both filters
// keep it unit and compare it on SO(3).
//
// State x = (p, v, a, b, q, omega): position, velocity and acceleration in the earth frame
// (east-north-up) [m, m/s, m/s^2], the accelerometer bias [m/s^2] in the sensor frame, the
// rotation q from the sensor to the earth frame (w, x, y, z) and the body angular velocity
// omega [rad/s]. Tangent: 18 (q perturbed in the body frame).
// Process over T (the control, u = T [s]), driven by w = (jerk j, angular acceleration alpha,
// bias rate b'), the paper's eqs. 11-21 with a constant acceleration and angular velocity:
//   p' = p + T v + T^2/2 a + T^3/6 j,  v' = v + T a + T^2/2 j,  a' = a + T j,  b' = b + T b',
//   q' = q exp((omega + T/2 alpha) T),  omega' = omega + T alpha.
// The paper's eq. 13 adds alpha x v + omega x a to the acceleration's derivative; here p, v, a
// are earth-frame vectors of one point, whose constant-acceleration motion has no such term
// (doc/armesto.md, "The model").
// Measurements: the accelerometer, the specific force in the sensor frame plus its bias,
// q^-1 (a + g e_up) q + b; the gyro, omega; and with vision, the position p and the rotation q
// (compared on SO(3), its noise a body-frame rotation vector). The paper rotates the IMU
// samples into the earth frame to make its measurement equation linear; here the filters
// differentiate the rotation instead.
#pragma once

#include <Eigen/Core>

#include "sf_estimation/manifold/so3.hpp"
#include "sf_estimation/manifold/state_layout.hpp"
#include "sf_estimation/types.hpp"

namespace estimation {
namespace armesto {

/// Offsets of the stored state.
enum : int { kP = 0, kV = 3, kA = 6, kB = 9, kQ = 12, kOmega = 16 };
/// Offsets of the tangent state (the quaternion's 3 rotation-vector rows at kQ).
enum : int { kTangentOmega = 15 };

using State =
    manifold::StateLayout<manifold::VectorBlock<12>, manifold::So3Block, manifold::VectorBlock<3>>;

/// The measurement the model predicts: the IMU alone (every step) or IMU and vision.
struct Inertial {
  using Space = manifold::FlatLayout<6>;  // accelerometer, gyro
  static constexpr bool HasVision = false;
};
struct InertialVision {
  using Space = manifold::StateLayout<manifold::VectorBlock<9>, manifold::So3Block>;
  static constexpr bool HasVision = true;  // then position and the quaternion w, x, y, z
};

template <class Measurement>
struct Model {
  using StateSpace = State;
  using MeasurementSpace = typename Measurement::Space;
  static constexpr int NoiseSize = 9, ControlSize = 1;  // w = (j, alpha, b'), u = T

  double gravity = 9.81;  ///< [m/s^2], along the earth frame's up

  template <class S>
  void transition(const Eigen::Matrix<S, 19, 1>& x, const Vector<1>& u,
                  const Eigen::Matrix<S, 9, 1>& w, Eigen::Matrix<S, 19, 1>& next) const {
    const double T = u(0);
    const manifold::Vector3<S> jerk = w.template head<3>();
    const auto p = x.template segment<3>(kP), v = x.template segment<3>(kV);
    const auto a = x.template segment<3>(kA);
    next.template segment<3>(kP) = p + T * v + (T * T / 2.0) * a + (T * T * T / 6.0) * jerk;
    next.template segment<3>(kV) = v + T * a + (T * T / 2.0) * jerk;
    next.template segment<3>(kA) = a + T * jerk;
    next.template segment<3>(kB) = x.template segment<3>(kB) + T * w.template tail<3>();
    const manifold::Vector3<S> omega = x.template segment<3>(kOmega);
    const manifold::Vector3<S> alpha = w.template segment<3>(3);
    const manifold::Vector3<S> turn = (omega + (T / 2.0) * alpha) * T;
    auto q = next.template segment<4>(kQ);
    manifold::storeQuaternion<S>(
        manifold::so3Plus<S>(manifold::storedQuaternion(x.template segment<4>(kQ)), turn), q);
    next.template segment<3>(kOmega) = omega + T * alpha;
  }

  template <class S>
  void observation(const Eigen::Matrix<S, 19, 1>& x,
                   Eigen::Matrix<S, MeasurementSpace::StoredSize, 1>& z) const {
    const manifold::Quaternion<S> q = manifold::storedQuaternion(x.template segment<4>(kQ));
    manifold::Vector3<S> force = x.template segment<3>(kA);
    force(2) += gravity;
    z.template head<3>() = manifold::so3RotateInverse<S>(q, force) + x.template segment<3>(kB);
    z.template segment<3>(3) = x.template segment<3>(kOmega);
    if constexpr (Measurement::HasVision) {
      z.template segment<3>(6) = x.template segment<3>(kP);
      z.template segment<4>(9) = x.template segment<4>(kQ);
    }
  }
};

}  // namespace armesto
}  // namespace estimation
