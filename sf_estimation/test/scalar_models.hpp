// Scalar models shared by the angle and numerical-repair tests (library and fusion core).
#pragma once

#include "sf_estimation/types.hpp"

namespace sftest {

/// x' = x, z = x: a constant measured directly (a compass on a robot that does not turn).
struct IdentityModel {
  static constexpr int StateSize = 1, MeasurementSize = 1, ControlSize = 0;
  estimation::Index stateSize() const { return 1; }
  estimation::Index measurementSize() const { return 1; }
  estimation::Index controlSize() const { return 0; }
  template <class S>
  void transition(const Eigen::Matrix<S, 1, 1>& x, const estimation::Vector<0>&,
                  Eigen::Matrix<S, 1, 1>& next) const {
    next = x;
  }
  template <class S>
  void observation(const Eigen::Matrix<S, 1, 1>& x, Eigen::Matrix<S, 1, 1>& z) const {
    z = x;
  }
};

/// x' = x^2, z = x. With alpha = 1, kappa = 0 and a negative beta the unscented predicted
/// covariance of x ~ N(0, 1) is negative in closed form: a UKF that must repair it.
struct SquareTransition {
  static constexpr int StateSize = 1, MeasurementSize = 1, ControlSize = 0;
  estimation::Index stateSize() const { return 1; }
  estimation::Index measurementSize() const { return 1; }
  estimation::Index controlSize() const { return 0; }
  template <class S>
  void transition(const Eigen::Matrix<S, 1, 1>& x, const estimation::Vector<0>&,
                  Eigen::Matrix<S, 1, 1>& next) const {
    next(0) = x(0) * x(0);
  }
  template <class S>
  void observation(const Eigen::Matrix<S, 1, 1>& x, Eigen::Matrix<S, 1, 1>& z) const {
    z = x;
  }
};

}  // namespace sftest
