// IMU attitude filter: a multiplicative (error-state) EKF on SO(3) with a gyro bias, built on
// ManifoldExtendedKalmanFilter (doc/broad.md).
//
// State: q, the rotation from the sensor frame to an east-north-up earth frame (v_earth =
// q v_sensor q^-1), perturbed in the body frame (q exp(e)), and the gyro bias b [rad/s].
// Process: q' = q exp((omega - b + w_g) dt), b' = b + w_b dt, with white gyro noise of
// density gyroNoise [rad/s/sqrt(Hz)] and a bias random walk of biasWalk [rad/s/sqrt(s)].
// Measurements, both as unit directions in the sensor frame, z = q^-1 d q + v:
//  - the accelerometer as the direction of gravity (d = up): it measures the specific force,
//    which is up and of size g only while the sensor does not accelerate. Optionally the
//    force is first low-passed in the earth frame (a moving sensor's linear acceleration
//    averages out over seconds, gravity does not: the idea of Laidig and Seel's VQF); its
//    noise is inflated by how far |a| departs from g and the sample is skipped past a gate;
//  - optionally the magnetometer's horizontal direction as north (d = north): heading only,
//    skipped when the field's size or dip departs from the first sample's (a nearby magnet
//    or iron changes both).
#pragma once

#include <algorithm>
#include <cmath>

#include <Eigen/Geometry>

#include "sf_estimation/manifold/so3.hpp"
#include "sf_estimation/manifold/state_layout.hpp"
#include "sf_estimation/manifold_extended_kalman_filter.hpp"

namespace estimation {

struct AttitudeParameters {
  double gyroNoise = 0.005;             ///< gyro white noise density [rad/s/sqrt(Hz)]
  double biasWalk = 1e-4;               ///< gyro bias random walk [rad/s/sqrt(s)]
  double gravity = 9.81;                ///< [m/s^2]
  double accelerometerNoise = 0.05;     ///< std of the measured gravity direction [rad]
  double accelerationInflation = 0.02;  ///< |a|/g - 1 at which R has doubled (quadratic growth)
  double accelerationGate = 0.25;       ///< | |a|/g - 1 | above which the sample is skipped
  /// Time constant [s] of a low-pass of the specific force in the earth frame, whose direction
  /// is then measured instead of the raw sample's (0: the raw sample). A hand-held or vehicle
  /// sensor's linear acceleration averages out over a few seconds, gravity does not.
  double accelerationTimeConstant = 0.0;
  bool useMagnetometer = true;
  double magnetometerNoise = 0.2;  ///< std of the measured horizontal field direction [rad]
  double fieldNormGate = 0.1;      ///< relative change of |m| above which m is skipped
  double fieldDipGate = 0.0873;    ///< change of the dip angle [rad] above which m is skipped
};

/// The transition and the direction measurement of the attitude filter (see the top).
struct AttitudeModel {
  using StateSpace = manifold::StateLayout<manifold::So3Block, manifold::VectorBlock<3>>;
  using MeasurementSpace = manifold::FlatLayout<3>;
  static constexpr int NoiseSize = 6, ControlSize = 4;  // u = (omega, dt)

  Eigen::Vector3d reference = Eigen::Vector3d::UnitZ();  ///< earth direction measured next

  template <class S>
  void transition(const Eigen::Matrix<S, 7, 1>& x, const Vector<4>& u,
                  const Eigen::Matrix<S, 6, 1>& w, Eigen::Matrix<S, 7, 1>& next) const {
    const double dt = u(3);
    const manifold::Vector3<S> rate =
        u.head<3>().cast<S>() - x.template tail<3>() + w.template head<3>();
    const manifold::Quaternion<S> q = manifold::storedQuaternion(x.template head<4>());
    auto head = next.template head<4>();
    manifold::storeQuaternion<S>(manifold::so3Plus<S>(q, manifold::Vector3<S>(rate * dt)), head);
    next.template tail<3>() = x.template tail<3>() + w.template tail<3>() * dt;
  }

  template <class S>
  void observation(const Eigen::Matrix<S, 7, 1>& x, Eigen::Matrix<S, 3, 1>& z) const {
    const manifold::Quaternion<S> q = manifold::storedQuaternion(x.template head<4>());
    z = manifold::so3RotateInverse<S>(q, reference.cast<S>());
  }
};

class AttitudeFilter {
 public:
  using Ekf = ManifoldExtendedKalmanFilter<AttitudeModel>;
  /// Variance [rad^2] of a direction component that a measurement does not inform.
  static constexpr double kDiscardedVariance = 1e6;

  /// Starts at q0 (sensor to ENU) with zero bias; P0 over (rotation vector, bias).
  AttitudeFilter(const AttitudeParameters& parameters, const Eigen::Quaterniond& q0,
                 const Matrix<6, 6>& P0)
      : parameters_(parameters),
        ekf_(AttitudeModel(), processNoise(1.0), directionNoise(1.0), initial(q0), P0) {}

  /// The orientation of one accelerometer and one magnetometer sample (up along a, the
  /// horizontal field north); east along m x a.
  static Eigen::Quaterniond fromAccelerometerAndField(const Eigen::Vector3d& a,
                                                      const Eigen::Vector3d& m) {
    const Eigen::Vector3d up = a.normalized();
    const Eigen::Vector3d east = m.cross(up).normalized();
    Eigen::Matrix3d toEarth;
    toEarth.row(0) = east.transpose();
    toEarth.row(1) = up.cross(east).transpose();
    toEarth.row(2) = up.transpose();
    return Eigen::Quaterniond(toEarth).normalized();
  }

