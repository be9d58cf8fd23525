// The multi-rate filter of Armesto, Tornero and Vincze's inertial+vision model
// (armesto_inertial_vision.hpp, doc/armesto.md): it predicts and corrects with the IMU every
// period T and adds the vision measurement to the correction when a frame arrives (the
// paper's MR-EKF and MR-UKF, Algorithms 2 and 3: the sampler stacks the sensors sampled at
// this step). The manifold filters have one measurement type each, so the filter is a pair
// over one belief: the IMU-only filter steps, and the belief passes to the IMU+vision filter
// for a step with a frame and back.
#pragma once

#include "sf_estimation/models/armesto_inertial_vision.hpp"

namespace estimation {
namespace armesto {

/// The noise of the model: the paper's eqs. 25-26 by default. R: variances of the
/// accelerometer [(m/s^2)^2], gyro [(rad/s)^2], position [m^2] and of each quaternion component
/// (the rotation vector's variance is 4 times that: q = (1, phi / 2) for a small rotation).
/// Q: variances of one step's jerk [(m/s^3)^2], angular acceleration [(rad/s^2)^2] and bias
/// rate [(m/s^3)^2].
struct Noise {
  double accelerometer = 1e-3, gyro = 1e-4, position = 1e-7, quaternion = 1e-6;
  double jerk = 0.7447, angularAcceleration = 0.38, biasRate = 0.19e-6;
};

template <template <class> class Filter>
class MultiRateFilter {
 public:
  using InertialFilter = Filter<Model<Inertial>>;
  using VisionFilter = Filter<Model<InertialVision>>;
  using StateVector = Vector<State::StoredSize>;
  using Covariance = Matrix<State::TangentSize, State::TangentSize>;

  /// Starts at (x0, P0); T is the period [s] of the IMU and of the filter's steps; `options`
  /// go to both filters' constructors (e.g. the UKF's ManifoldUnscentedParameters).
  template <class... FilterOptions>
  MultiRateFilter(const Noise& noise, const StateVector& x0, const Covariance& P0, double T,
                  double gravity = 9.81, const FilterOptions&... options)
      : inertial_(makeModel<Inertial>(gravity), processNoise(noise), inertialNoise(noise), x0, P0,
                  options...),
        vision_(makeModel<InertialVision>(gravity), processNoise(noise), visionNoise(noise), x0, P0,
                options...),
        period_(Vector<1>::Constant(T)) {}

  /// One period with an IMU sample (accelerometer [m/s^2], gyro [rad/s]).
  void step(const Vector<6>& imu) {
    inertial_.predict(period_);
    inertial_.update(imu);
  }

  /// One period with an IMU sample and a vision frame (position [m], quaternion w, x, y, z
  /// from the sensor to the earth frame).
  void step(const Vector<6>& imu, const Vector<7>& vision) {
    inertial_.predict(period_);
    vision_.setBelief(inertial_.state(), inertial_.covariance());
    Vector<13> z;
    z << imu, vision;
    vision_.update(z);
    inertial_.setBelief(vision_.state(), vision_.covariance());
  }

  const StateVector& state() const { return inertial_.state(); }
  const Covariance& covariance() const { return inertial_.covariance(); }

 private:
  template <class Measurement>
  static Model<Measurement> makeModel(double gravity) {
    Model<Measurement> model;
    model.gravity = gravity;
    return model;
  }

  static Matrix<9, 9> processNoise(const Noise& n) {
    Vector<9> q;
    q << Vector<3>::Constant(n.jerk), Vector<3>::Constant(n.angularAcceleration),
        Vector<3>::Constant(n.biasRate);
    return q.asDiagonal();
  }
  static Matrix<6, 6> inertialNoise(const Noise& n) {
    Vector<6> r;
    r << Vector<3>::Constant(n.accelerometer), Vector<3>::Constant(n.gyro);
    return r.asDiagonal();
  }
  static Matrix<12, 12> visionNoise(const Noise& n) {
    Vector<12> r;
    r << Vector<3>::Constant(n.accelerometer), Vector<3>::Constant(n.gyro),
        Vector<3>::Constant(n.position), Vector<3>::Constant(4.0 * n.quaternion);
    return r.asDiagonal();
  }

  InertialFilter inertial_;
  VisionFilter vision_;
  Vector<1> period_;
};

}  // namespace armesto
}  // namespace estimation
