// The thesis's dead-reckoning models of the Pioneer 3-AT (section 5.1.2), used by the tests,
// the benchmark and as worked examples of the model concept (see ../model.hpp).
//   state   x = (x, y, theta, omega, delta_s, v, a)          [m, m, rad, rad/s, m, m/s, m/s^2]
//   control u = (cmd_vel.linear.x, cmd_vel.angular.z)        [m/s, rad/s]
//   measurement z = (gyro omega, accel a, wheel left, wheel right)   [rad/s, m/s^2, mm/s, mm/s]
#pragma once

#include <cmath>

#include "sf_estimation/types.hpp"

namespace estimation {
namespace models {

/// Observation model of nav3 and nav3ctrl (eqs. 5.15-5.18) for a state holding omega, v and
/// a at the given indices; R is the effective skid-steer radius.
template <class S, class X>
void observeGyroAccelWheels(const X& x, int omega, int v, int a, double radius,
                            Eigen::Matrix<S, 4, 1>& z) {
  z(0) = x(omega);
  z(1) = x(a);
  z(2) = (x(v) - x(omega) * radius) * 1000.0;
  z(3) = (x(v) + x(omega) * radius) * 1000.0;
}

/// nav3ctrl: eqs. 5.8-5.14 (transition with cmd_vel) and 5.15-5.18 (observation).
struct Nav3Ctrl {
  static constexpr int StateSize = 7;
  static constexpr int MeasurementSize = 4;
  static constexpr int ControlSize = 2;

  double T = 0.1;       ///< estimation period [s]
  double radius = 0.3;  ///< effective skid-steer radius R [m]

  Index stateSize() const { return StateSize; }
  Index measurementSize() const { return MeasurementSize; }
  Index controlSize() const { return ControlSize; }

  template <class S>
  void transition(const Eigen::Matrix<S, 7, 1>& x, const Vector<2>& u,
                  Eigen::Matrix<S, 7, 1>& next) const {
    using std::cos;
    using std::sin;
    next(0) = x(0) + x(4) * cos(x(2));
    next(1) = x(1) + x(4) * sin(x(2));
    next(2) = x(2) + x(3) * T;
    next(3) = S(u(1));
    next(4) = x(5) * T;
    next(5) = x(5) + x(6) * T;
    next(6) = (u(0) - x(5)) / T;
  }

  template <class S>
  void observation(const Eigen::Matrix<S, 7, 1>& x, Eigen::Matrix<S, 4, 1>& z) const {
    observeGyroAccelWheels<S>(x, 3, 5, 6, radius, z);
  }
};

/// nav3red: nav3ctrl reduced to (omega, v, a), eqs. 5.11-5.14 and 5.15-5.18. Linear.
struct Nav3Reduced {
  static constexpr int StateSize = 3;
  static constexpr int MeasurementSize = 4;
  static constexpr int ControlSize = 2;

  double T = 0.1;
  double radius = 0.3;

  Index stateSize() const { return StateSize; }
  Index measurementSize() const { return MeasurementSize; }
  Index controlSize() const { return ControlSize; }

  template <class S>
  void transition(const Eigen::Matrix<S, 3, 1>& x, const Vector<2>& u,
                  Eigen::Matrix<S, 3, 1>& next) const {
    next(0) = S(u(1));
    next(1) = x(1) + x(2) * T;
    next(2) = (u(0) - x(1)) / T;
  }

  template <class S>
  void observation(const Eigen::Matrix<S, 3, 1>& x, Eigen::Matrix<S, 4, 1>& z) const {
    observeGyroAccelWheels<S>(x, 0, 1, 2, radius, z);
  }

  Matrix<3, 3> transitionMatrix() const {
    return (Matrix<3, 3>() << 0, 0, 0, 0, 1, T, 0, -1.0 / T, 0).finished();
  }
  Matrix<3, 2> controlMatrix() const {
    return (Matrix<3, 2>() << 0, 1, 0, 0, 1.0 / T, 0).finished();
  }
  Matrix<4, 3> observationMatrix() const {
    return (Matrix<4, 3>() << 1, 0, 0, 0, 0, 1, -1000.0 * radius, 1000, 0, 1000.0 * radius,
            1000, 0)
        .finished();
  }
};

/// Noise of section 5.1.2: Q of eq. 5.20 (the Kalman filters), the particle filter's own Q,
/// and R (variances of gyro, accelerometer, left and right wheel).
inline Matrix<7, 7> nav3ProcessNoise() {
  Vector<7> d;
  d << 0, 0, 0, 0.5, 0, 0, 0.3;
  return d.asDiagonal();
}
inline Matrix<7, 7> nav3ParticleProcessNoise() {
  Vector<7> d;
  d << 0.1, 0.1, 0.1, 0.5, 0.1, 0.1, 0.3;
  return d.asDiagonal();
}
inline Matrix<3, 3> nav3ReducedProcessNoise() {
  Vector<3> d;
  d << 0.5, 0, 0.3;
  return d.asDiagonal();
}
inline Matrix<4, 4> nav3MeasurementNoise() {
  Vector<4> d;
  d << 0.00017, 0.25, 2, 2;
  return d.asDiagonal();
}

}  // namespace models
}  // namespace estimation
