// The nonlinear state-space model used by EKF, UKF and the particle filter:
//
//   struct MyModel {
//     static constexpr int StateSize = 7, MeasurementSize = 4, ControlSize = 2;  // or Dynamic
//     Index stateSize() const;  Index measurementSize() const;  Index controlSize() const;
//     template <class S>   // S = double, or an AutoDiffScalar for automatic Jacobians
//     void transition(const Eigen::Matrix<S, 7, 1>& x, const Vector<2>& u,
//                     Eigen::Matrix<S, 7, 1>& next) const;              // next = f(x, u)
//     template <class S>
//     void observation(const Eigen::Matrix<S, 7, 1>& x, Eigen::Matrix<S, 4, 1>& z) const;
//     // Optional; used instead of automatic differentiation when present:
//     void transitionJacobian(const Vector<7>& x, const Vector<2>& u, Matrix<7, 7>& A) const;
//     void observationJacobian(const Vector<7>& x, Matrix<4, 7>& H) const;
//   };
//
// Noise is additive (x' = f(x, u) + w, z = h(x) + v), as in the thesis. FunctionModel
// (function_model.hpp) is the run-time-sized variant used by the factory.
#pragma once

#include <string>

#include "sf_estimation/errors.hpp"
#include "sf_estimation/types.hpp"

namespace estimation {

/// Throws ParameterError naming `method` unless the model's sizes are those of Q and R
/// (compiled once in the library, src/parameter_checks.cpp).
void checkModelSizes(const std::string& method, Index modelStateSize, Index modelMeasurementSize,
                     Index stateSize, Index measurementSize);

template <class Model>
void checkModelSizes(const std::string& method, const Model& model, Index stateSize,
                     Index measurementSize) {
  checkModelSizes(method, model.stateSize(), model.measurementSize(), stateSize, measurementSize);
}

}  // namespace estimation
