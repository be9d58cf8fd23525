// A nonlinear model whose sizes are known only at run time (used by the factory). It stores
// type-erased functions; build it from generic lambdas with makeFunctionModel() to get exact
// automatic Jacobians, or give the Jacobians yourself.
#pragma once

#include <functional>
#include <string>
#include <utility>

#include <unsupported/Eigen/AutoDiff>

#include "sf_estimation/errors.hpp"
#include "sf_estimation/jacobian.hpp"
#include "sf_estimation/types.hpp"

namespace estimation {

class FunctionModel {
 public:
  static constexpr int StateSize = Dynamic;
  static constexpr int MeasurementSize = Dynamic;
  static constexpr int ControlSize = Dynamic;

  using TransitionFunction =
      std::function<void(const Eigen::VectorXd& x, const Eigen::VectorXd& u, Eigen::VectorXd& next)>;
  using ObservationFunction = std::function<void(const Eigen::VectorXd& x, Eigen::VectorXd& z)>;
  using TransitionJacobianFunction =
      std::function<void(const Eigen::VectorXd& x, const Eigen::VectorXd& u, Eigen::MatrixXd& A)>;
  using ObservationJacobianFunction =
      std::function<void(const Eigen::VectorXd& x, Eigen::MatrixXd& H)>;

  FunctionModel() = default;
  FunctionModel(Index stateSize, Index measurementSize, Index controlSize,
                TransitionFunction transition, ObservationFunction observation,
                TransitionJacobianFunction transitionJacobian = {},
                ObservationJacobianFunction observationJacobian = {})
      : n_(stateSize),
        m_(measurementSize),
        l_(controlSize),
        f_(std::move(transition)),
        h_(std::move(observation)),
        df_(std::move(transitionJacobian)),
        dh_(std::move(observationJacobian)) {}

  Index stateSize() const { return n_; }
  Index measurementSize() const { return m_; }
  Index controlSize() const { return l_; }
  bool hasTransition() const { return static_cast<bool>(f_); }
  bool hasObservation() const { return static_cast<bool>(h_); }
  bool hasJacobians() const { return df_ && dh_; }

  void setJacobians(TransitionJacobianFunction df, ObservationJacobianFunction dh) {
    df_ = std::move(df);
    dh_ = std::move(dh);
  }

  void transition(const Eigen::VectorXd& x, const Eigen::VectorXd& u, Eigen::VectorXd& next) const {
    next.resize(n_);
    f_(x, u, next);
  }
  void observation(const Eigen::VectorXd& x, Eigen::VectorXd& z) const {
    z.resize(m_);
    h_(x, z);
  }
  void transitionJacobian(const Eigen::VectorXd& x, const Eigen::VectorXd& u,
                          Eigen::MatrixXd& A) const {
    if (!df_) throw ParameterError("model has no Jacobian of the state transition function");
    A.resize(n_, n_);
    df_(x, u, A);
  }
  void observationJacobian(const Eigen::VectorXd& x, Eigen::MatrixXd& H) const {
    if (!dh_) throw ParameterError("model has no Jacobian of the observation function");
    H.resize(m_, n_);
    dh_(x, H);
  }

 private:
  Index n_ = 0, m_ = 0, l_ = 0;
  TransitionFunction f_;
  ObservationFunction h_;
  TransitionJacobianFunction df_;
  ObservationJacobianFunction dh_;
};

/// Builds a FunctionModel from generic lambdas
///   transition(const auto& x, const auto& u, auto& next)   and
///   observation(const auto& x, auto& z),
/// instantiated once for double and once for AutoDiffScalar, which gives exact Jacobians.
template <class Transition, class Observation>
FunctionModel makeFunctionModel(Index stateSize, Index measurementSize, Index controlSize,
                                Transition transition, Observation observation) {
  using ADScalar = Eigen::AutoDiffScalar<Eigen::VectorXd>;
  using ADVector = Eigen::Matrix<ADScalar, Eigen::Dynamic, 1>;
  auto df = [transition](const Eigen::VectorXd& x, const Eigen::VectorXd& u, Eigen::MatrixXd& A) {
    ADVector xa, next(x.size());
    detail::seedDerivatives(x, xa);
    transition(xa, u, next);
    detail::extractJacobian(next, x.size(), A);
  };
  auto dh = [observation, measurementSize](const Eigen::VectorXd& x, Eigen::MatrixXd& H) {
    ADVector xa, z(measurementSize);
    detail::seedDerivatives(x, xa);
    observation(xa, z);
    detail::extractJacobian(z, x.size(), H);
  };
  return FunctionModel(stateSize, measurementSize, controlSize, transition, observation, df, dh);
}

}  // namespace estimation