  /// Integrates the gyro over dt [s].
  void predict(const Eigen::Vector3d& gyro, double dt) {
    if (dt != dt_) {
      ekf_.setProcessNoise(processNoise(dt));
      dt_ = dt;
    }
    Vector<4> u;
    u << gyro, dt;
    ekf_.predict(u);
  }

  /// Corrects the tilt with one accelerometer sample [m/s^2]; false when it was skipped. With
  /// accelerationTimeConstant, the sample first enters the earth-frame low-pass; dt is the
  /// time since the previous sample.
  bool correctGravity(const Eigen::Vector3d& a, double dt = 0.0) {
    const double departure = std::abs(a.norm() / parameters_.gravity - 1.0);
    Eigen::Vector3d measured = a;
    if (parameters_.accelerationTimeConstant > 0.0) {
      const Eigen::Vector3d earth = manifold::so3Rotate<double>(orientation(), a);
      const bool first = smoothedForce_.isZero();
      smoothedForce_ += first ? earth
                              : (earth - smoothedForce_) *
                                    std::min(1.0, dt / parameters_.accelerationTimeConstant);
      measured = manifold::so3RotateInverse<double>(orientation(), smoothedForce_);
    }
    if (!(departure <= parameters_.accelerationGate) || !(measured.norm() > 0.0)) return false;
    const double r = departure / parameters_.accelerationInflation;
    return correct(Eigen::Vector3d::UnitZ(), measured.normalized(),
                   directionNoise(parameters_.accelerometerNoise * std::sqrt(1.0 + r * r)));
  }

  /// Corrects the heading with one magnetometer sample (any unit): the field's part
  /// perpendicular to the estimated up is compared with north, so that the field (whose
  /// vertical part a disturbance often changes most) leaves the tilt to the accelerometer.
  /// The first sample defines the undisturbed field (size and dip); false when skipped.
  bool correctField(const Eigen::Vector3d& m) {
    if (!parameters_.useMagnetometer || !(m.norm() > 0.0)) return false;
    const Eigen::Vector3d up = gravityDirection();
    const double dip = std::asin(std::clamp(m.normalized().dot(up), -1.0, 1.0));
    if (fieldNorm_ == 0.0) {
      fieldNorm_ = m.norm();
      fieldDip_ = dip;
      return false;
    }
    const Eigen::Vector3d horizontal = m - m.dot(up) * up;
    if (std::abs(m.norm() / fieldNorm_ - 1.0) > parameters_.fieldNormGate ||
        std::abs(dip - fieldDip_) > parameters_.fieldDipGate || !(horizontal.norm() > 0.0)) {
      return false;
    }
    // The measured direction is horizontal by construction: its vertical component carries no
    // information, and is given a variance that discards it (otherwise the filter would read
    // the tilt about east as measured, at its own current value).
    const double s2 = parameters_.magnetometerNoise * parameters_.magnetometerNoise;
    const Matrix<3, 3> R =
        s2 * Matrix<3, 3>::Identity() + (kDiscardedVariance - s2) * up * up.transpose();
    return correct(Eigen::Vector3d::UnitY(), horizontal.normalized(), R);
  }

  Eigen::Quaterniond orientation() const {
    return manifold::storedQuaternion(ekf_.state().head<4>());
  }
  Eigen::Vector3d bias() const { return ekf_.state().tail<3>(); }
  const Ekf& ekf() const { return ekf_; }

 private:
  static Vector<7> initial(const Eigen::Quaterniond& q0) {
    Vector<7> x;
    x << q0.w(), q0.x(), q0.y(), q0.z(), 0.0, 0.0, 0.0;
    return x;
  }

  Matrix<6, 6> processNoise(double dt) const {
    Matrix<6, 6> Q = Matrix<6, 6>::Zero();
    // Densities to the variances of one step's w: the angle error of a step is w_g dt.
    Q.topLeftCorner<3, 3>().diagonal().setConstant(parameters_.gyroNoise * parameters_.gyroNoise /
                                                   dt);
    Q.bottomRightCorner<3, 3>().diagonal().setConstant(parameters_.biasWalk * parameters_.biasWalk /
                                                       dt);
    return Q;
  }

  static Matrix<3, 3> directionNoise(double sigma) {
    return Matrix<3, 3>::Identity() * (sigma * sigma);
  }

  /// The estimated up direction in the sensor frame.
  Eigen::Vector3d gravityDirection() const {
    return manifold::so3RotateInverse<double>(orientation(), Eigen::Vector3d::UnitZ());
  }

  bool correct(const Eigen::Vector3d& reference, const Eigen::Vector3d& measured,
               const Matrix<3, 3>& R) {
    ekf_.model().reference = reference;
    ekf_.setMeasurementNoise(R);
    ekf_.update(measured);
    return true;
  }

  AttitudeParameters parameters_;
  Ekf ekf_;
  double dt_ = 1.0;
  double fieldNorm_ = 0.0, fieldDip_ = 0.0;
  Eigen::Vector3d smoothedForce_ = Eigen::Vector3d::Zero();  ///< earth frame [m/s^2]
};

}  // namespace estimation
