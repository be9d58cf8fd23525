// The thesis's moving-train example (section 2.2.1): state (v, a), v' = v + a T, a' = a, and
// two sensors measuring v and a directly. Linear, so every method can run it.
#pragma once

#include "sf_estimation/types.hpp"

namespace estimation {
namespace models {

struct MovingTrain {
  static constexpr int StateSize = 2;
  static constexpr int MeasurementSize = 2;
  static constexpr int ControlSize = 0;

  double T = 0.1;

  Index stateSize() const { return StateSize; }
  Index measurementSize() const { return MeasurementSize; }
  Index controlSize() const { return ControlSize; }

  template <class S>
  void transition(const Eigen::Matrix<S, 2, 1>& x, const Vector<0>&,
                  Eigen::Matrix<S, 2, 1>& next) const {
    next(0) = x(0) + x(1) * T;
    next(1) = x(1);
  }

  template <class S>
  void observation(const Eigen::Matrix<S, 2, 1>& x, Eigen::Matrix<S, 2, 1>& z) const {
    z = x;
  }

  Matrix<2, 2> transitionMatrix() const { return (Matrix<2, 2>() << 1, T, 0, 1).finished(); }
  Matrix<2, 0> controlMatrix() const { return Matrix<2, 0>(); }
  Matrix<2, 2> observationMatrix() const { return Matrix<2, 2>::Identity(); }
};

}  // namespace models
}  // namespace estimation
